import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../core/model/lightingScene/lightingScene';
import type { DirectMaps } from '../bake/bakeJob';
import type { BakeLuminaire } from '../bake/bakeScene';
import type { SurfaceLayout } from '../bake/surfaceLayout';
import type { ObjectAtlas } from '../bake/objects/preparedObjects';

/** A receiver's relit maps: RGB lux per texel, 3 floats. */
export interface DirectTotal {
  direct: Float32Array;
  total: Float32Array;
}

/** The objects' atlas maps (scenes with objects; bakedMaps.ts ObjectMaps without the indirect map). */
export interface ObjectDirectTotal extends DirectTotal {
  atlas: ObjectAtlas;
}

/**
 * One group's basis: its direct maps at unit weight (walls and, with objects, the atlas as the
 * bounces read it and as it is shown) and `flux`, the reflected direct flux Φ per channel
 * (reflectedFlux.ts) that scales the shared indirect solution between solves.
 */
export interface DirectBasis extends DirectMaps {
  flux: Rgb;
  /** The group's luminaires at unit dimming and white colour, as the basis was baked (the work plane's per-basis direct light, workPlaneBases.ts). */
  luminaires?: readonly BakeLuminaire[];
}

/**
 * The shared indirect solve of a scene (docs/viewer.md, "Relighting without rebaking"): the
 * indirect maps (blurred, with the tail; the atlas's dilated as shown) computed from
 * Σ w_g · direct_g, the reflected direct flux Φ_solve of that sum, and the weights it was
 * solved at (`key`, groupState.ts weightsKey). `final`: the finished solve, not a preview.
 */
export interface IndirectSolution {
  surfaces: Record<SurfaceName, Float32Array>;
  objects?: Float32Array;
  flux: Rgb;
  key: string;
  final: boolean;
}

/** Relit maps: what the viewer shows and the statistics read. `objects` is there when the bases have objects. */
export interface LitMaps {
  layouts: Record<SurfaceName, SurfaceLayout>;
  maps: Record<SurfaceName, DirectTotal> & { objects?: ObjectDirectTotal };
}

export interface WeightedBasis {
  basis: DirectBasis;
  weight: Rgb;
}

/** Zeroed output buffers for a set of layouts. */
export function emptyLitMaps(layouts: readonly SurfaceLayout[]): LitMaps {
  const byName = Object.fromEntries(layouts.map((l) => [l.name, l])) as Record<SurfaceName, SurfaceLayout>;
  const maps = Object.fromEntries(layouts.map((l) => [l.name, { direct: new Float32Array(l.width * l.height * 3), total: new Float32Array(l.width * l.height * 3) }])) as LitMaps['maps'];
  return { layouts: byName, maps };
}

/** dst = Σ weight · pick(basis), per channel (3 floats per texel); one pass over the texels per non-zero part. */
function weightedSum(name: string, dst: Float32Array, parts: readonly WeightedBasis[], pick: (b: DirectBasis) => Float32Array | undefined): void {
  dst.fill(0);
  for (const { basis, weight } of parts) {
    const [wr, wg, wb] = weight;
    if (wr === 0 && wg === 0 && wb === 0) continue;
    const s = pick(basis);
    if (!s) throw new Error(`relightMaps: a basis has no ${name} map`);
    if (s.length !== dst.length) throw new Error(`relightMaps: the ${name} basis has ${s.length / 3} texels, the output ${dst.length / 3}`);
    for (let i = 0; i < dst.length; i += 3) {
      dst[i] += s[i] * wr;
      dst[i + 1] += s[i + 1] * wg;
      dst[i + 2] += s[i + 2] * wb;
    }
  }
}

/**
 * The shared solve's input: Σ_g w_g · direct_g per surface, and the atlas's emitted direct map
 * (null without objects). Light is linear in the sources and the bounce operator is linear in
 * the direct maps, so one solve from this sum is the indirect light of every group at once.
 */
export function sumDirect(parts: readonly WeightedBasis[], layouts: readonly SurfaceLayout[], atlas: ObjectAtlas | null): { surfaces: Record<SurfaceName, Float32Array>; objects: Float32Array | null } {
  const surfaces = Object.fromEntries(
    layouts.map((l) => {
      const dst = new Float32Array(l.width * l.height * 3);
      weightedSum(l.name, dst, parts, (b) => b.surfaces[l.name]);
      return [l.name, dst];
    }),
  ) as Record<SurfaceName, Float32Array>;
  let objects: Float32Array | null = null;
  if (atlas) {
    objects = new Float32Array(atlas.width * atlas.height * 3);
    weightedSum('objects', objects, parts, (b) => b.objects?.emitted);
  }
  return { surfaces, objects };
}

/** One indirect solution with its per-channel factor in the total. */
export interface IndirectTerm {
  solution: IndirectSolution;
  scale: Rgb;
}

/**
 * out.direct = Σ_g w_g · direct_g (exact at any weights); out.total = out.direct + Σ_k s_k ⊙ indirect_k.
 * One term with s = 1 when the solution was solved at these weights, Φ_now/Φ_solve between a weight
 * change and the re-solve (indirectScale in reflectedFlux.ts); during a crossfade from A to B with
 * both solved, two terms (1 − e)·I_A + e·I_B (the indirect light is linear in the weights).
 * No term: total = direct. Writes into `out` (no allocation but the atlas's first use).
 */
export function relightMaps(parts: readonly WeightedBasis[], terms: readonly IndirectTerm[], atlas: ObjectAtlas | null, out: LitMaps): LitMaps {
  const addIndirect = (dst: DirectTotal, pick: (s: IndirectSolution) => Float32Array | undefined) => {
    const { direct, total } = dst;
    total.set(direct);
    for (const { solution, scale } of terms) {
      const ind = pick(solution);
      if (!ind) continue;
      if (ind.length !== total.length) throw new Error(`relightMaps: the indirect solution has ${ind.length / 3} texels, the output ${total.length / 3}`);
      const [sr, sg, sb] = scale;
      for (let i = 0; i < total.length; i += 3) {
        total[i] += ind[i] * sr;
        total[i + 1] += ind[i + 1] * sg;
        total[i + 2] += ind[i + 2] * sb;
      }
    }
  };
  for (const name of SURFACE_NAMES) {
    const dst = out.maps[name];
    weightedSum(name, dst.direct, parts, (b) => b.surfaces[name]);
    addIndirect(dst, (s) => s.surfaces[name]);
  }
  // The objects' atlas: every basis of one scene has the same atlas (the same objects, the same settings).
  if (atlas) {
    const size = atlas.width * atlas.height * 3;
    if (!out.maps.objects || out.maps.objects.total.length !== size) {
      out.maps.objects = { atlas, direct: new Float32Array(size), total: new Float32Array(size) };
    }
    out.maps.objects.atlas = atlas;
    weightedSum('objects', out.maps.objects.direct, parts, (b) => b.objects?.shown);
    addIndirect(out.maps.objects, (s) => s.objects);
  } else delete out.maps.objects;
  return out;
}
