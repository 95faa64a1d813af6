/**
 * Distances along a system's chain (docs/model.md, "Power feeds", "Suspension points" and
 * "Trees of rails"): the one coordinate the feed assignment and the suspension derivation share.
 *
 * Chain coordinate s: the rails laid end to end in list order: s = 0 at the start of the first
 * rail, each rail adds its length, then the length of rail profile the connector at its end
 * bridges (a straight connector its gap `arm`, a corner, flexible, T or X connector both arms),
 * then, when the next rail hangs on another node, that node's bridge once more (so every rail,
 * node point and bridge has its own interval). A connector node's own point (where its feed or
 * suspension sits) is the middle of that bridge: the gap's centre, or the hinge point. On a snake
 * this is the distance along the chain; on a tree it is a bookkeeping order (each rail a disjoint
 * interval), and distances use the tree: `treeDistance` runs along the rails and through the
 * nodes, as the current does.
 */
import { findConnector, type Catalog } from '../catalogSchema/catalogSchema';
import { twoArmed } from '../catalogSchema/connectorTurns';
import type { FeedAt, LightSystem } from '../configuration/configuration';
import { railPlacements, type PlanVec } from './geometry';
import { jointParent, railParents } from './railTree';

export interface ChainCoordinates {
  /** s of each rail's start. */
  readonly railStart: readonly number[];
  /** s of each joint's connector point (joints[k]: the node at the end of its parent rail). */
  readonly jointAt: readonly number[];
  /** s of the end of the last rail. */
  readonly length: number;
  /** Each rail's length (its interval in s). */
  readonly railLength: readonly number[];
  /** Parent rail of each rail (−1: the root). */
  readonly parent: readonly number[];
  /** s of the node at the end of each rail; NaN where the end is free. */
  readonly nodeAt: readonly number[];
  /** Distance along the tree from the chain start to each rail's start. */
  readonly depthStart: readonly number[];
  /** Distance along the tree from the chain start to the node at each rail's end; NaN where free. */
  readonly nodeDepth: readonly number[];
  /** Distance from a rail's end to its node's point (half the connector's span); 0 where free. */
  readonly nodeOut: readonly number[];
  /** Every rail hangs on the one before: distances along the tree are differences of depth. */
  readonly snake: boolean;
}

/** Length of profile a connector bridges between two rail ends: the straight gap, or both arms of a corner, flexible, T or X connector (at any turn). */
export function connectorSpan(catalog: Catalog, connector: string): number {
  const con = findConnector(catalog, connector);
  return twoArmed(con) ? 2 * con.arm : con.arm;
}

export function chainCoordinates(system: LightSystem, catalog: Catalog): ChainCoordinates {
  const n = system.rails.length;
  const parent = railParents(system);
  const railStart: number[] = [];
  // The connector at each rail's end (the first joint there names it).
  const nodeConnector: (string | undefined)[] = system.rails.map(() => undefined);
  system.joints.forEach((j, k) => {
    const p = jointParent(j, k);
    if (k < n - 1 && p >= 0 && p < n && nodeConnector[p] === undefined) nodeConnector[p] = j.connector;
  });
  let s = 0;
  system.rails.forEach((rail, i) => {
    railStart.push(s);
    s += rail.length;
    const joint = system.joints[i];
    if (!joint || i >= n - 1) return;
    // After rail i: its own node's bridge, then (when rail i+1 hangs elsewhere) the bridge rail i+1
    // comes through; on a snake both are joint i's, counted once.
    const own = nodeConnector[i];
    if (own !== undefined && jointParent(joint, i) !== i) s += connectorSpan(catalog, own);
    s += connectorSpan(catalog, joint.connector);
  });
  const nodeAt: number[] = system.rails.map(() => NaN);
  const nodeOut: number[] = system.rails.map(() => 0);
  const depthStart: number[] = system.rails.map(() => 0);
  const nodeDepth: number[] = system.rails.map(() => NaN);
  const jointAt: number[] = [];
  system.joints.forEach((joint, k) => {
    if (k >= n - 1) return;
    const p = jointParent(joint, k);
    if (!(p >= 0 && p <= k)) return jointAt.push(NaN);
    // The first joint at a node fixes its point (validate() requires one connector per node).
    if (Number.isNaN(nodeAt[p])) {
      const half = connectorSpan(catalog, joint.connector) / 2;
      nodeAt[p] = railStart[p] + system.rails[p].length + half;
      nodeOut[p] = half;
      nodeDepth[p] = depthStart[p] + system.rails[p].length + half;
    }
    depthStart[k + 1] = nodeDepth[p] + nodeOut[p];
    jointAt.push(nodeAt[p]);
  });
  const last = n - 1;
  return { railStart, jointAt, length: last >= 0 ? railStart[last] + system.rails[last].length : 0, railLength: system.rails.map((r) => r.length), parent, nodeAt, depthStart, nodeDepth, nodeOut, snake: parent.every((p, i) => p === i - 1) };
}

/** A place on the tree: a rail and the distance from the chain start along the tree (a node: its rail's index and the node's depth). */
export interface TreeLocation {
  readonly rail: number;
  readonly depth: number;
}

/** Where chain coordinate s lies on the tree: a node's point, else a rail (or a bridge: the rail it leads to). */
export function locate(chain: ChainCoordinates, s: number): TreeLocation {
  for (let p = 0; p < chain.nodeAt.length; p++) if (Math.abs(chain.nodeAt[p] - s) <= 1e-9) return { rail: p, depth: chain.nodeDepth[p] };
  const n = chain.railStart.length;
  for (let i = n - 1; i >= 0; i--) {
    // A point on the bridge after rail i (only invalid fixing lists have one) counts as past rail i's end.
    if (s >= chain.railStart[i] - 1e-9 || i === 0) return { rail: i, depth: chain.depthStart[i] + (s - chain.railStart[i]) };
  }
  return { rail: 0, depth: s };
}

/** Location of a point u metres from the start of rail i. */
export function onRail(chain: ChainCoordinates, i: number, u: number): TreeLocation {
  return { rail: i, depth: chain.depthStart[i] + u };
}

/**
 * Distance along the tree between two locations: along the rails and through the nodes (the
 * path a current or a fitter's tape takes). Same rail: the difference in depth; otherwise both
 * run up to where their paths meet (the node below their lowest common rail).
 */
export function treeDistance(chain: ChainCoordinates, a: TreeLocation, b: TreeLocation): number {
  if (a.rail === b.rail || chain.snake) return Math.abs(a.depth - b.depth);
  const above = new Set<number>();
  for (let r = a.rail; r >= 0; r = chain.parent[r]) above.add(r);
  let c = b.rail;
  while (c >= 0 && !above.has(c)) c = chain.parent[c];
  if (c < 0) return Infinity;
  const meet = chain.nodeDepth[c];
  return Math.abs(a.depth - meet) + Math.abs(b.depth - meet);
}

/**
 * Distances along the tree from one location to every place at once, in time linear in the rails
 * (feedLoads asks it once per feed instead of treeDistance once per module and feed, so a hostile
 * file's deep tree stays cheap). Returns a function giving the distance to any location: the walk
 * enters a rail through its start or through the node at its end, whichever is shorter (on a tree
 * the path to a rail the source is not on passes one of them).
 */
export function distancesFrom(chain: ChainCoordinates, from: TreeLocation): (to: TreeLocation) => number {
  const n = chain.railStart.length;
  if (chain.snake) return (to) => Math.abs(to.depth - from.depth);
  const end = (i: number) => chain.depthStart[i] + chain.railLength[i];
  // Vertices: 2i = start of rail i, 2i + 1 = the node at its end (or its free end).
  const adj: [number, number][][] = Array.from({ length: 2 * n }, () => []);
  const link = (a: number, b: number, w: number) => (adj[a].push([b, w]), adj[b].push([a, w]));
  for (let i = 0; i < n; i++) {
    link(2 * i, 2 * i + 1, Number.isNaN(chain.nodeAt[i]) ? chain.railLength[i] : chain.nodeDepth[i] - chain.depthStart[i]);
    const p = chain.parent[i];
    if (p >= 0 && p < n) link(2 * p + 1, 2 * i, chain.depthStart[i] - chain.nodeDepth[p]);
  }
  const dist = new Float64Array(2 * n).fill(Infinity);
  const r = from.rail;
  const atNode = !Number.isNaN(chain.nodeAt[r]) && Math.abs(from.depth - chain.nodeDepth[r]) <= 1e-12;
  dist[2 * r] = Math.abs(from.depth - chain.depthStart[r]);
  dist[2 * r + 1] = atNode ? 0 : Math.abs((Number.isNaN(chain.nodeAt[r]) ? end(r) : chain.nodeDepth[r]) - from.depth);
  const stack = [2 * r, 2 * r + 1];
  const seen = new Uint8Array(2 * n);
  seen[2 * r] = seen[2 * r + 1] = 1;
  while (stack.length > 0) {
    const v = stack.pop()!;
    for (const [w, len] of adj[v]) {
      if (seen[w]) continue;
      seen[w] = 1;
      dist[w] = dist[v] + len;
      stack.push(w);
    }
  }
  return (to) => {
    if (to.rail === r) return Math.abs(to.depth - from.depth);
    const i = to.rail;
    const top = Number.isNaN(chain.nodeAt[i]) ? end(i) : chain.nodeDepth[i];
    return Math.min(dist[2 * i] + (to.depth - chain.depthStart[i]), dist[2 * i + 1] + Math.abs(top - to.depth));
  };
}

/** s of a feed position; NaN for a connector or rail the chain does not have. */
export function feedCoordinate(at: FeedAt, chain: ChainCoordinates): number {
  if (at === 'start') return 0;
  if (at === 'end') return chain.length;
  if ('joint' in at) return chain.jointAt[at.joint] ?? NaN;
  const i = at.end;
  return Number.isInteger(i) && i >= 0 && i < chain.railStart.length && Number.isNaN(chain.nodeAt[i]) ? chain.railStart[i] + railLength(chain, i) : NaN;
}

/** Location of a feed position on the tree (null for one the chain lacks). */
export function feedLocation(at: FeedAt, chain: ChainCoordinates): TreeLocation | null {
  const n = chain.railStart.length;
  if (n === 0) return null;
  if (at === 'start') return { rail: 0, depth: 0 };
  if (at === 'end') return { rail: n - 1, depth: chain.depthStart[n - 1] + railLength(chain, n - 1) };
  if ('joint' in at) {
    const k = at.joint;
    if (!(Number.isInteger(k) && k >= 0 && k < n - 1)) return null;
    const p = chain.parent[k + 1];
    return { rail: p, depth: chain.nodeDepth[p] };
  }
  const i = at.end;
  if (!(Number.isInteger(i) && i >= 0 && i < n) || !Number.isNaN(chain.nodeAt[i])) return null;
  return { rail: i, depth: chain.depthStart[i] + railLength(chain, i) };
}

function railLength(chain: ChainCoordinates, i: number): number {
  return chain.railLength[i];
}

/**
 * The plan point at chain coordinate s: a node's point (the gap's centre or the hinge); on a
 * rail, its start plus s along it; on a bridge, along the parent rail's connector toward the
 * rail it leads to. s outside the chain clamps to its ends.
 */
export function chainPoint(system: LightSystem, catalog: Catalog, s: number): PlanVec {
  const chain = chainCoordinates(system, catalog);
  const rails = railPlacements(system, catalog);
  if (rails.length === 0) return [system.x, system.z];
  for (let p = 0; p < rails.length; p++) {
    if (Math.abs(chain.nodeAt[p] - s) <= 1e-9) {
      const r = rails[p];
      const h = chain.nodeOut[p];
      return [r.end[0] + r.direction[0] * h, r.end[1] + r.direction[1] * h];
    }
  }
  for (let i = rails.length - 1; i >= 0; i--) {
    const r = rails[i];
    const u = s - chain.railStart[i];
    if (u >= 0 || i === 0) {
      if (u <= r.length || i === rails.length - 1) {
        const t = Math.max(0, Math.min(r.length, u));
        return [r.start[0] + r.direction[0] * t, r.start[1] + r.direction[1] * t];
      }
      // On the bridge after rail i: the connector from rail i+1's parent toward rail i+1.
      const next = rails[i + 1];
      const parent = rails[chain.parent[i + 1]];
      const con = findConnector(catalog, system.joints[i].connector);
      const arm = con.arm;
      // Measured from the start of rail i+1's own bridge (on a tree, rail i's node may come first).
      const along = s - (chain.railStart[i + 1] - connectorSpan(catalog, system.joints[i].connector));
      if (along < 0) return r.end;
      if (!twoArmed(con) || along <= arm) return [parent.end[0] + parent.direction[0] * along, parent.end[1] + parent.direction[1] * along];
      const pivot: PlanVec = [parent.end[0] + parent.direction[0] * arm, parent.end[1] + parent.direction[1] * arm];
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
