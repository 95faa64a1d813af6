/**
 * The rules a list of fixing points (suspensions or clips) must keep (docs/model.md, "Moving
 * fixing points"), judged on the list alone: validate() applies them to a system's stored
 * `fixings`; the actions that change a chain use them to decide whether moved points survive
 * the change or fall back to the derived ones. The derived points (suspensionPoints.ts) keep
 * these rules by construction.
 *  - finite and strictly ascending (points keep their order; no two at one spot);
 *  - the free chain ends (the start, and every rail end without a connector: on a tree each
 *    branch's) overhang their outermost point by at most maxOverhang, and no point lies past one;
 *  - consecutive points are at most `spacing` apart along each rail, a branch counted from the
 *    node it hangs on (distances along the tree);
 *  - every connector node carries a point at its own coordinate (a joint is always supported);
 *  - any other point lies on a rail, not inside a connector's bridge.
 */
import { keyed } from '../configuration/coding';
import type { Catalog } from '../catalogSchema/catalogSchema';
import type { LightSystem } from '../configuration/configuration';
import { chainCoordinates, locate } from './chainCoordinates';
import { nodeJoints } from './railTree';
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
  // `what` is a parameter ('suspension' or 'clip'): a UI words it (docs/i18n.md).
  if (points.length === 0) return keyed({ code: 'fixing-overhang', index: 0, message: `system ${system.id} has no ${what} points` }, 'fixingNone', { id: system.id, what });
  for (let i = 0; i < points.length; i++) {
    const s = points[i];
    if (!Number.isFinite(s)) return keyed({ code: 'fixing-order', index: i, message: `${what} point ${i + 1} is not a number` }, 'fixingNotNumber', { what, n: i + 1 });
    if (i > 0 && !(s > points[i - 1] + FIXING_EPS)) return keyed({ code: 'fixing-order', index: i, message: `${what} point ${i + 1} must lie past point ${i} along the chain` }, 'fixingOrder', { what, n: i + 1, prev: i });
  }
  const n = system.rails.length;
  // Each point's rail and depth along the tree (a node's point: the rail it ends), grouped per rail in depth order.
  const located = points.map((s) => locate(chain, s));
  const onRail: { depth: number; index: number }[][] = system.rails.map(() => []);
  located.forEach((l, index) => onRail[l.rail]?.push({ depth: l.depth, index }));
  const nodePoint = (p: number): number => points.findIndex((s) => Math.abs(s - chain.nodeAt[p]) <= FIXING_EPS);
  // Free ends: the chain start, and the end of every rail without a node (the last rail's: "the chain end").
  const first = onRail[0].length > 0 ? onRail[0][0].depth : located[0].depth;
  if (points[0] < -FIXING_EPS || first > rule.maxOverhang + FIXING_EPS)
    return keyed({ code: 'fixing-overhang', index: 0, message: `the chain start would overhang its first ${what} by ${fmt(Math.max(first, points[0]))} m (at most ${rule.maxOverhang} m)` }, 'fixingOverhangStart', {
      what,
      by: Number(fmt(Math.max(first, points[0]))),
      max: rule.maxOverhang,
    });
  for (let i = 0; i < n; i++) {
    if (!Number.isNaN(chain.nodeAt[i])) continue;
    const mine = onRail[i];
    const p = chain.parent[i];
    const lastDepth = mine.length > 0 ? mine[mine.length - 1].depth : p >= 0 ? chain.nodeDepth[p] : -Infinity;
    const tail = chain.depthStart[i] + chain.railLength[i] - lastDepth;
    const index = mine.length > 0 ? mine[mine.length - 1].index : points.length - 1;
    const end = i === n - 1 ? 'the chain end' : `the end of rail ${i + 1}`;
    const key = i === n - 1 ? 'fixingOverhangEnd' : 'fixingOverhangRailEnd';
    if (tail < -FIXING_EPS || tail > rule.maxOverhang + FIXING_EPS)
      return keyed({ code: 'fixing-overhang', index, message: `${end} would overhang its last ${what} by ${fmt(tail)} m (at most ${rule.maxOverhang} m)` }, key, { what, rail: i + 1, by: Number(fmt(tail)), max: rule.maxOverhang });
  }
  // Spacing along each rail, from the node it hangs on (if any) through its points.
  for (let i = 0; i < n; i++) {
    const p = chain.parent[i];
    const seq = p >= 0 ? [{ depth: chain.nodeDepth[p], index: nodePoint(p) }, ...onRail[i]] : onRail[i];
    for (let k = 1; k < seq.length; k++) {
      const gap = seq[k].depth - seq[k - 1].depth;
      if (gap > rule.spacing + FIXING_EPS) {
        const a = seq[k - 1].index;
        const params = { what, a: a + 1, b: seq[k].index + 1, gap: Number(fmt(gap)), max: rule.spacing };
        return keyed(
          { code: 'fixing-spacing', index: seq[k].index, message: `${what} points ${a >= 0 ? a + 1 : `at connector`} and ${seq[k].index + 1} would be ${fmt(gap)} m apart (at most ${rule.spacing} m)` },
          a >= 0 ? 'fixingSpacing' : 'fixingSpacingFromConnector',
          params,
        );
      }
    }
  }
  // Every connector node keeps its point.
  for (let p = 0; p < n; p++) {
    if (Number.isNaN(chain.nodeAt[p]) || nodePoint(p) >= 0) continue;
    const j = nodeJoints(system, p)[0];
    const k = points.findIndex((s) => s >= chain.nodeAt[p] - FIXING_EPS);
    return keyed({ code: 'fixing-joint', index: k >= 0 ? k : points.length - 1, message: `connector ${j + 1} must keep its ${what} (a connector is always a support)` }, 'fixingJoint', { what, n: j + 1 });
  }
  for (let i = 0; i < points.length; i++) {
    const s = points[i];
    if (chain.nodeAt.some((at) => Math.abs(s - at) <= FIXING_EPS)) continue;
    const onARail = chain.railStart.some((r0, r) => s >= r0 - FIXING_EPS && s <= r0 + system.rails[r].length + FIXING_EPS);
    if (!onARail) return keyed({ code: 'fixing-off-rail', index: i, message: `${what} point ${i + 1} would sit inside a connector, not on a rail` }, 'fixingOffRail', { what, n: i + 1 });
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
