/**
 * Where a system is fixed to the ceiling (docs/model.md, "Suspension points"), derived from
 * the catalog's rules, never stored: suspensions (`suspension.maxSpacing`, `maxOverhang`)
 * when the system hangs, clips (`surfaceMount.spacing`, `maxOverhang`) when it is on the
 * ceiling. Deterministic rule, per rail from its start support a to its end support b:
 *  - every connector node is a support (at its point: the gap's centre or the hinge point), one
 *    point however many branches it holds;
 *  - a free chain end (start of the first rail, end of any rail without a node: the last rail's
 *    and every branch's) has its support
 *    e = min(maxOverhang, L/4) inside the rail (L that rail's length): the overhang never
 *    exceeds the rule, and a short rail still gets two points at its quarter points;
 *  - between a and b, k = ⌈(b − a)/spacing⌉ − 1 interior points evenly, so no gap exceeds
 *    the spacing and the gaps are equal (b − a along the tree: a branch starts at its node).
 * So a system is always fixable by construction (no action can break it); the count goes to
 * the bill of materials and the ceiling-fixing count of installationNeeds. Points the user
 * moved (`system.fixings`, moveFixingPoint) replace the derived ones; fixingRules.ts states
 * the rules they keep.
 */
import type { Catalog } from '../catalogSchema/catalogSchema';
import type { LightSystem, Room } from '../configuration/configuration';
import { chainCoordinates, chainPoint } from './chainCoordinates';
import { firstNodeJoints } from './railTree';
import type { PlanVec } from './geometry';
import { requireRoomShapeSupport } from '../configuration/roomShapeSupport';

export interface MountingRule {
  /** Largest distance between two points along the chain, metres. */
  readonly spacing: number;
  /** Largest overhang past the last point at a free chain end, metres. */
  readonly maxOverhang: number;
}

export interface SuspensionPoint {
  /** Chain coordinate, metres from the start of the first rail. */
  readonly s: number;
  /** Plan position [x, z]. */
  readonly plan: PlanVec;
  /** The connector (joints index) it sits at, or null on a rail. */
  readonly joint: number | null;
}

/** The spacing rules of the system's mounting. */
export function mountingRule(system: LightSystem, catalog: Catalog): MountingRule {
  return system.mounting === 'surface' ? { spacing: catalog.surfaceMount.spacing, maxOverhang: catalog.surfaceMount.maxOverhang } : { spacing: catalog.suspension.maxSpacing, maxOverhang: catalog.suspension.maxOverhang };
}

/** Chain coordinates of the fixing points: the user's moved ones, or else the derived ones; with the connector each sits at. */
export function suspensionCoordinates(system: LightSystem, catalog: Catalog): { s: number; joint: number | null }[] {
  if (system.fixings === undefined) return derivedSuspensionCoordinates(system, catalog);
  const chain = chainCoordinates(system, catalog);
  return system.fixings.map((s) => {
    const k = chain.jointAt.findIndex((at) => Math.abs(at - s) <= 1e-6);
    return { s, joint: k >= 0 ? k : null };
  });
}

/** Chain coordinates of the derived fixing points (see the rule above), with the connector each sits at. */
export function derivedSuspensionCoordinates(system: LightSystem, catalog: Catalog): { s: number; joint: number | null }[] {
  const rule = mountingRule(system, catalog);
  const chain = chainCoordinates(system, catalog);
  const out: { s: number; joint: number | null }[] = [];
  const firstJoint = firstNodeJoints(system);
  system.rails.forEach((rail, i) => {
    const inset = Math.min(rule.maxOverhang, rail.length / 4);
    const node = firstJoint[i];
    const p = chain.parent[i];
    // In chain coordinates; a branch that is not its node's first has its node elsewhere in s, so
    // its start support is placed by the tree distance (nodeOut) before its start.
    const a = i === 0 ? chain.railStart[0] + inset : p === i - 1 ? chain.nodeAt[p] : chain.railStart[i] - chain.nodeOut[p];
    const b = node === undefined ? chain.railStart[i] + rail.length - inset : chain.nodeAt[i];
    if (i === 0) out.push({ s: a, joint: null });
    // 1e-9: a gap of exactly the spacing (float noise aside) needs no extra point.
    const k = Math.max(0, Math.ceil((b - a) / rule.spacing - 1e-9) - 1);
    for (let j = 1; j <= k; j++) out.push({ s: a + ((b - a) * j) / (k + 1), joint: null });
    out.push({ s: b, joint: node ?? null });
  });
  return out;
}

/** The fixing points with their plan positions (the plan draws them as dots). */
export function suspensionPoints(system: LightSystem, catalog: Catalog): SuspensionPoint[] {
  return suspensionCoordinates(system, catalog).map((p) => ({ ...p, plan: chainPoint(system, catalog, p.s) }));
}

/** Ceiling to photometric centre of the system's modules: its suspension, or the surface mount's drop. */
export function photometricDrop(system: LightSystem, catalog: Catalog): number {
  return system.mounting === 'surface' ? catalog.surfaceMount.drop : system.suspension;
}

/** Height of the modules' photometric centre above the floor (toLightingScene, the head-room rule). */
export function moduleHeight(system: LightSystem, room: Pick<Room, 'height'>, catalog: Catalog): number {
  return room.height - photometricDrop(system, catalog);
}

/**
 * The wire of each fixing point (suspensionPoints order), metres: the ceiling above the point less
 * the modules' height. In a box every wire is the system's suspension; under a slope (issue 29) the
 * modules stay level and each wire follows the ceiling above its own point, shorter toward the
 * slope (validate() keeps every one at least the catalog's suspension.min). Surface-mounted
 * systems have clips, not wires: 0 each.
 */
export function suspensionWireLengths(system: LightSystem, room: Room, catalog: Catalog): number[] {
  const points = suspensionPoints(system, catalog);
  if (system.mounting === 'surface') return points.map(() => 0);
  const modules = moduleHeight(system, room, catalog);
  if (!room.shape) return points.map(() => room.height - modules);
  const { ceilingAt } = requireRoomShapeSupport();
  return points.map((p) => ceilingAt(room, p.plan[0], p.plan[1]) - modules);
}
