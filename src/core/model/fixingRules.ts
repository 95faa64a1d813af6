/**
 * The rules a list of fixing points (suspensions or clips) must keep (docs/model.md, "Moving
 * fixing points"), judged on the list alone: validate() applies them to a system's stored
 * `fixings`; the actions that change a chain use them to decide whether moved points survive
 * the change or fall back to the derived ones. The derived points (suspensionPoints.ts) keep
 * these rules by construction.
 *  - finite and strictly ascending (points keep their order; no two at one spot);
 *  - the free chain ends overhang their outermost point by at most maxOverhang, and no point
 *    lies past a chain end;
 *  - consecutive points are at most `spacing` apart along the chain;
 *  - every connector carries a point at its own coordinate (a joint is always supported);
 *  - any other point lies on a rail, not inside a connector's bridge.
 */
import type { Catalog } from './catalogSchema';
import type { LightSystem } from './configuration';
import { chainCoordinates } from './chainCoordinates';
import { mountingRule } from './suspensionPoints';

/** Float noise allowed when comparing chain coordinates: a micrometre (stored points are rounded to it). */
export const FIXING_EPS = 1e-6;

export interface FixingProblem {
  readonly code: 'fixing-order' | 'fixing-overhang' | 'fixing-spacing' | 'fixing-joint' | 'fixing-off-rail';
  /** Index into the list (the point the problem is about). */
  readonly index: number;
  readonly message: string;
}

const fmt = (x: number) => String(Math.round(x * 1000) / 1000);

/** The first rule a fixing list breaks on this system's chain, or null when it keeps them all. */
export function fixingProblem(system: LightSystem, points: readonly number[], catalog: Catalog): FixingProblem | null {
  const rule = mountingRule(system, catalog);
  const chain = chainCoordinates(system, catalog);
  const what = system.mounting === 'surface' ? 'clip' : 'suspension';
  if (points.length === 0) return { code: 'fixing-overhang', index: 0, message: `system ${system.id} has no ${what} points` };
  for (let i = 0; i < points.length; i++) {
    const s = points[i];
    if (!Number.isFinite(s)) return { code: 'fixing-order', index: i, message: `${what} point ${i + 1} is not a number` };
    if (i > 0 && !(s > points[i - 1] + FIXING_EPS)) return { code: 'fixing-order', index: i, message: `${what} point ${i + 1} must lie past point ${i} along the chain` };
  }
  const first = points[0];
  const last = points[points.length - 1];
  if (first < -FIXING_EPS || first > rule.maxOverhang + FIXING_EPS) return { code: 'fixing-overhang', index: 0, message: `the chain start would overhang its first ${what} by ${fmt(first)} m (at most ${rule.maxOverhang} m)` };
  const tail = chain.length - last;
  if (tail < -FIXING_EPS || tail > rule.maxOverhang + FIXING_EPS) return { code: 'fixing-overhang', index: points.length - 1, message: `the chain end would overhang its last ${what} by ${fmt(tail)} m (at most ${rule.maxOverhang} m)` };
  for (let i = 1; i < points.length; i++) {
    const gap = points[i] - points[i - 1];
    if (gap > rule.spacing + FIXING_EPS) return { code: 'fixing-spacing', index: i, message: `${what} points ${i} and ${i + 1} would be ${fmt(gap)} m apart (at most ${rule.spacing} m)` };
  }
  // Two pointers: both lists ascend.
  let k = 0;
  for (let j = 0; j < chain.jointAt.length; j++) {
    const at = chain.jointAt[j];
    while (k < points.length && points[k] < at - FIXING_EPS) k++;
    if (k >= points.length || Math.abs(points[k] - at) > FIXING_EPS) return { code: 'fixing-joint', index: Math.min(k, points.length - 1), message: `connector ${j + 1} must keep its ${what} (a connector is always a support)` };
  }
  for (let i = 0; i < points.length; i++) {
    const s = points[i];
    if (chain.jointAt.some((at) => Math.abs(s - at) <= FIXING_EPS)) continue;
    const onRail = chain.railStart.some((r0, r) => s >= r0 - FIXING_EPS && s <= r0 + system.rails[r].length + FIXING_EPS);
    if (!onRail) return { code: 'fixing-off-rail', index: i, message: `${what} point ${i + 1} would sit inside a connector, not on a rail` };
  }
  return null;
}

/**
 * The system after a change to its chain or mounting: moved fixing points stay when they still
 * keep every rule on the changed chain, otherwise they go back to the derived ones (in the same
 * action, so one undo restores both).
 */
export function keepFixingsIfValid(system: LightSystem, catalog: Catalog): LightSystem {
  if (system.fixings === undefined) return system;
  let ok: boolean;
  try {
    ok = fixingProblem(system, system.fixings, catalog) === null;
  } catch {
    // An unknown connector on the changed chain: validate() refuses the change; drop the points meanwhile.
    ok = false;
  }
  return ok ? system : withoutFixings(system);
}

/** The system without moved fixing points (removing a rail renumbers the chain's coordinates). */
export function withoutFixings(system: LightSystem): LightSystem {
  if (system.fixings === undefined) return system;
  const { fixings: _dropped, ...rest } = system;
  return rest;
}
