/**
 * Free module positions along a rail (docs/model.md, "Free positions"). A module's `offset` is
 * the distance from the rail start to the module's START, metres. A rail is free when its
 * modules carry offsets (all of them: a rail is never half free) and distributed otherwise.
 *
 * Rules (validate() checks them on the state; moveModule snaps before they are checked):
 *  - every offset is finite, 0 ≤ oᵢ and oᵢ + lᵢ ≤ L: a module never passes the rail's ends, so
 *    never a connector (joints sit between rails) and never a feed (the catalog's feed rule puts
 *    feeds only at the chain ends and at connectors, both outside every rail's module span);
 *  - modules are listed in rail order and never overlap: oᵢ₊₁ ≥ oᵢ + lᵢ (touching is allowed).
 * Snapping: the requested offset goes to the nearest of the grid (multiples of the catalog's
 * `rail.placementStep`, default `rail.step`, from the rail start), the rail's two ends and the
 * other modules' ends (touching a neighbour on either side). The grid point is always within half
 * a step, so a neighbour or an end wins only when it is nearer than the grid.
 */
import { keyed } from '../configuration/coding';
import type { Catalog } from '../catalogSchema/catalogSchema';
import type { ModuleInstance, Rail } from '../configuration/configuration';

/** Float noise allowed at the ends and between neighbours (a nanometre), as the distributions' LAYOUT_EPS. */
export const FREE_EPS = 1e-9;

/** The grid a free module's start snaps to, metres. */
export function placementStep(catalog: Catalog): number {
  return catalog.rail.placementStep ?? catalog.rail.step;
}

/** Offsets are stored rounded to a micrometre, so 3 × 0.05 stays 0.15 (and −0 reads 0). */
export function roundOffset(x: number): number {
  return Math.round(x * 1e6) / 1e6 + 0;
}

/** True when the rail's modules are placed freely (any carries an offset). */
export function isFreeRail(rail: Pick<Rail, 'modules'>): boolean {
  return rail.modules.some((m) => m.offset !== undefined);
}

/** The modules without their free positions (what setDistribution hands back to a distribution). */
export function withoutOffsets(modules: readonly ModuleInstance[]): ModuleInstance[] {
  return modules.map((m) => {
    if (m.offset === undefined) return m;
    const { offset: _dropped, ...rest } = m;
    return rest;
  });
}

export interface FreeRailProblem {
  readonly code: 'module-position' | 'module-past-end' | 'module-overlap';
  /** The module (index into the rail's list) the problem is about. */
  readonly index: number;
  readonly message: string;
}

const fmt = (x: number): string => String(Math.round(x * 1000) / 1000);

/** The first broken rule of a free rail (lengths: each module's length, in list order), or null. */
export function freeRailProblem(rail: Pick<Rail, 'id' | 'length' | 'modules'>, lengths: readonly number[]): FreeRailProblem | null {
  const mods = rail.modules;
  for (let i = 0; i < mods.length; i++) {
    const o = mods[i].offset;
    if (o === undefined || !Number.isFinite(o)) {
      return keyed({ code: 'module-position', index: i, message: `module ${mods[i].id} on rail ${rail.id} needs a finite offset (every module of a freely arranged rail has one; got ${String(o)})` }, 'moduleOffsetMissing', {
        id: mods[i].id,
        rail: rail.id,
        value: String(o),
      });
    }
  }
  for (let i = 0; i < mods.length; i++) {
    const o = mods[i].offset!;
    if (o < -FREE_EPS)
      return keyed({ code: 'module-past-end', index: i, message: `module ${mods[i].id} starts ${fmt(-o)} m before the start of rail ${rail.id}` }, 'moduleStartsBefore', { id: mods[i].id, by: Number(fmt(-o)), rail: rail.id });
    if (o + lengths[i] > rail.length + FREE_EPS)
      return keyed({ code: 'module-past-end', index: i, message: `module ${mods[i].id} (${fmt(o)}–${fmt(o + lengths[i])} m) passes the end of the ${fmt(rail.length)} m rail ${rail.id}` }, 'modulePassesEnd', {
        id: mods[i].id,
        from: Number(fmt(o)),
        to: Number(fmt(o + lengths[i])),
        length: Number(fmt(rail.length)),
        rail: rail.id,
      });
  }
  for (let i = 0; i + 1 < mods.length; i++) {
    const end = mods[i].offset! + lengths[i];
    if (mods[i + 1].offset! < end - FREE_EPS)
      return keyed({ code: 'module-overlap', index: i + 1, message: `module ${mods[i + 1].id} at ${fmt(mods[i + 1].offset!)} m overlaps module ${mods[i].id} (${fmt(mods[i].offset!)}–${fmt(end)} m) on rail ${rail.id}` }, 'moduleOverlap', {
        id: mods[i + 1].id,
        at: Number(fmt(mods[i + 1].offset!)),
        other: mods[i].id,
        from: Number(fmt(mods[i].offset!)),
        to: Number(fmt(end)),
        rail: rail.id,
      });
  }
  return null;
}

/** Offsets of a free rail's modules, or null when a rule above is broken. */
export function freeOffsets(rail: Pick<Rail, 'id' | 'length' | 'modules'>, lengths: readonly number[]): number[] | null {
  return freeRailProblem(rail, lengths) === null ? rail.modules.map((m) => m.offset!) : null;
}

/**
 * Where a module of length `length` asked to start at `requested` snaps (see the header): the
 * nearest of the grid point, the rail's ends and the positions touching another module.
 * `others`: the other modules' [start, end) on the rail. Ties go to the grid.
 */
export function snapOffset(requested: number, length: number, railLength: number, others: readonly (readonly [number, number])[], step: number): number {
  let best = roundOffset(Math.round(requested / step) * step);
  const targets = [0, railLength - length, ...others.flatMap(([a, b]) => [b, a - length])];
  for (const t of targets) {
    if (Math.abs(t - requested) < Math.abs(best - requested) - 1e-12) best = roundOffset(t);
  }
  return best;
}

/** The free stretches of a rail between its modules and ends: [start, end] pairs in rail order. */
export function freeGaps(railLength: number, occupied: readonly (readonly [number, number])[]): [number, number][] {
  const sorted = [...occupied].sort((a, b) => a[0] - b[0]);
  const out: [number, number][] = [];
  let from = 0;
  for (const [a, b] of sorted) {
    if (a > from + FREE_EPS) out.push([from, a]);
    from = Math.max(from, b);
  }
  if (railLength > from + FREE_EPS) out.push([from, railLength]);
  return out;
}

/**
 * Where addModule puts a new module on a free rail: centred in the largest gap, its start
 * snapped to the grid when that keeps it inside the gap, else at the gap's start. With no gap
 * long enough it returns the largest gap's start anyway (the result overlaps and validate()
 * refuses it; the refusal names the largest gap). Ties: the gap nearest the rail start.
 */
export function placeInLargestGap(length: number, railLength: number, occupied: readonly (readonly [number, number])[], step: number): { offset: number; gap: number } {
  const gaps = freeGaps(railLength, occupied);
  if (gaps.length === 0) return { offset: 0, gap: 0 };
  const [a, b] = gaps.reduce((best, g) => (g[1] - g[0] > best[1] - best[0] + FREE_EPS ? g : best));
  const gap = roundOffset(b - a);
  const centred = roundOffset(Math.round((a + (b - a - length) / 2) / step) * step);
  const offset = centred >= a - FREE_EPS && centred + length <= b + FREE_EPS ? centred : roundOffset(a);
  return { offset, gap };
}
