/**
 * Cameras in a room of any shape (issue 29): the eye camera stands inside the outline, at least a
 * margin from every wall and under the ceiling above it (never inside a wall of an L), looks at
 * where the light is among the spots it sees in plan, and its orbit is clamped to the same region.
 * The scoring is frameTheLight's (docs/viewer.md, "Cameras that frame the light"); what differs is
 * where a person may stand and what the room's own corners hide.
 */
import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import { ceilingHeightAt, pointInsideRoom } from '../../core/room/ceilingHeightAt';
import type { Room as ShapedRoom } from '../../core/room/normaliseRoom';
import { distanceToSegment, segmentsCrossProperly, type PlanPoint } from '../../core/room/planPolygon';
import { roomSurfaces } from '../../core/room/roomSurfaces';
import { pointInPolygon } from '../../core/room/planPolygon';
import type { BakeScene } from '../bake/bakeScene';
import { LUMINANCE_WEIGHTS } from '../bake/bakedMaps';
import { directAtPoint } from '../bake/directAtPoint';
import { scenePointSources } from '../bake/scenePointSources';
import { encloseShapedRoom } from '../bake/shapedRoom/encloseShapedRoom';
import type { CameraPose } from './cameraPresets';

/** Does a person at plan point p keep `margin` from every wall (and stand inside the outline)? */
export function clearOfWalls(shape: ShapedRoom, p: PlanPoint, margin: number): boolean {
  if (!pointInPolygon(p, shape.corners, 0)) return false;
  return shape.walls.every((w) => distanceToSegment(p, w.start, w.end) >= margin - 1e-9);
}

/** Is plan point b seen from plan point a: no wall crosses the segment between them (the room's walls are full height). */
export function seesInPlan(shape: ShapedRoom, a: PlanPoint, b: PlanPoint): boolean {
  return shape.walls.every((w) => !segmentsCrossProperly(a, b, w.start, w.end));
}

/**
 * A point kept inside the room shrunk by `margin` (the eye camera's orbit limit): inside the
 * outline, `margin` from every wall, between `margin` above the floor and `margin` under the
 * ceiling over it. A point outside is moved to the nearest wall point, then `margin` along that
 * wall's inward normal (and, in a corner narrower than that, to the point of the region nearest
 * the room's centroid of corners along the way).
 */
export function clampInsideShape(p: Vec3, shape: ShapedRoom, margin: number): Vec3 {
  let q: PlanPoint = [p[0], p[2]];
  if (!clearOfWalls(shape, q, margin)) {
    let best: PlanPoint | null = null;
    let bestD = Infinity;
    for (const w of shape.walls) {
      const [dx, dz] = [w.end[0] - w.start[0], w.end[1] - w.start[1]];
      const t = Math.max(0, Math.min(1, ((q[0] - w.start[0]) * dx + (q[1] - w.start[1]) * dz) / (dx * dx + dz * dz)));
      const candidate: PlanPoint = [w.start[0] + t * dx + margin * w.inward[0], w.start[1] + t * dz + margin * w.inward[1]];
      const d = Math.hypot(candidate[0] - q[0], candidate[1] - q[1]);
      if (d < bestD && clearOfWalls(shape, candidate, margin)) [best, bestD] = [candidate, d];
    }
    if (!best) {
      // Narrow corners: walk toward the centroid of the corners until clear (or give the centroid).
      const c: PlanPoint = [shape.corners.reduce((s, k) => s + k[0], 0) / shape.corners.length, shape.corners.reduce((s, k) => s + k[1], 0) / shape.corners.length];
      best = c;
      for (let i = 1; i <= 32; i++) {
        const f = i / 32;
        const r: PlanPoint = [q[0] + f * (c[0] - q[0]), q[1] + f * (c[1] - q[1])];
        if (clearOfWalls(shape, r, margin)) {
          best = r;
          break;
        }
      }
    }
    q = best;
  }
  const top = ceilingHeightAt(shape, q[0], q[1]);
  const m = Math.min(margin, top / 2);
  return [q[0], Math.min(top - m, Math.max(m, p[1])), q[1]];
}

interface Patch {
  p: Vec3;
  n: Vec3;
  area: number;
  luminance: number;
}

/** The room's surfaces as patches of about `cell` metres (centres inside their polygon, outside openings) with their direct luminance ρ·E/π (unshadowed: a framing needs where the light falls). */
function shapedPatches(scene: BakeScene, shape: ShapedRoom, cell: number): Patch[] {
  // The lamps as the baker places them, in its enclosure's coordinates (bake = world + offset).
  const enclosed = encloseShapedRoom(scene);
  const offset = enclosed.room.enclosure!.offset;
  const lamps = scenePointSources(enclosed, { sourceSpacing: 1, maxSourcesPerAxis: 1, nearField: 'point' });
  const out: Patch[] = [];
  for (const s of roomSurfaces(shape)) {
    const rhoY = LUMINANCE_WEIGHTS[0] * s.reflectance[0] + LUMINANCE_WEIGHTS[1] * s.reflectance[1] + LUMINANCE_WEIGHTS[2] * s.reflectance[2];
    const all = s.polygons2d.flat();
    const [u0, u1] = [Math.min(...all.map((p) => p[0])), Math.max(...all.map((p) => p[0]))];
    const [v0, v1] = [Math.min(...all.map((p) => p[1])), Math.max(...all.map((p) => p[1]))];
    const nu = Math.max(1, Math.round((u1 - u0) / cell));
    const nv = Math.max(1, Math.round((v1 - v0) / cell));
    const area = ((u1 - u0) / nu) * ((v1 - v0) / nv);
    for (let j = 0; j < nv; j++) {
      for (let i = 0; i < nu; i++) {
        const q: PlanPoint = [u0 + ((i + 0.5) * (u1 - u0)) / nu, v0 + ((j + 0.5) * (v1 - v0)) / nv];
        if (!s.polygons2d.some((poly) => pointInPolygon(q, poly)) || s.openings.some((o) => pointInPolygon(q, o.polygon2d))) continue;
        const p: Vec3 = [0, 1, 2].map((k) => s.frame.origin[k] + q[0] * s.frame.u[k] + q[1] * s.frame.v[k]) as Vec3;
        const n: Vec3 = [...s.inward];
        const e = directAtPoint(lamps, [p[0] + offset[0], p[1] + offset[1], p[2] + offset[2]], n);
        out.push({ p, n, area, luminance: (rhoY * (LUMINANCE_WEIGHTS[0] * e[0] + LUMINANCE_WEIGHTS[1] * e[1] + LUMINANCE_WEIGHTS[2] * e[2])) / Math.PI });
      }
    }
  }
  return out;
}

/**
 * The eye camera of a shaped room: standing points a quarter, half and three quarters along each
 * wall, `margin` inside it (kept only where clear of every wall), at eye height under the ceiling
 * there, looking within ±70° of straight into the room at four downward pitches; each view scores
 * the light it sees (patches in the frame and in sight in plan), the brightest pool and the
 * luminaires in view, as frameTheLight does in a box. Null when no lamp emits.
 */
export function frameShapedRoom(scene: BakeScene, shape: ShapedRoom, aspect: number, eye: { margin: number; height: (ceiling: number) => number; fov: number }): CameraPose | null {
  const xs = shape.corners.map((c) => c[0]);
  const zs = shape.corners.map((c) => c[1]);
  const cell = Math.max(0.1, Math.max(Math.max(...xs) - Math.min(...xs), Math.max(...zs) - Math.min(...zs), shape.height) / 20);
  const patches = shapedPatches(scene, shape, cell).filter((q) => q.luminance > 0);
  const lamps = scene.luminaires.map((l) => l.position);
  if (patches.length === 0) return null;
  let pool = patches[0];
  for (const q of patches) if (q.n[1] >= 0 && q.luminance > pool.luminance) pool = q;
  const tanV = Math.tan(((eye.fov / 2) * Math.PI) / 180);
  const tanH = tanV * (aspect > 0 ? aspect : 1.6);
  let best: { score: number; pose: CameraPose } | null = null;
  const candidates: { c: Vec3; f: Vec3; flux: number; pool: boolean; lamps: number }[] = [];
  for (const w of shape.walls) {
    for (const t of [0.25, 0.5, 0.75]) {
      const plan: PlanPoint = [w.start[0] + t * (w.end[0] - w.start[0]) + eye.margin * w.inward[0], w.start[1] + t * (w.end[1] - w.start[1]) + eye.margin * w.inward[1]];
      if (!clearOfWalls(shape, plan, eye.margin * 0.999)) continue;
      const c: Vec3 = [plan[0], eye.height(ceilingHeightAt(shape, plan[0], plan[1])), plan[1]];
      if (!pointInsideRoom(shape, c)) continue;
      const inward = Math.atan2(w.inward[0], -w.inward[1]);
      for (let dy = -70; dy <= 70; dy += 10) {
        const yaw = inward + (dy * Math.PI) / 180;
        for (const pitchDeg of [-5, -15, -25, -35]) {
          const pitch = (pitchDeg * Math.PI) / 180;
          const f: Vec3 = [Math.sin(yaw) * Math.cos(pitch), Math.sin(pitch), -Math.cos(yaw) * Math.cos(pitch)];
          const r: Vec3 = [Math.cos(yaw), 0, Math.sin(yaw)];
          const u: Vec3 = [r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]];
          const inFrame = (p: Vec3, k: number): boolean => {
            const d: Vec3 = [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
            const z = d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
            if (!(z > 0.05)) return false;
            const x = (d[0] * r[0] + d[1] * r[1] + d[2] * r[2]) / z;
            const y = (d[0] * u[0] + d[1] * u[1] + d[2] * u[2]) / z;
            return Math.abs(x) <= k * tanH && Math.abs(y) <= k * tanV && seesInPlan(shape, plan, [p[0], p[2]]);
          };
          let flux = 0;
          for (const q of patches) {
            if (!inFrame(q.p, 1)) continue;
            const d: Vec3 = [c[0] - q.p[0], c[1] - q.p[1], c[2] - q.p[2]];
            const d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            const cos = (q.n[0] * d[0] + q.n[1] * d[1] + q.n[2] * d[2]) / Math.sqrt(d2);
            if (cos > 0) flux += (q.luminance * q.area * cos) / d2;
          }
          candidates.push({ c, f, flux, pool: inFrame(pool.p, 0.7), lamps: lamps.filter((p) => inFrame(p, 0.75)).length });
        }
      }
    }
  }
  const maxFlux = Math.max(0, ...candidates.map((k) => k.flux));
  if (!(maxFlux > 0)) return null;
  for (const k of candidates) {
    const score = k.flux / maxFlux + (k.pool ? 0.5 : 0) + (k.lamps > 0 ? 0.5 : 0) + (0.5 * k.lamps) / Math.max(1, lamps.length);
    if (!best || score > best.score + 1e-12) {
      // The orbit target: 1.5 m along the view, kept inside the room.
      const target = clampInsideShape([k.c[0] + 1.5 * k.f[0], k.c[1] + 1.5 * k.f[1], k.c[2] + 1.5 * k.f[2]], shape, 0.05);
      best = { score, pose: { position: k.c, target, fov: eye.fov } };
    }
  }
  return best ? best.pose : null;
}

/** The plain eye view of a shaped room without light: from the middle of its longest wall, `margin` inside, toward the room's centroid of corners. */
export function eyeAcrossShapedRoom(shape: ShapedRoom, eye: { margin: number; height: (ceiling: number) => number; fov: number }): CameraPose {
  const wall = [...shape.walls].sort((a, b) => b.length - a.length)[0];
  const at = clampInsideShape([(wall.start[0] + wall.end[0]) / 2 + eye.margin * wall.inward[0], 0, (wall.start[1] + wall.end[1]) / 2 + eye.margin * wall.inward[1]], shape, eye.margin);
  const h = eye.height(ceilingHeightAt(shape, at[0], at[2]));
  const c: PlanPoint = [shape.corners.reduce((s, k) => s + k[0], 0) / shape.corners.length, shape.corners.reduce((s, k) => s + k[1], 0) / shape.corners.length];
  const target = clampInsideShape([c[0], h * 0.6, c[1]], shape, 0.05);
  return { position: [at[0], h, at[2]], target, fov: eye.fov };
}
