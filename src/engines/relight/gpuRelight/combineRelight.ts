import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../../core/model/lightingScene/lightingScene';
import { RELIGHT_BASES_PER_DRAW, RELIGHT_BASIS_SAMPLERS, type RelightCombineUniforms } from '../../../../shaders/relightCombine.glsl';
import type { FloatTarget } from '../../bake/floatTarget';
import { runPass, type UniformValues } from '../../bake/runPass';
import type { SurfaceLayout } from '../../bake/surfaceLayout';
import type { ObjectAtlas } from '../../bake/objects/preparedObjects';
import type { GpuDirectTotal, GpuLitMaps, GridPart } from '../createGpuRelight';
import type { DirectBasis, IndirectSolution, IndirectTerm, WeightedBasis } from '../relightMaps';
import type { GpuRelightState } from './gpuRelightState';
import { pruneUploads, receiverTargets, replaceGridMaps, uploadMap, zeroOf } from './relightTextures';

/** An uploaded map and its per-channel factor. */
interface WeightedTexture {
  texture: WebGLTexture;
  weight: Rgb;
}

/**
 * dst = accum + Σ weight_k ⊙ map_k, in chunks of RELIGHT_BASES_PER_DRAW; consecutive chunks alternate
 * between `dst` and `scratch` so that no draw reads the texture it writes and the last lands in dst.
 */
function combine(s: GpuRelightState, dst: FloatTarget, scratch: FloatTarget, accum: WebGLTexture, maps: readonly WeightedTexture[]): void {
  const chunks = Math.max(1, Math.ceil(maps.length / RELIGHT_BASES_PER_DRAW));
  let input = accum;
  for (let c = 0; c < chunks; c++) {
    const target = (chunks - 1 - c) % 2 === 0 ? dst : scratch;
    const chunk = maps.slice(c * RELIGHT_BASES_PER_DRAW, (c + 1) * RELIGHT_BASES_PER_DRAW);
    const weights = new Float32Array(RELIGHT_BASES_PER_DRAW * 3);
    const values = { uAccum: input, uWeight: weights, uCount: chunk.length } as Record<string, unknown>;
    RELIGHT_BASIS_SAMPLERS.forEach((name, k) => {
      values[name] = chunk[k]?.texture ?? s.zero.texture;
      if (chunk[k]) weights.set(chunk[k].weight, k * 3);
    });
    runPass(s.gl, s.program, target, values as UniformValues<RelightCombineUniforms>);
    s.draws++;
    input = target.texture;
  }
}

/** Where one receiver's maps are found in a basis and in an indirect solution. */
interface ReceiverMaps {
  key: string;
  width: number;
  height: number;
  basis: (b: DirectBasis) => Float32Array | undefined;
  indirect: (s: IndirectSolution) => Float32Array | undefined;
}

/** One receiver's direct map (Σ of its weighted bases) and total (direct plus the scaled indirect solutions). */
function relightReceiver(s: GpuRelightState, r: ReceiverMaps, parts: readonly WeightedBasis[], terms: readonly IndirectTerm[]): GpuDirectTotal {
  const o = receiverTargets(s, r.key, r.width, r.height);
  const direct: WeightedTexture[] = [];
  for (const { basis, weight } of parts) {
    if (weight[0] === 0 && weight[1] === 0 && weight[2] === 0) continue;
    const map = r.basis(basis);
    if (!map) throw new Error(`GPU relight: a basis has no ${r.key} map`);
    direct.push({ texture: uploadMap(s, map, r.width, r.height), weight });
  }
  combine(s, o.direct, o.scratch, zeroOf(s, r.width, r.height).texture, direct);
  const indirect: WeightedTexture[] = [];
  for (const { solution, scale } of terms) {
    const map = r.indirect(solution);
    if (map) indirect.push({ texture: uploadMap(s, map, r.width, r.height), weight: scale });
  }
  combine(s, o.total, o.scratch, o.direct.texture, indirect);
  return { direct: o.direct, total: o.total };
}

/** Every map the bases and indirect solutions of a relight hold: what the prune keeps. */
function mapsInUse(parts: readonly WeightedBasis[], terms: readonly IndirectTerm[]): Set<Float32Array> {
  const inUse = new Set<Float32Array>();
  for (const { basis } of parts) {
    for (const n of SURFACE_NAMES) inUse.add(basis.surfaces[n]);
    if (basis.objects) inUse.add(basis.objects.shown);
  }
  for (const { solution } of terms) {
    for (const n of SURFACE_NAMES) inUse.add(solution.surfaces[n]);
    if (solution.objects) inUse.add(solution.objects);
  }
  return inUse;
}

/** The display maps of every wall and, with objects, the atlas, after freeing the textures no longer in use. */
export function relightReceivers(s: GpuRelightState, parts: readonly WeightedBasis[], terms: readonly IndirectTerm[], layouts: Readonly<Record<SurfaceName, SurfaceLayout>>, atlas: ObjectAtlas | null): GpuLitMaps {
  pruneUploads(s, mapsInUse(parts, terms));
  const maps = {} as GpuLitMaps;
  for (const name of SURFACE_NAMES) {
    const { width, height } = layouts[name];
    maps[name] = relightReceiver(s, { key: name, width, height, basis: (b) => b.surfaces[name], indirect: (x) => x.surfaces[name] }, parts, terms);
  }
  if (atlas) maps.objects = relightReceiver(s, { key: 'objects', width: atlas.width, height: atlas.height, basis: (b) => b.objects?.shown, indirect: (x) => x.objects }, parts, terms);
  return maps;
}

/** A grid combined like a receiver; its maps are uploaded as RGBA32F and replace the previous grid's. */
export function relightGrid(s: GpuRelightState, key: string, width: number, height: number, direct: readonly GridPart[], indirect: readonly GridPart[]): GpuDirectTotal {
  replaceGridMaps(s, new Set([...direct, ...indirect].map((p) => p.map)));
  const o = receiverTargets(s, `grid:${key}`, width, height);
  const upload32 = (parts: readonly GridPart[]) => parts.filter((p) => p.weight.some((w) => w !== 0)).map((p) => ({ texture: uploadMap(s, p.map, width, height, true), weight: p.weight }));
  combine(s, o.direct, o.scratch, zeroOf(s, width, height).texture, upload32(direct));
  combine(s, o.total, o.scratch, o.direct.texture, upload32(indirect));
  return { direct: o.direct, total: o.total };
}
