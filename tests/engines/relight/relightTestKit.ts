import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../../src/core/model/lightingScene/lightingScene';
import type { BakedMaps } from '../../../src/engines/bake/bakedMaps';
import { texelArea } from '../../../src/engines/bake/surfaceLayout';
import type { LitMaps } from '../../../src/engines/relight/relightMaps';

/** Worst |relit − reference| of the direct and total maps (walls and the atlas), and the reference's peak total. */
export function compareWithBake(lit: LitMaps, reference: BakedMaps): { peak: number; direct: number; total: number; objectTexels: number } {
  let peak = 0;
  let direct = 0;
  let total = 0;
  const pairs: [{ direct: Float32Array; total: Float32Array }, { direct: Float32Array; total: Float32Array }][] = SURFACE_NAMES.map((n) => [lit.maps[n], reference[n]]);
  if (reference.objects) {
    if (!lit.maps.objects) throw new Error('the relit maps have no objects');
    pairs.push([lit.maps.objects, reference.objects]);
  }
  for (const [a, b] of pairs) {
    if (a.total.length !== b.total.length) throw new Error(`sizes differ: ${a.total.length} vs ${b.total.length}`);
    for (let i = 0; i < b.total.length; i++) {
      peak = Math.max(peak, b.total[i]);
      direct = Math.max(direct, Math.abs(a.direct[i] - b.direct[i]));
      total = Math.max(total, Math.abs(a.total[i] - b.total[i]));
    }
  }
  return { peak, direct, total, objectTexels: reference.objects ? reference.objects.total.length / 3 : 0 };
}

/** The indirect part shown: total − direct, per receiver (walls, then the atlas when there is one). */
export function shownIndirect(lit: LitMaps): Float32Array[] {
  const receivers = [...SURFACE_NAMES.map((n) => lit.maps[n]), ...(lit.maps.objects ? [lit.maps.objects] : [])];
  return receivers.map(({ direct, total }) => total.map((t, i) => t - direct[i]));
}

/**
 * Reflected direct flux per channel computed from relit direct maps, independently of the
 * engine's reflectedFlux: Σ_walls ρ·A_texel·ΣE + Σ_atlas ρ_texel·coverage·texel²·E.
 */
export function reflectedDirectFlux(lit: LitMaps, reflectance: Record<SurfaceName, Rgb>): Rgb {
  const flux: Rgb = [0, 0, 0];
  for (const n of SURFACE_NAMES) {
    const a = texelArea(lit.layouts[n]);
    const e = lit.maps[n].direct;
    for (let i = 0; i < e.length; i++) flux[i % 3] += reflectance[n][i % 3] * a * e[i];
  }
  const o = lit.maps.objects;
  if (o) {
    const { position, reflectance: rho, texelSize } = o.atlas;
    for (let t = 0; t < o.direct.length / 3; t++) {
      const c = position[t * 4 + 3];
      if (c > 0) for (let k = 0; k < 3; k++) flux[k] += rho[t * 4 + k] * c * texelSize * texelSize * o.direct[t * 3 + k];
    }
  }
  return flux;
}
