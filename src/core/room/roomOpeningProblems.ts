/** The openings' rules (issue 29): on a wall, a known kind, a size, between the wall's ends, under its top, apart from each other. */
import { lowestPlaneHeight, type CeilingPlane } from './ceilingPlanes';
import { OPENING_KINDS, type RoomOpening } from './roomInput';
import { EPS, isFiniteNumber, problem, round, wallLength, wallOk, type RoomFrame, type RoomProblem } from './roomProblem';

/** An opening already accepted: its wall and its rectangle on it (u along the wall, v up, metres). */
interface PlacedOpening {
  i: number;
  wall: number;
  u0: number;
  u1: number;
  v0: number;
  v1: number;
}

/** Each opening's first problem, in order; an opening that keeps every rule is placed for the overlap test of the next ones. */
export function openingProblems(openings: readonly RoomOpening[], frame: RoomFrame, planes: readonly CeilingPlane[]): RoomProblem[] {
  const out: RoomProblem[] = [];
  const placed: PlacedOpening[] = [];
  openings.forEach((o, i) => {
    const found = openingShapeProblem(o, i, frame) ?? openingPlacementProblem(o, i, frame, planes, placed);
    if (found) out.push(found);
    else placed.push({ i, wall: o.wall, u0: o.offset, u1: o.offset + o.width, v0: o.sill, v1: o.sill + o.height });
  });
  return out;
}

/** The opening on its own: wall, kind, width and height, sill, and within the wall's length. */
function openingShapeProblem(o: RoomOpening, i: number, frame: RoomFrame): RoomProblem | null {
  const { n } = frame;
  const at = `room.openings[${i}]`;
  if (!wallOk(frame, o.wall)) {
    return problem('room-opening-wall', `${at}.wall`, `opening ${i} is in wall ${String(o.wall)}, but the room has walls 0 to ${n - 1}`, { opening: i, wall: String(o.wall), last: n - 1 });
  }
  if (!OPENING_KINDS.includes(o.kind)) {
    return problem('room-opening-kind', `${at}.kind`, `opening ${i} is a ${String(o.kind)}; it must be a door, a window or an opening`, { opening: i, kind: String(o.kind) });
  }
  for (const key of ['width', 'height'] as const) {
    if (!(isFiniteNumber(o[key]) && o[key] > 0)) {
      return problem('room-opening-size', `${at}.${key}`, `opening ${i} must have a ${key} above 0 m (got ${String(o[key])})`, { opening: i, dimension: key, value: String(o[key]) });
    }
  }
  if (!(isFiniteNumber(o.sill) && o.sill >= 0)) {
    return problem('room-opening-sill', `${at}.sill`, `opening ${i} has a sill of ${String(o.sill)} m; it must be 0 or above`, { opening: i, value: String(o.sill) });
  }
  const length = wallLength(frame, o.wall);
  if (!(isFiniteNumber(o.offset) && o.offset >= -EPS && o.offset + o.width <= length + EPS)) {
    return problem('room-opening-beyond-wall', `${at}.offset`, `opening ${i} reaches from ${String(o.offset)} to ${round(o.offset + o.width)} m along wall ${o.wall}, which is ${round(length)} m long; it must stay between the wall's ends`, {
      opening: i,
      wall: o.wall,
      offset: String(o.offset),
      end: round(o.offset + o.width),
      length: round(length),
    });
  }
  return null;
}

/** The opening among the rest: under the wall's top (the ceiling along it), and overlapping no opening placed before it. */
function openingPlacementProblem(o: RoomOpening, i: number, frame: RoomFrame, planes: readonly CeilingPlane[], placed: readonly PlacedOpening[]): RoomProblem | null {
  const at = `room.openings[${i}]`;
  // The wall's top is concave along it: the opening fits under it when both top corners do.
  const top = o.sill + o.height;
  const ceiling = Math.min(ceilingAlong(frame, planes, o.wall, o.offset), ceilingAlong(frame, planes, o.wall, o.offset + o.width));
  if (top > ceiling + EPS) {
    return problem('room-opening-above-ceiling', `${at}.height`, `opening ${i} reaches ${round(top)} m up wall ${o.wall}, above its top (${round(ceiling)} m there)`, { opening: i, wall: o.wall, top: round(top), ceiling: round(ceiling) });
  }
  for (const p of placed) {
    if (p.wall !== o.wall) continue;
    if (o.offset < p.u1 - EPS && p.u0 < o.offset + o.width - EPS && o.sill < p.v1 - EPS && p.v0 < top - EPS) {
      return problem('room-openings-overlap', at, `openings ${p.i} and ${i} overlap on wall ${o.wall}`, { opening: i, other: p.i, wall: o.wall });
    }
  }
  return null;
}

/** The ceiling's height above wall w, u metres from its first corner. */
function ceilingAlong(frame: RoomFrame, planes: readonly CeilingPlane[], w: number, u: number): number {
  const { corners, n } = frame;
  const a = corners[w];
  const b = corners[(w + 1) % n];
  const t = u / wallLength(frame, w);
  return lowestPlaneHeight(planes, a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]));
}
