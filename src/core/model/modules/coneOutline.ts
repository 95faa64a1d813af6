/**
 * Where a light cone meets the room (docs/aiming.md): rays on a cone of half angle α around an
 * axis, from an apex inside the room, each traced to the first room surface it reaches (floor,
 * walls or ceiling of the axis-aligned box [0, W] × [0, H] × [0, D]). On the floor alone the hits
 * trace the conic section: an ellipse while the whole cone points below the horizon
 * (tilt + α < 90°), a parabola or hyperbola beyond; the walls cut it where it goes there.
 * The planner draws the hits in plan (a footprint clipped to the room), the spotlight view
 * draws them in 3D as the beam and field outlines.
 */
import type { Vec3 } from '../lightingScene/lightingScene';

export interface RoomBox {
  readonly width: number;
  readonly depth: number;
  readonly height: number;
}

/** A hit of one cone ray: the point, and which surface it lies on. */
export interface ConeHit {
  readonly point: Vec3;
  readonly surface: 'floor' | 'ceiling' | 'north' | 'south' | 'west' | 'east';
}

const DEG = Math.PI / 180;

function normalise(v: Vec3): Vec3 {
  const l = Math.hypot(v[0], v[1], v[2]);
  return [v[0] / l, v[1] / l, v[2] / l];
}

function cross(a: Vec3, b: Vec3): Vec3 {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

/** First surface of the room box a ray from `p` (inside) along `d` reaches; null if p is outside or d is zero. */
export function traceToRoom(p: Vec3, d: Vec3, room: RoomBox): ConeHit | null {
  const max: Vec3 = [room.width, room.height, room.depth];
  const names: [ConeHit['surface'], ConeHit['surface']][] = [
    ['west', 'east'],
    ['floor', 'ceiling'],
    ['north', 'south'],
  ];
  let best = Infinity;
  let surface: ConeHit['surface'] | null = null;
  let axisOf = -1;
  for (let i = 0; i < 3; i++) {
    if (Math.abs(d[i]) < 1e-12) continue;
    const t = ((d[i] > 0 ? max[i] : 0) - p[i]) / d[i];
    if (t >= 0 && t < best) {
      best = t;
      surface = names[i][d[i] > 0 ? 1 : 0];
      axisOf = i;
    }
  }
  if (surface === null || !Number.isFinite(best)) return null;
  const point: Vec3 = [p[0] + best * d[0], p[1] + best * d[1], p[2] + best * d[2]];
  // Pin the coordinate of the surface hit exactly (no float drift off the wall).
  point[axisOf] = d[axisOf] > 0 ? max[axisOf] : 0;
  return { point, surface };
}

/**
 * `rays` hits (≥ 3) of the cone of half angle `halfAngleDeg` around `axis` from `apex`, in order
 * around the axis (starting from the side of the axis' horizontal direction, counterclockwise seen
 * along the axis). A half angle of 0 gives the axis' hit, repeated.
 */
export function coneRoomOutline(apex: Vec3, axis: Vec3, halfAngleDeg: number, room: RoomBox, rays = 96): ConeHit[] {
  const a = normalise(axis);
  // A vector across the axis: horizontal when the axis is not vertical.
  const ref: Vec3 = Math.abs(a[1]) > 0.999 ? [1, 0, 0] : [0, 1, 0];
  const u = normalise(cross(a, ref));
  const v = cross(a, u);
  const c = Math.cos(halfAngleDeg * DEG);
  const s = Math.sin(halfAngleDeg * DEG);
  const out: ConeHit[] = [];
  for (let k = 0; k < rays; k++) {
    const phi = (2 * Math.PI * k) / rays;
    const d: Vec3 = [0, 1, 2].map((i) => c * a[i] + s * (Math.cos(phi) * u[i] + Math.sin(phi) * v[i])) as unknown as Vec3;
    const hit = traceToRoom(apex, d, room);
    if (hit) out.push(hit);
  }
  return out;
}
