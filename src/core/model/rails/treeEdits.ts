/**
 * Structural edits of a tree of rails (docs/model.md, "Trees of rails"): cutting a rail out
 * (the tree falls into the pieces that remain) and where feeds go when the tree changes. Pure
 * functions on a system; the actions (actions/railActions.ts, actions/branchActions.ts) wrap
 * them, validate() judges the result.
 */
import type { Catalog } from '../catalogSchema/catalogSchema';
import type { Feed, FeedAt, Joint, LightSystem } from '../configuration/configuration';
import { railPlacements } from './geometry';
import { jointParent, nodeJoints, railParents, subtreeRails } from './railTree';

/** Where a feed physically is: the root start, the node at a rail's end, or a rail's free end. */
export type FeedPlace = { readonly kind: 'start' } | { readonly kind: 'node'; readonly rail: number } | { readonly kind: 'end'; readonly rail: number };

/** The place of a feed position on this system (positions the chain lacks give null). */
export function feedPlace(system: Pick<LightSystem, 'rails' | 'joints'>, at: FeedAt): FeedPlace | null {
  if (at === 'start') return { kind: 'start' };
  if (at === 'end') return { kind: 'end', rail: system.rails.length - 1 };
  if ('joint' in at) {
    const j = system.joints[at.joint];
    return j ? { kind: 'node', rail: jointParent(j, at.joint) } : null;
  }
  return { kind: 'end', rail: at.end };
}

/**
 * The written position for a place, as a system of this shape states it: a node through its
 * first joint, the last rail's free end as 'end', another free end as { end: i }. A node that
 * lost all its branches is a free end again.
 */
export function feedAtFor(system: Pick<LightSystem, 'rails' | 'joints'>, place: FeedPlace): FeedAt {
  if (place.kind === 'start') return 'start';
  const branches = nodeJoints(system, place.rail);
  if (branches.length > 0) return { joint: branches[0] };
  return place.rail === system.rails.length - 1 ? 'end' : { end: place.rail };
}

/**
 * The pieces of a system's tree, each as its old rail indices (ascending) with its root: the
 * tree without the subtree of `rail` (when `rail` is not the root), then one piece per branch of
 * the node at `rail`'s end, in joint order.
 */
export function piecesWithout(system: Pick<LightSystem, 'rails' | 'joints'>, rail: number): number[][] {
  const pieces: number[][] = [];
  const cut = new Set(subtreeRails(system, rail));
  if (rail !== 0) pieces.push(system.rails.map((_, i) => i).filter((i) => !cut.has(i)));
  for (const k of nodeJoints(system, rail)) pieces.push(subtreeRails(system, k + 1));
  return pieces;
}

/**
 * One piece of a system as its own system: rails `members` (old indices, ascending, the first
 * its root), anchored at its root's start and heading; joints re-indexed (a joint's `parent`
 * written only when it is not the rail just before). Feeds are given separately.
 */
export function pieceSystem(system: LightSystem, catalog: Catalog, members: readonly number[], id: string, feeds: readonly Feed[]): LightSystem {
  const parents = railParents(system);
  const newIndex = new Map(members.map((old, i) => [old, i]));
  const root = railPlacements(system, catalog)[members[0]];
  const joints: Joint[] = members.slice(1).map((old, i) => {
    const { parent: _old, ...rest } = system.joints[old - 1];
    const parent = newIndex.get(parents[old])!;
    return parent === i ? rest : { ...rest, parent };
  });
  const { presetId, fixings: _fixings, ...base } = system;
  const keepsPreset = id === system.id && presetId !== undefined;
  return {
    ...base,
    ...(keepsPreset ? { presetId } : {}),
    id,
    x: root.start[0],
    z: root.start[1],
    rotation: root.heading,
    rails: members.map((i) => system.rails[i]),
    joints,
    feeds,
  };
}

/**
 * Where each feed goes when `rail` is cut out: its place in the piece that holds it (a node that
 * lost its only branch becomes that rail's free end; a feed at the removed rail's own free end
 * goes to the node it hung on). A feed at the removed rail's node, or at the chain start when the
 * root is removed, goes to the start of the first branch's piece (the first connector becomes the
 * start). Returns per piece its feeds with places in OLD indices; null for a feed that has none.
 */
export function feedsByPiece(system: LightSystem, rail: number, pieces: readonly number[][]): { feed: Feed; place: FeedPlace }[][] {
  const parents = railParents(system);
  const pieceOf = new Map<number, number>();
  pieces.forEach((members, i) => members.forEach((r) => pieceOf.set(r, i)));
  const out: { feed: Feed; place: FeedPlace }[][] = pieces.map(() => []);
  // The first branch's piece: right after the rest of the tree, or first when the root goes.
  const branchPiece = rail === 0 ? 0 : 1;
  for (const feed of system.feeds) {
    const was = feedPlace(system, feed.at);
    if (!was) continue;
    let place: FeedPlace = was;
    let piece: number | undefined;
    if (was.kind === 'start') piece = 0;
    else if (was.rail === rail && was.kind === 'node') {
      place = { kind: 'start' };
      piece = branchPiece;
    } else if (was.rail === rail) {
      // The removed rail's own free end: the feed stays at the node it hung on (the root: the next start).
      if (rail === 0) continue;
      place = { kind: 'node', rail: parents[rail] };
      piece = pieceOf.get(parents[rail]);
    } else piece = pieceOf.get(was.rail);
    if (piece === undefined || !pieces[piece]) continue;
    out[piece].push({ feed, place });
  }
  return out;
}

/**
 * The system with rail `rail` cut out, as the systems that remain (docs/model.md, "Removing a
 * rail"): the first keeps the system's id (and preset), the others get `newIds` in order; each
 * keeps its rails, joints, modules and the feeds on it (feedsByPiece); moved fixing points go
 * (the coordinates are renumbered). Pieces without a feed are returned with `feeds: []` for the
 * caller to plan. An empty list when the only rail goes.
 */
export function cutRail(system: LightSystem, catalog: Catalog, rail: number, newIds: readonly string[]): LightSystem[] {
  const pieces = piecesWithout(system, rail);
  const byPiece = feedsByPiece(system, rail, pieces);
  return pieces.map((members, i) => {
    const shape = pieceSystem(system, catalog, members, i === 0 ? system.id : newIds[i - 1], []);
    const newIndex = new Map(members.map((old, k) => [old, k]));
    const feeds = byPiece[i].map(({ feed, place }) => ({ ...feed, at: feedAtFor(shape, place.kind === 'start' ? place : { ...place, rail: newIndex.get(place.rail)! }) }));
    return { ...shape, feeds };
  });
}
