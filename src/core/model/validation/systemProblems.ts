/** A system in the plan: inside the room, not running into itself, not clashing with another system. */
import type { Catalog } from '../catalogSchema/catalogSchema';
import type { Configuration, LightSystem } from '../configuration/configuration';
import type { Problem } from '../configuration/problem';
import { perCatalog } from '../catalogSchema/perCatalog';
import { rectCorners, rectsOverlap, systemElementTree, type PlanRect, type SystemElementTree } from '../rails/geometry';
import { boxesMeet, boxOf, forEachOverlap, type Box } from './planOverlaps';
import { EPS } from './reporting';
import { ownProblems } from './systemOwnProblems';
import { requireRoomShapeSupport } from '../configuration/roomShapeSupport';
import type { Room } from '../configuration/configuration';

/**
 * Problems of one system: its own rules, its fit in the room and clashes with
 * the other systems. The action binding (validateResult.ts) and the preset
 * placement search check only the systems a change touched with it.
 */
export function systemProblems(config: Configuration, index: number, catalog: Catalog): Problem[] {
  const s = config.systems[index];
  const at = `systems[${index}]`;
  const out = ownProblems(s, at, config.room.height, catalog);
  if (out.length > 0) return out; // geometry needs sound references and numbers
  const tree = systemElementTree(s, catalog);
  const elements = tree.elements;
  const misfit = roomFitProblem(s, index, elements, config.room, catalog);
  if (misfit) out.push(misfit);
  if (crossesItself(tree)) out.push({ code: 'self-overlap', path: at, message: `system ${s.id} runs into itself`, params: { id: s.id } });
  const mine = footprintOf(s, catalog);
  config.systems.forEach((other, j) => {
    if (j !== index && clashes(mine, other, config.room.height, catalog)) {
      out.push({ code: 'system-overlap', path: at, message: `system ${s.id} overlaps system ${other.id}`, params: { id: s.id, other: other.id } });
    }
  });
  return out;
}

/** A system's own rules, with paths relative to the system ('.rails[0].length'): the part of systemProblems that does not depend on where it stands, but for a finite x and z. */
export function systemOwnProblems(s: LightSystem, roomHeight: number, catalog: Catalog): Problem[] {
  return ownProblems(s, '', roomHeight, catalog);
}

/**
 * Whether systemProblems(config, index, catalog) would be empty, for a system whose own rules
 * (systemOwnProblems) the caller already knows to hold and whose x and z are finite: the preset
 * placement search tries up to 1 600 spots of one system, and stops at the first problem, the
 * cheap ones first (room bounds, clashes by bounding boxes, then self-crossing).
 */
export function systemFitsAt(config: Configuration, index: number, catalog: Catalog): boolean {
  const s = config.systems[index];
  const tree = systemElementTree(s, catalog);
  if (roomFitProblem(s, index, tree.elements, config.room, catalog)) return false;
  const mine = footprintOf(s, catalog);
  if (config.systems.some((other, j) => j !== index && clashes(mine, other, config.room.height, catalog))) return false;
  return !crossesItself(tree);
}

/** Neighbours in the tree touch by design; anything further apart must not overlap. */
function crossesItself(tree: SystemElementTree): boolean {
  const rects = tree.elements.flat();
  const chainIndex = tree.elements.flatMap((group, a) => group.map(() => a));
  let crosses = false;
  forEachOverlap(
    rects,
    { pairTests: 0 },
    () => ((crosses = true), 'stop'),
    (p, q) => !tree.near[chainIndex[p]].has(chainIndex[q]),
  );
  return crosses;
}

interface Footprint {
  readonly rects: readonly PlanRect[];
  readonly boxes: readonly Box[];
  /** The union of the boxes. */
  readonly box: Box;
}

/** A sound system's rectangles and their boxes, once per system object (perCatalog.ts). */
const footprintOf = perCatalog((s: LightSystem, catalog: Catalog): Footprint => {
  const rects = systemElementTree(s, catalog).elements.flat();
  const boxes = rects.map(boxOf);
  const box = boxes.reduce((u, b) => ({ minX: Math.min(u.minX, b.minX), minZ: Math.min(u.minZ, b.minZ), maxX: Math.max(u.maxX, b.maxX), maxZ: Math.max(u.maxZ, b.maxZ) }), {
    minX: Infinity,
    minZ: Infinity,
    maxX: -Infinity,
    maxZ: -Infinity,
  });
  return { rects, boxes, box };
});

/** Whether a sound system's footprint overlaps `other`'s (none when other breaks its own rules: it has no geometry to clash with). */
function clashes(mine: Footprint, other: LightSystem, roomHeight: number, catalog: Catalog): boolean {
  if (ownProblems(other, '', roomHeight, catalog).length > 0) return false;
  const theirs = footprintOf(other, catalog);
  if (!boxesMeet(mine.box, theirs.box)) return false;
  // Only their rectangles whose boxes meet my whole footprint's box, then pair by pair: boxes first, then the exact test.
  const near = theirs.rects.flatMap((rb, q) => (boxesMeet(theirs.boxes[q], mine.box) ? [q] : []));
  return mine.rects.some((ra, p) => near.some((q) => boxesMeet(mine.boxes[p], theirs.boxes[q]) && rectsOverlap(ra, theirs.rects[q])));
}

export function outsideRoom(elements: PlanRect[][], width: number, depth: number): boolean {
  // "Not inside" rather than "outside": a NaN corner fails every comparison and must count as outside (issue 32).
  return elements
    .flat()
    .flatMap(rectCorners)
    .some(([x, z]) => !(x >= -EPS && x <= width + EPS && z >= -EPS && z <= depth + EPS));
}

export function outsideProblem(s: LightSystem, index: number, room: Configuration['room']): Problem {
  return { code: 'outside-room', path: `systems[${index}]`, message: `system ${s.id} reaches outside the ${room.width} × ${room.depth} m room`, params: { id: s.id, width: room.width, depth: room.depth } };
}

/**
 * Whether a sound system fits its room: inside the box, and in a room with a shape (issue 29)
 * inside its outline and clear of its slopes (shapedSystemFit.ts, in the room-shape chunk).
 */
export function roomFitProblem(s: LightSystem, index: number, elements: PlanRect[][], room: Room, catalog: Catalog): Problem | null {
  if (outsideRoom(elements, room.width, room.depth)) return outsideProblem(s, index, room);
  return room.shape ? requireRoomShapeSupport().systemFit(s, index, elements.flat().map(rectCorners), room, catalog) : null;
}
