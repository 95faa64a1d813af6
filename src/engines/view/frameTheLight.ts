import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import { reflectanceRgb, type BakeScene } from '../bake/bakeScene';
import { LUMINANCE_WEIGHTS } from '../bake/bakedMaps';
import { directAtPoint } from '../bake/directAtPoint';
import { scenePointSources } from '../bake/scenePointSources';
import type { CameraPose } from './cameraPresets';
import { clampInsideShape, eyeAcrossShapedRoom, frameShapedRoom } from './shapedRoomCamera';

type Room = BakeScene['room'];

/** Eye height of a standing adult, metres (the usual 1.6 m of architectural views). */
export const EYE_HEIGHT = 1.6;
/** How far the eye camera stands inside the walls, ceiling and floor at least, metres (and the orbit limit's margin). */
export const EYE_MARGIN = 0.3;
/** Vertical field of the eye view on a landscape screen, degrees (a portrait one widens it to keep 60° across). */
export const EYE_FOV = 60;

/** One patch of a room surface for the framing: centre, inward normal, area, luminance (cd/m², photometric). */
interface Patch {
  p: Vec3;
  n: Vec3;
  area: number;
  luminance: number;
}

/** What the eye view was chosen for: the pose, the main pool's centre, the luminaires it shows. */
export interface LightFraming {
  pose: CameraPose;
  /** Centre of the brightest patch of floor or wall (the main pool), or null in a dark room. */
  pool: Vec3 | null;
  /** Indices (into the scene's luminaires) of the emitting luminaires inside the view. */
  luminairesInView: number[];
}

/** Eye height in a room of height H: 1.6 m, lowered to stay EYE_MARGIN below a low ceiling. */
export function eyeHeight(H: number): number {
  return Math.max(Math.min(EYE_HEIGHT, H - EYE_MARGIN), Math.min(H / 2, EYE_MARGIN));
}

/** The margin the eye keeps from the walls: EYE_MARGIN, less in a room too narrow for it. */
function wallMargin(room: Pick<Room, 'width' | 'depth'>): number {
  return Math.min(EYE_MARGIN, room.width / 4, room.depth / 4);
}

/** A point clamped into the room shrunk by `margin` on every side (the eye camera's orbit limit; a shaped room: clampInsideShape). */
export function clampInsideRoom(p: Vec3, room: Pick<Room, 'width' | 'height' | 'depth' | 'shape'>, margin = EYE_MARGIN): Vec3 {
  if (room.shape) return clampInsideShape(p, room.shape, margin);
  const size: Vec3 = [room.width, room.height, room.depth];
  return p.map((v, a) => {
    const m = Math.min(margin, size[a] / 2);
    return Math.min(size[a] - m, Math.max(m, v));
  }) as Vec3;
}

/** The eye view's vertical field for a view of aspect width / height: EYE_FOV, widened on portrait screens so 60° stay across. */
export function eyeFov(aspect: number): number {
  if (!(aspect > 0) || aspect >= 1) return EYE_FOV;
  const half = Math.atan(Math.tan(((EYE_FOV / 2) * Math.PI) / 180) / aspect);
  return Math.min(100, (2 * half * 180) / Math.PI);
}

/** The eye view without light to frame: from the middle of the south wall, EYE_MARGIN inside it, across the room (a shaped room: from its longest wall). */
export function eyeAcrossTheRoom(room: Pick<Room, 'width' | 'height' | 'depth' | 'shape'>, aspect = 1.6): CameraPose {
  if (room.shape) return eyeAcrossShapedRoom(room.shape, { margin: EYE_MARGIN, height: eyeHeight, fov: eyeFov(aspect) });
  const { width: W, height: H, depth: D } = room;
  const h = eyeHeight(H);
  return { position: [W / 2, h, D - Math.min(EYE_MARGIN, D / 4)], target: [W / 2, h * 0.6, D * 0.3], fov: eyeFov(aspect) };
}

/**
 * The room's six surfaces as patches of about `cell` metres with their direct luminance L = ρ·E/π
 * (E from the same point sources as the baker, each luminaire as one source at its photometric
 * centre: a framing needs where the light falls, not its last percent).
 */
function litPatches(scene: BakeScene, cell: number): Patch[] {
  const { width: W, height: H, depth: D } = scene.room;
  const lamps = scenePointSources(scene, { sourceSpacing: 1, maxSourcesPerAxis: 1, nearField: 'point' });
  const rho = reflectanceRgb(scene.room);
  const Y = (c: Vec3) => LUMINANCE_WEIGHTS[0] * c[0] + LUMINANCE_WEIGHTS[1] * c[1] + LUMINANCE_WEIGHTS[2] * c[2];
  // Each surface: origin, u and v axes (lengths), inward normal.
  const faces: { name: keyof typeof rho; o: Vec3; u: Vec3; v: Vec3; n: Vec3 }[] = [
    { name: 'floor', o: [0, 0, 0], u: [W, 0, 0], v: [0, 0, D], n: [0, 1, 0] },
    { name: 'ceiling', o: [0, H, 0], u: [W, 0, 0], v: [0, 0, D], n: [0, -1, 0] },
    { name: 'north', o: [0, 0, 0], u: [W, 0, 0], v: [0, H, 0], n: [0, 0, 1] },
    { name: 'south', o: [0, 0, D], u: [W, 0, 0], v: [0, H, 0], n: [0, 0, -1] },
    { name: 'west', o: [0, 0, 0], u: [0, 0, D], v: [0, H, 0], n: [1, 0, 0] },
    { name: 'east', o: [W, 0, 0], u: [0, 0, D], v: [0, H, 0], n: [-1, 0, 0] },
  ];
  const patches: Patch[] = [];
  for (const f of faces) {
    const lu = Math.hypot(...f.u);
    const lv = Math.hypot(...f.v);
    const nu = Math.max(1, Math.round(lu / cell));
    const nv = Math.max(1, Math.round(lv / cell));
    const rhoY = Y(rho[f.name]);
    for (let j = 0; j < nv; j++) {
      for (let i = 0; i < nu; i++) {
        const a = (i + 0.5) / nu;
        const b = (j + 0.5) / nv;
        const p: Vec3 = [0, 1, 2].map((k) => f.o[k] + a * f.u[k] + b * f.v[k]) as Vec3;
        const luminance = (rhoY * Y(directAtPoint(lamps, p, f.n))) / Math.PI;
        patches.push({ p, n: f.n, area: (lu / nu) * (lv / nv), luminance });
      }
    }
  }
  return patches;
}

const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/** A view's axes (forward, right, up) for a yaw (0 = looking north, −z; radians, clockwise seen from above) and a pitch (negative: down). */
function viewAxes(yaw: number, pitch: number): { f: Vec3; r: Vec3; u: Vec3 } {
  const f: Vec3 = [Math.sin(yaw) * Math.cos(pitch), Math.sin(pitch), -Math.cos(yaw) * Math.cos(pitch)];
  const r: Vec3 = [Math.cos(yaw), 0, Math.sin(yaw)];
  const u: Vec3 = [r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]];
  return { f, r, u };
}

/** Where a point lands in a view: the tangent-plane coordinates (x right, y up) and the depth; null behind the camera. */
function project(c: Vec3, axes: { f: Vec3; r: Vec3; u: Vec3 }, p: Vec3): { x: number; y: number; z: number } | null {
  const d = sub(p, c);
  const z = dot(d, axes.f);
  if (!(z > 0.05)) return null;
  return { x: dot(d, axes.r) / z, y: dot(d, axes.u) / z, z };
}

/**
 * The eye camera that frames the light (issue 26, "cameras that frame the light"): a person
 * standing at eye height, EYE_MARGIN inside a wall, looking across the room at where the light is.
 * Candidates: 16 standing points round the room (its corners and the quarter, half and three-quarter
 * points of each wall) × looking directions every 10° within ±70° of straight into the room × four
 * downward pitches (5°…35°). Each view scores
 *
 *   Φ_view / max Φ_view + ½·[main pool in view] + ½·[a luminaire in view] + ½·(luminaires in view / luminaires)
 *
 * where Φ_view = Σ L·A·cos θ / d² over the surface patches inside the view is the illuminance the
 * visible surfaces give at the lens (what a camera's exposure meter reads: the light the picture
 * holds), the main pool is the brightest patch of floor or wall, and a luminaire or the pool counts
 * when it lies inside the central 75 % (a luminaire: its housing reaches beyond its photometric centre) or 70 % (the pool) of the frame. The best score wins; ties keep the first
 * candidate, so the result is deterministic. A scene without emitting luminaires gets the plain
 * view across the room from the middle of the south wall. A room too small or low to show the pool and
 * a luminaire in one view at that field gets a wider lens (+15°, then +30°).
 */
export function frameTheLight(scene: BakeScene, aspect = 1.6): LightFraming {
  // A room of any shape: a person stands inside its outline, clear of every wall (shapedRoomCamera.ts).
  const shape = scene.room.shape;
  if (shape) {
    const eye = { margin: EYE_MARGIN, height: eyeHeight, fov: eyeFov(aspect) };
    return { pose: frameShapedRoom(scene, shape, aspect, eye) ?? eyeAcrossShapedRoom(shape, eye), pool: null, luminairesInView: [] };
  }
  const room = scene.room;
  const { width: W, height: H, depth: D } = room;
  const cell = Math.max(0.1, Math.max(W, H, D) / 20);
  const patches = litPatches(scene, cell);
  const emitting = scenePointSources(scene, { sourceSpacing: 1, maxSourcesPerAxis: 1, nearField: 'point' }).map((l) => l.luminaire);
  const lampPositions = emitting.map((i) => clampInsideRoom(scene.luminaires[i].position, room, 0) as Vec3);
  let pool: Patch | null = null;
  for (const q of patches) if (q.n[1] >= 0 && q.luminance > 0 && (!pool || q.luminance > pool.luminance)) pool = q;
  const views: ViewSet = { stands: standingPoints(room), patches, emitting, lampPositions, pool, aspect };

  // A room too small (or low) to show the pool and a luminaire in one 60° view gets a wider lens, as a photographer would.
  const base = eyeFov(aspect);
  let fov = base;
  let candidates = candidateViews(views, fov);
  for (const wider of [base + 15, base + 30]) {
    if (candidates.some((k) => k.pool && k.lamps.length > 0)) break;
    const next = candidateViews(views, Math.min(100, wider));
    if (next.some((k) => k.pool && k.lamps.length > 0)) {
      fov = Math.min(100, wider);
      candidates = next;
      break;
    }
  }
  const best = bestCandidate(candidates, emitting.length);
  if (!best) return { pose: eyeAcrossTheRoom(room, aspect), pool: null, luminairesInView: [] };
  return { pose: { position: [...best.c] as Vec3, target: orbitTarget(best, [W, H, D]), fov }, pool: pool ? pool.p : null, luminairesInView: best.lamps };
}

/** A standing point of the eye and the yaw straight into the room from it. */
interface Stand {
  c: Vec3;
  inward: number;
}

/** One candidate view and what it shows: the flux at the lens, the pool in frame, the luminaires in frame. */
interface Candidate {
  c: Vec3;
  yaw: number;
  pitch: number;
  flux: number;
  pool: boolean;
  lamps: number[];
}

/** What every candidate view is judged on. */
interface ViewSet {
  stands: Stand[];
  patches: Patch[];
  emitting: number[];
  lampPositions: Vec3[];
  pool: Patch | null;
  aspect: number;
}

/** Standing points: corners and 1/4, 1/2, 3/4 of each wall at eye height, each with the direction straight into the room. */
function standingPoints(room: Room): Stand[] {
  const { width: W, height: H, depth: D } = room;
  const m = wallMargin(room);
  const h = eyeHeight(H);
  const stands: Stand[] = [];
  const xs = [m, W / 4, W / 2, (3 * W) / 4, W - m];
  const zs = [m, D / 4, D / 2, (3 * D) / 4, D - m];
  const yawOf = (dx: number, dz: number) => Math.atan2(dx, -dz);
  for (const x of xs) {
    stands.push({ c: [x, h, D - m], inward: x === m ? yawOf(1, -1) : x === W - m ? yawOf(-1, -1) : yawOf(0, -1) });
    stands.push({ c: [x, h, m], inward: x === m ? yawOf(1, 1) : x === W - m ? yawOf(-1, 1) : yawOf(0, 1) });
  }
  for (const z of zs.slice(1, -1)) {
    stands.push({ c: [m, h, z], inward: yawOf(1, 0) });
    stands.push({ c: [W - m, h, z], inward: yawOf(-1, 0) });
  }
  return stands;
}

/** Every standing point × looking direction (±70° every 10°) × pitch (5°…35° down) at a vertical field of `fov` degrees. */
function candidateViews({ stands, patches, emitting, lampPositions, pool, aspect }: ViewSet, fov: number): Candidate[] {
  const tanV = Math.tan(((fov / 2) * Math.PI) / 180);
  const tanH = tanV * (aspect > 0 ? aspect : 1.6);
  const inFrame = (v: { x: number; y: number } | null, k: number) => v !== null && Math.abs(v.x) <= k * tanH && Math.abs(v.y) <= k * tanV;
  const candidates: Candidate[] = [];
  for (const { c, inward } of stands) {
    for (let dy = -70; dy <= 70; dy += 10) {
      const yaw = inward + (dy * Math.PI) / 180;
      for (const pitchDeg of [-5, -15, -25, -35]) {
        const pitch = (pitchDeg * Math.PI) / 180;
        const axes = viewAxes(yaw, pitch);
        let flux = 0;
        for (const q of patches) {
          if (!(q.luminance > 0)) continue;
          const v = project(c, axes, q.p);
          if (!inFrame(v, 1)) continue;
          const d = sub(c, q.p);
          const d2 = dot(d, d);
          const cos = dot(q.n, d) / Math.sqrt(d2);
          if (cos > 0) flux += (q.luminance * q.area * cos) / d2;
        }
        const lamps = emitting.filter((_, k) => inFrame(project(c, axes, lampPositions[k]), 0.75));
        candidates.push({ c, yaw, pitch, flux, pool: pool !== null && inFrame(project(c, axes, pool.p), 0.7), lamps });
      }
    }
  }
  return candidates;
}

/** The highest score (see frameTheLight); ties keep the first. Null when nothing lit is in any view or no luminaire emits. */
function bestCandidate(candidates: Candidate[], emittingCount: number): Candidate | null {
  const maxFlux = Math.max(...candidates.map((k) => k.flux));
  if (!(maxFlux > 0) || emittingCount === 0) return null;
  let best = candidates[0];
  let bestScore = -Infinity;
  for (const k of candidates) {
    const score = k.flux / maxFlux + (k.pool ? 0.5 : 0) + (k.lamps.length > 0 ? 0.5 : 0) + (0.5 * k.lamps.length) / emittingCount;
    if (score > bestScore + 1e-12) {
      bestScore = score;
      best = k;
    }
  }
  return best;
}

/** The orbit target: along the view, half way to where it meets the room's surfaces (the camera turns about a point in the room). */
function orbitTarget(best: Candidate, size: Vec3): Vec3 {
  const { f } = viewAxes(best.yaw, best.pitch);
  let reach = Infinity;
  for (let a = 0; a < 3; a++) {
    if (f[a] > 1e-9) reach = Math.min(reach, (size[a] - best.c[a]) / f[a]);
    else if (f[a] < -1e-9) reach = Math.min(reach, -best.c[a] / f[a]);
  }
  const t = Math.max(0.5, reach / 2);
  return [best.c[0] + f[0] * t, best.c[1] + f[1] * t, best.c[2] + f[2] * t];
}
