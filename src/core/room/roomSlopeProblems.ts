/** The slopes' rules (issue 29): each on its own wall, a pitch in (0°, 90°), a knee under the ceiling; and no ceiling below the floor. */
import type { RoomSlope } from './roomInput';
import { flatPlane, lowestPlaneHeight, slopePlane, type CeilingPlane } from './ceilingPlanes';
import { EPS, isFiniteNumber, problem, reflectanceOk, round, wallOk, type RoomFrame, type RoomProblem } from './roomProblem';

/** The slopes' problems (each slope's first), and the ceiling's planes (the flat ceiling, then one per sound slope). */
export function slopeProblems(slopes: readonly RoomSlope[], frame: RoomFrame): { problems: RoomProblem[]; planes: CeilingPlane[] } {
  const { corners, n, orientation } = frame;
  const problems: RoomProblem[] = [];
  const planes: CeilingPlane[] = [flatPlane(frame.H)];
  const slopeOnWall = new Map<number, number>();
  slopes.forEach((s, i) => {
    const found = slopeProblem(s, i, frame, slopeOnWall);
    // The planes are read only when every slope is sound: a slope with a problem adds none.
    if (found) problems.push(found);
    else planes.push(slopePlane(corners[s.wall], corners[(s.wall + 1) % n], orientation, s.kneeHeight, s.pitch));
  });
  return { problems, planes };
}

/** Slope i's first problem (null: none); a slope on a free wall claims it in `slopeOnWall`. */
function slopeProblem(s: RoomSlope, i: number, frame: RoomFrame, slopeOnWall: Map<number, number>): RoomProblem | null {
  const { n, H } = frame;
  const at = `room.slopes[${i}]`;
  if (!wallOk(frame, s.wall)) {
    return problem('room-slope-wall', `${at}.wall`, `slope ${i} stands on wall ${String(s.wall)}, but the room has walls 0 to ${n - 1}`, { slope: i, wall: String(s.wall), last: n - 1 });
  }
  const other = slopeOnWall.get(s.wall);
  if (other !== undefined) {
    return problem('room-slope-twice', `${at}.wall`, `slopes ${other} and ${i} both stand on wall ${s.wall}; a wall carries at most one slope`, { slope: i, other, wall: s.wall });
  }
  slopeOnWall.set(s.wall, i);
  if (!(isFiniteNumber(s.pitch) && s.pitch > 0 && s.pitch < 90)) {
    return problem('room-slope-pitch', `${at}.pitch`, `slope ${i} has a pitch of ${String(s.pitch)}°; it must lie between 0° and 90°`, { slope: i, value: String(s.pitch) });
  }
  if (!(isFiniteNumber(s.kneeHeight) && s.kneeHeight >= 0 && s.kneeHeight <= H + EPS)) {
    return problem('room-slope-knee', `${at}.kneeHeight`, `slope ${i} has a knee height of ${String(s.kneeHeight)} m; it must lie between 0 and the ceiling height ${H} m`, { slope: i, value: String(s.kneeHeight), height: H });
  }
  if (s.reflectance !== undefined && !reflectanceOk(s.reflectance)) {
    return problem('room-reflectance', `${at}.reflectance`, `slope ${i}: a reflectance must be a number in [0, 1) or [r, g, b]`, { surface: `slope ${i}` });
  }
  return null;
}

/** The ceiling is concave over the plan (the lowest of planes), so it is lowest at a corner: one check per corner. */
export function ceilingBelowFloorProblems({ corners }: RoomFrame, planes: readonly CeilingPlane[]): RoomProblem[] {
  const out: RoomProblem[] = [];
  corners.forEach((c, i) => {
    const h = lowestPlaneHeight(planes, c[0], c[1]);
    if (h < -EPS) {
      out.push(problem('room-ceiling-below-floor', `room.outline[${i}]`, `the slopes bring the ceiling ${round(-h)} m below the floor at corner ${i}; lower the pitch or raise the knee`, { corner: i, depth: round(-h) }));
    }
  });
  return out;
}
