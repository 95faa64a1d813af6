/**
 * The rules a room of any shape must keep (issue 29), as problems a UI can word in its own
 * language: a stable `code`, the values in `params` (indices count from 0, as in the file; lengths
 * in metres) and an English `message` that names the problem and where (wall i, corner i, slope i,
 * opening i), like the configuration's problems (src/core/model/validate.ts).
 */
import { doubleSignedArea, orient, segmentsIntersect, type PlanPoint } from './planPolygon';
import { ROOM_SHAPE_LIMITS, type RoomInput } from './roomInput';
import { openingProblems } from './roomOpeningProblems';
import { EPS, isFiniteNumber, problem, round, type RoomFrame, type RoomProblem } from './roomProblem';
import { reflectanceProblems } from './roomReflectanceProblems';
import { ceilingBelowFloorProblems, slopeProblems } from './roomSlopeProblems';

export type { RoomProblem } from './roomProblem';

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

/**
 * Every problem of a room, in the order a reader fixes them: the outline first (the rest need a
 * sound outline), then the height, the slopes, a ceiling below the floor, and last the openings and
 * the finishes together. An empty list: the room is valid.
 */
export function roomProblems(room: RoomInput): RoomProblem[] {
  const outline = outlineProblems(room.outline);
  if (outline.length > 0) return outline;
  const corners = room.outline;
  const { minHeight, maxHeight } = ROOM_SHAPE_LIMITS;
  const H = room.height;
  if (!(isFiniteNumber(H) && H >= minHeight && H <= maxHeight)) {
    return [problem('room-height', 'room.height', `the ceiling height must be between ${minHeight} and ${maxHeight} m (got ${String(H)})`, { value: String(H), min: minHeight, max: maxHeight })];
  }
  const frame: RoomFrame = { corners, n: corners.length, orientation: doubleSignedArea(corners) > 0 ? 1 : -1, H };
  const slopes = slopeProblems(room.slopes ?? [], frame);
  if (slopes.problems.length > 0) return slopes.problems;
  const below = ceilingBelowFloorProblems(frame, slopes.planes);
  if (below.length > 0) return below;
  return [...openingProblems(room.openings ?? [], frame, slopes.planes), ...reflectanceProblems(room.reflectance, frame.n)];
}
