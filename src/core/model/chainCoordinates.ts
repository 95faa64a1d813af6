/**
 * Distances along a system's chain (docs/model.md, "Power feeds" and "Suspension points"):
 * the one coordinate the feed assignment and the suspension derivation share. s = 0 at the
 * start of the first rail; each rail adds its length and each connector the length of the
 * rail profile it bridges: a straight connector its gap (`arm`), a corner or flexible connector both
 * arms (rail end → corner point → next rail start). A connector's own point (where its feed
 * or suspension sits) is the middle of that bridge: the gap's centre, or the corner point.
 */
import { findConnector, twoArmed, type Catalog } from './catalogSchema';
import type { FeedAt, LightSystem } from './configuration';
import { railPlacements, type PlanVec } from './geometry';

export interface ChainCoordinates {
  /** s of each rail's start. */
  readonly railStart: readonly number[];
  /** s of each connector's point (joints[k]). */
  readonly jointAt: readonly number[];
  /** s of the end of the last rail. */
  readonly length: number;
}

/** Length of profile a connector bridges between two rail ends: the straight gap, or both arms of a corner or flexible connector (at any turn). */
export function connectorSpan(catalog: Catalog, connector: string): number {
  const con = findConnector(catalog, connector);
  return twoArmed(con) ? 2 * con.arm : con.arm;
}

export function chainCoordinates(system: LightSystem, catalog: Catalog): ChainCoordinates {
  const railStart: number[] = [];
  const jointAt: number[] = [];
  let s = 0;
  system.rails.forEach((rail, i) => {
    railStart.push(s);
    s += rail.length;
    const joint = system.joints[i];
    if (joint && i < system.rails.length - 1) {
      const span = connectorSpan(catalog, joint.connector);
      jointAt.push(s + span / 2);
      s += span;
    }
  });
  const last = system.rails.length - 1;
  return { railStart, jointAt, length: last >= 0 ? railStart[last] + system.rails[last].length : 0 };
}

/** s of a feed position; NaN for a joint the chain does not have. */
export function feedCoordinate(at: FeedAt, chain: ChainCoordinates): number {
  if (at === 'start') return 0;
  if (at === 'end') return chain.length;
  return chain.jointAt[at.joint] ?? NaN;
}

/**
 * The plan point at chain coordinate s: on a rail, its start plus s along it; on a connector,
 * the gap's centre (straight) or the corner point. s outside the chain clamps to its ends.
 */
export function chainPoint(system: LightSystem, catalog: Catalog, s: number): PlanVec {
  const chain = chainCoordinates(system, catalog);
  const rails = railPlacements(system, catalog);
  for (let i = 0; i < rails.length; i++) {
    const r = rails[i];
    const u = s - chain.railStart[i];
    if (u <= r.length || i === rails.length - 1) {
      const t = Math.max(0, Math.min(r.length, u));
      return [r.start[0] + r.direction[0] * t, r.start[1] + r.direction[1] * t];
    }
    const next = rails[i + 1];
    if (s < chain.railStart[i + 1]) {
      // On the connector: its straight gap, or the two arms through the corner point.
      const joint = system.joints[i];
      const con = findConnector(catalog, joint.connector);
      const arm = con.arm;
      const along = u - r.length;
      if (!twoArmed(con) || along <= arm) return [r.end[0] + r.direction[0] * along, r.end[1] + r.direction[1] * along];
      const pivot: PlanVec = [r.end[0] + r.direction[0] * arm, r.end[1] + r.direction[1] * arm];
      return [pivot[0] + next.direction[0] * (along - arm), pivot[1] + next.direction[1] * (along - arm)];
    }
  }
  return [system.x, system.z];
}

/**
 * The chain coordinate of the rail point nearest to a plan point (the orthogonal projection onto
 * each rail segment, clamped to it; the nearest rail wins, the earlier one on a tie): where a
 * dragged fixing point goes. Connector bridges are left out, since only rails carry moved points.
 */
export function chainCoordinateAt(system: LightSystem, catalog: Catalog, point: PlanVec): number {
  const chain = chainCoordinates(system, catalog);
  let best = { d: Infinity, s: 0 };
  railPlacements(system, catalog).forEach((r, i) => {
    const t = Math.max(0, Math.min(r.length, (point[0] - r.start[0]) * r.direction[0] + (point[1] - r.start[1]) * r.direction[1]));
    const d = Math.hypot(point[0] - (r.start[0] + r.direction[0] * t), point[1] - (r.start[1] + r.direction[1] * t));
    if (d < best.d) best = { d, s: chain.railStart[i] + t };
  });
  return best.s;
}
