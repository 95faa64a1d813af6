/**
 * The flux that leaves a baked room through its windows (issue 30's flux balance: the light entering
 * through the windows minus what leaves again equals what the surfaces absorb), measured on the
 * windows themselves and so independent of the baker's own bookkeeping (the flux statistics, the
 * tail): the glass is not a mirror, so every lumen that reaches a window from inside leaves, and
 *
 *   Φ_out = Σ_W ∫_W E_in dA,   E_in = ∫ L cos θ dω over the hemisphere facing into the room,
 *
 * with L = ρ·E/π of the room's surface seen in each direction (diffuse). E_in at the centre of each
 * cell of a grid on the window is a cosine-weighted gather of the maps, the estimator of the gather
 * passes and of workPlaneIlluminance (E = mean ρ·E_hit: the π cancels), on a Fibonacci lattice of
 * directions; the integral over the window is the midpoint rule on the cells.
 */
import type { Vec3 } from '../../../core/model/lightingScene/lightingScene';
import { LUMINANCE_WEIGHTS } from '../bakedMaps';
import type { ObjectRayCaster } from '../objects/createObjectRayCaster';
import type { ObjectAtlas } from '../objects/preparedObjects';
import type { BakeWindow } from './daylightWindows';

/** The golden-ratio step of the direction lattice (as workPlaneDaylight.ts). */
const GOLDEN = (Math.sqrt(5) - 1) / 2;
/** The gather starts this far inside the window's plane (m), so a ray never starts on the wall it leaves. */
const INSET = 1e-4;

export interface WindowGatherOptions {
  /** Largest cell edge of the grid on each window (m). */
  cellSize: number;
  /** Directions per cell. */
  samples: number;
}

const unit = (v: Vec3): Vec3 => {
  const l = Math.hypot(v[0], v[1], v[2]);
  return [v[0] / l, v[1] / l, v[2] / l];
};

/** Y illuminance (lux) on the inner face of a window at p from the baked room: the cosine-weighted gather about `inward`. */
function windowIlluminanceAt(p: Vec3, frame: { a: Vec3; b: Vec3; n: Vec3 }, caster: ObjectRayCaster, atlas: ObjectAtlas, total: Float32Array, samples: number): number {
  let gathered = 0;
  for (let s = 0; s < samples; s++) {
    const u = (s + 0.5) / samples;
    const phi = 2 * Math.PI * ((s * GOLDEN) % 1);
    const [x, y, z] = [Math.sqrt(u) * Math.cos(phi), Math.sqrt(u) * Math.sin(phi), Math.sqrt(1 - u)];
    const dir: Vec3 = [0, 1, 2].map((k) => x * frame.a[k] + y * frame.b[k] + z * frame.n[k]) as Vec3;
    const hit = caster.closestHit(p, dir, 1e4);
    if (!hit || !hit.frontFace) continue;
    const ix = Math.min(atlas.width - 1, Math.floor(hit.atlasUv[0] * atlas.width));
    const iy = Math.min(atlas.height - 1, Math.floor(hit.atlasUv[1] * atlas.height));
    const k = iy * atlas.width + ix;
    for (let c = 0; c < 3; c++) gathered += LUMINANCE_WEIGHTS[c] * atlas.reflectance[4 * k + c] * total[3 * k + c];
  }
  return gathered / samples;
}

/** Φ_out (lm, photometric Y) through `windows` (bake coordinates) of the room whose atlas and total map (RGB lux per texel) are given. */
export function windowLeavingFlux(windows: readonly BakeWindow[], caster: ObjectRayCaster, atlas: ObjectAtlas, total: Float32Array, options: WindowGatherOptions): number {
  let flux = 0;
  for (const w of windows) {
    const frame = { a: unit(w.edgeA), b: unit(w.edgeB), n: unit(w.inward) };
    const na = Math.max(1, Math.ceil(Math.hypot(...w.edgeA) / options.cellSize));
    const nb = Math.max(1, Math.ceil(Math.hypot(...w.edgeB) / options.cellSize));
    for (let i = 0; i < na; i++) {
      for (let j = 0; j < nb; j++) {
        const [a, b] = [(i + 0.5) / na, (j + 0.5) / nb];
        const p: Vec3 = [0, 1, 2].map((k) => w.corner[k] + a * w.edgeA[k] + b * w.edgeB[k] + INSET * frame.n[k]) as Vec3;
        flux += (windowIlluminanceAt(p, frame, caster, atlas, total, options.samples) * w.area) / (na * nb);
      }
    }
  }
  return flux;
}
