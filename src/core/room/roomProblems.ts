/**
 * The rules a room of any shape must keep (issue 29), as problems a UI can word in its own
 * language: a stable `code`, the values in `params` (indices count from 0, as in the file; lengths
 * in metres) and an English `message` that names the problem and where (wall i, corner i, slope i,
 * opening i), like the configuration's problems (src/core/model/validate.ts).
 */
import type { MessageParams } from '../inputError';
import { flatPlane, lowestPlaneHeight, slopePlane, type CeilingPlane } from './ceilingPlanes';
import { doubleSignedArea, orient, segmentsIntersect, type PlanPoint } from './planPolygon';
import { OPENING_KINDS, ROOM_SHAPE_LIMITS, type RoomInput, type RoomReflectance } from './roomInput';

export interface RoomProblem {
  /** Stable machine-readable code, e.g. 'room-wall-short'. */
  readonly code: string;
  /** One English sentence naming the problem and where. */
  readonly message: string;
  readonly params: MessageParams;
  /** Where in the room object, e.g. 'room.openings[1].offset'. */
  readonly path: string;
}

/** Float noise allowed in the geometric comparisons (a nanometre). */
const EPS = 1e-9;

const round = (v: number): number => Math.round(v * 1000) / 1000;
const isFiniteNumber = (v: unknown): v is number => typeof v === 'number' && Number.isFinite(v);

function problem(code: string, path: string, message: string, params: MessageParams): RoomProblem {
  return { code, path, message, params };
}

function reflectanceOk(r: unknown): boolean {
  const ok = (v: unknown) => isFiniteNumber(v) && v >= 0 && v < 1;
  return ok(r) || (Array.isArray(r) && r.length === 3 && r.every(ok));
}

/** The outline's own rules: corner count, coordinates, wall lengths, corner spacing, no self-intersection. */
export function outlineProblems(outline: readonly PlanPoint[]): RoomProblem[] {
  const { minCorners, maxCorners, minWall, maxCoordinate } = ROOM_SHAPE_LIMITS;
  const n = Array.isArray(outline) ? outline.length : 0;
  if (n < minCorners || n > maxCorners) {
    return [problem('room-corner-count', 'room.outline', `the outline has ${n} corners; a room needs ${minCorners} to ${maxCorners}`, { count: n, min: minCorners, max: maxCorners })];
  }
  const out: RoomProblem[] = [];
  outline.forEach((c, i) => {
    if (!Array.isArray(c) || c.length !== 2 || !c.every((v) => isFiniteNumber(v) && Math.abs(v) <= maxCoordinate)) {
      out.push(problem('room-corner-invalid', `room.outline[${i}]`, `corner ${i} must be [x, z] in metres within ±${maxCoordinate} m`, { corner: i, max: maxCoordinate }));
    }
  });
  if (out.length > 0) return out;
  for (let i = 0; i < n; i++) {
    const a = outline[i];
    const b = outline[(i + 1) % n];
    const length = Math.hypot(b[0] - a[0], b[1] - a[1]);
    if (length < minWall - EPS) {
      out.push(
        problem('room-wall-short', `room.outline[${i}]`, `wall ${i} (corner ${i} to corner ${(i + 1) % n}) is ${round(length)} m long; each wall must be at least ${minWall} m`, {
          wall: i,
          to: (i + 1) % n,
          length: round(length),
          min: minWall,
        }),
      );
    }
  }
  for (let i = 0; i < n; i++) {
    for (let j = i + 2; j < n; j++) {
      if (i === 0 && j === n - 1) continue; // neighbours: their distance is wall n − 1's length
      const d = Math.hypot(outline[j][0] - outline[i][0], outline[j][1] - outline[i][1]);
      if (d < minWall - EPS) {
        out.push(problem('room-corners-close', `room.outline[${j}]`, `corners ${i} and ${j} are ${round(d)} m apart; corners must be at least ${minWall} m apart`, { corner: i, other: j, distance: round(d), min: minWall }));
      }
    }
  }
  if (out.length > 0) return out;
  // Walls meeting anywhere but at their shared corner: O(n²) pairs, n ≤ 64.
  for (let i = 0; i < n; i++) {
    const a = outline[i];
    const b = outline[(i + 1) % n];
    for (let j = i + 1; j < n; j++) {
      const c = outline[j];
      const d = outline[(j + 1) % n];
      const neighbours = j === i + 1 || (i === 0 && j === n - 1);
      let meet: boolean;
      if (neighbours) {
        // Neighbours share a corner; they are wrong only when one folds back along the other.
        const [p, q, r] = j === i + 1 ? [a, b, d] : [c, a, b];
        meet = Math.abs(orient(p, q, r)) <= EPS * Math.hypot(q[0] - p[0], q[1] - p[1]) * Math.hypot(r[0] - q[0], r[1] - q[1]) && (q[0] - p[0]) * (r[0] - q[0]) + (q[1] - p[1]) * (r[1] - q[1]) < 0;
      } else {
        meet = segmentsIntersect(a, b, c, d);
      }
      if (meet) {
        out.push(problem('room-self-intersection', `room.outline[${j}]`, `wall ${i} and wall ${j} cross or touch; the outline must not intersect itself`, { wall: i, other: j }));
      }
    }
  }
  if (out.length === 0 && Math.abs(doubleSignedArea(outline)) < EPS) {
    out.push(problem('room-no-area', 'room.outline', 'the outline encloses no floor', {}));
  }
  return out;
}

/** Every problem of a room, the outline's first (the rest need a sound outline). An empty list: the room is valid. */
export function roomProblems(room: RoomInput): RoomProblem[] {
  const outline = outlineProblems(room.outline);
  if (outline.length > 0) return outline;
  const out: RoomProblem[] = [];
  const corners = room.outline;
  const n = corners.length;
  const orientation: 1 | -1 = doubleSignedArea(corners) > 0 ? 1 : -1;
  const { minHeight, maxHeight } = ROOM_SHAPE_LIMITS;
  const H = room.height;
  if (!(isFiniteNumber(H) && H >= minHeight && H <= maxHeight)) {
    out.push(problem('room-height', 'room.height', `the ceiling height must be between ${minHeight} and ${maxHeight} m (got ${String(H)})`, { value: String(H), min: minHeight, max: maxHeight }));
    return out;
  }
  const wallOk = (w: unknown): w is number => Number.isInteger(w) && (w as number) >= 0 && (w as number) < n;
  const wallLength = (w: number) => Math.hypot(corners[(w + 1) % n][0] - corners[w][0], corners[(w + 1) % n][1] - corners[w][1]);

  const planes: CeilingPlane[] = [flatPlane(H)];
  const slopeOnWall = new Map<number, number>();
  (room.slopes ?? []).forEach((s, i) => {
    const at = `room.slopes[${i}]`;
    if (!wallOk(s.wall)) {
      out.push(problem('room-slope-wall', `${at}.wall`, `slope ${i} stands on wall ${String(s.wall)}, but the room has walls 0 to ${n - 1}`, { slope: i, wall: String(s.wall), last: n - 1 }));
      return;
    }
    const other = slopeOnWall.get(s.wall);
    if (other !== undefined) {
      out.push(problem('room-slope-twice', `${at}.wall`, `slopes ${other} and ${i} both stand on wall ${s.wall}; a wall carries at most one slope`, { slope: i, other, wall: s.wall }));
      return;
    }
    slopeOnWall.set(s.wall, i);
    if (!(isFiniteNumber(s.pitch) && s.pitch > 0 && s.pitch < 90)) {
      out.push(problem('room-slope-pitch', `${at}.pitch`, `slope ${i} has a pitch of ${String(s.pitch)}°; it must lie between 0° and 90°`, { slope: i, value: String(s.pitch) }));
      return;
    }
    if (!(isFiniteNumber(s.kneeHeight) && s.kneeHeight >= 0 && s.kneeHeight <= H + EPS)) {
      out.push(problem('room-slope-knee', `${at}.kneeHeight`, `slope ${i} has a knee height of ${String(s.kneeHeight)} m; it must lie between 0 and the ceiling height ${H} m`, { slope: i, value: String(s.kneeHeight), height: H }));
      return;
    }
    if (s.reflectance !== undefined && !reflectanceOk(s.reflectance)) {
      out.push(problem('room-reflectance', `${at}.reflectance`, `slope ${i}: a reflectance must be a number in [0, 1) or [r, g, b]`, { surface: `slope ${i}` }));
    }
    planes.push(slopePlane(corners[s.wall], corners[(s.wall + 1) % n], orientation, s.kneeHeight, s.pitch));
  });
  if (out.length > 0) return out;
  // The ceiling is concave over the plan (the lowest of planes), so it is lowest at a corner.
  corners.forEach((c, i) => {
    const h = lowestPlaneHeight(planes, c[0], c[1]);
    if (h < -EPS) {
      out.push(problem('room-ceiling-below-floor', `room.outline[${i}]`, `the slopes bring the ceiling ${round(-h)} m below the floor at corner ${i}; lower the pitch or raise the knee`, { corner: i, depth: round(-h) }));
    }
  });
  if (out.length > 0) return out;

  const ceilingAlong = (w: number, u: number): number => {
    const a = corners[w];
    const b = corners[(w + 1) % n];
    const t = u / wallLength(w);
    return lowestPlaneHeight(planes, a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]));
  };
  const openings = room.openings ?? [];
  const placed: { i: number; wall: number; u0: number; u1: number; v0: number; v1: number }[] = [];
  openings.forEach((o, i) => {
    const at = `room.openings[${i}]`;
    if (!wallOk(o.wall)) {
      out.push(problem('room-opening-wall', `${at}.wall`, `opening ${i} is in wall ${String(o.wall)}, but the room has walls 0 to ${n - 1}`, { opening: i, wall: String(o.wall), last: n - 1 }));
      return;
    }
    if (!OPENING_KINDS.includes(o.kind)) {
      out.push(problem('room-opening-kind', `${at}.kind`, `opening ${i} is a ${String(o.kind)}; it must be a door, a window or an opening`, { opening: i, kind: String(o.kind) }));
      return;
    }
    for (const key of ['width', 'height'] as const) {
      if (!(isFiniteNumber(o[key]) && o[key] > 0)) {
        out.push(problem('room-opening-size', `${at}.${key}`, `opening ${i} must have a ${key} above 0 m (got ${String(o[key])})`, { opening: i, dimension: key, value: String(o[key]) }));
        return;
      }
    }
    if (!(isFiniteNumber(o.sill) && o.sill >= 0)) {
      out.push(problem('room-opening-sill', `${at}.sill`, `opening ${i} has a sill of ${String(o.sill)} m; it must be 0 or above`, { opening: i, value: String(o.sill) }));
      return;
    }
    const length = wallLength(o.wall);
    if (!(isFiniteNumber(o.offset) && o.offset >= -EPS && o.offset + o.width <= length + EPS)) {
      out.push(
        problem('room-opening-beyond-wall', `${at}.offset`, `opening ${i} reaches from ${String(o.offset)} to ${round(o.offset + o.width)} m along wall ${o.wall}, which is ${round(length)} m long; it must stay between the wall's ends`, {
          opening: i,
          wall: o.wall,
          offset: String(o.offset),
          end: round(o.offset + o.width),
          length: round(length),
        }),
      );
      return;
    }
    // The wall's top is concave along it: the opening fits under it when both top corners do.
    const top = o.sill + o.height;
    const ceiling = Math.min(ceilingAlong(o.wall, o.offset), ceilingAlong(o.wall, o.offset + o.width));
    if (top > ceiling + EPS) {
      out.push(
        problem('room-opening-above-ceiling', `${at}.height`, `opening ${i} reaches ${round(top)} m up wall ${o.wall}, above its top (${round(ceiling)} m there)`, { opening: i, wall: o.wall, top: round(top), ceiling: round(ceiling) }),
      );
      return;
    }
    for (const p of placed) {
      if (p.wall !== o.wall) continue;
      if (o.offset < p.u1 - EPS && p.u0 < o.offset + o.width - EPS && o.sill < p.v1 - EPS && p.v0 < top - EPS) {
        out.push(problem('room-openings-overlap', at, `openings ${p.i} and ${i} overlap on wall ${o.wall}`, { opening: i, other: p.i, wall: o.wall }));
        return;
      }
    }
    placed.push({ i, wall: o.wall, u0: o.offset, u1: o.offset + o.width, v0: o.sill, v1: top });
  });

  const r = (room.reflectance ?? {}) as Partial<RoomInput['reflectance']>;
  for (const key of ['floor', 'ceiling'] as const) {
    if (!reflectanceOk(r[key])) out.push(problem('room-reflectance', `room.reflectance.${key}`, `the ${key}'s reflectance must be a number in [0, 1) or [r, g, b]`, { surface: key }));
  }
  const walls = r.walls;
  const perWall = Array.isArray(walls) && !(walls.length === 3 && walls.every((v) => typeof v === 'number'));
  if (perWall) {
    const list = walls as readonly RoomReflectance[];
    if (list.length !== n) {
      out.push(problem('room-wall-reflectance-count', 'room.reflectance.walls', `the walls' reflectances list ${list.length} entries for ${n} walls`, { count: list.length, walls: n }));
    } else {
      list.forEach((v, i) => {
        if (!reflectanceOk(v)) out.push(problem('room-reflectance', `room.reflectance.walls[${i}]`, `wall ${i}: a reflectance must be a number in [0, 1) or [r, g, b]`, { surface: `wall ${i}` }));
      });
    }
  } else if (!reflectanceOk(walls)) {
    out.push(problem('room-reflectance', 'room.reflectance.walls', "the walls' reflectance must be a number in [0, 1), [r, g, b], or one of these per wall", { surface: 'walls' }));
  }
  return out;
}
