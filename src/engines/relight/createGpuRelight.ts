import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../core/model/lightingScene/lightingScene';
import { RELIGHT_BASES_PER_DRAW, RELIGHT_BASIS_SAMPLERS, relightCombinePass, type RelightCombineUniforms } from '../../../shaders/relightCombine.glsl';
import { createFloatTarget, deleteTarget, readRgb, requireFloatTargets, type FloatTarget } from '../bake/floatTarget';
import { passProgram, runPass, type UniformValues } from '../bake/runPass';
import type { SurfaceLayout } from '../bake/surfaceLayout';
import type { ObjectAtlas } from '../bake/objects/preparedObjects';
import { halfBits } from './halfFloat';
import type { DirectBasis, IndirectSolution, IndirectTerm, WeightedBasis } from './relightMaps';

/** A receiver's display maps on the GPU: the direct and the total illuminance, RGBA32F render targets. */
export interface GpuDirectTotal {
  direct: FloatTarget;
  total: FloatTarget;
}

/** The display maps of every wall and, with objects, the atlas: textures the view samples directly. */
export type GpuLitMaps = Record<SurfaceName, GpuDirectTotal> & { objects?: GpuDirectTotal };

/** Precision of the basis and indirect textures: `float` (RGBA32F, 16 B/texel) or `half` (RGBA16F, 8 B/texel). */
export type BasisPrecision = 'float' | 'half';

/** GPU → CPU read-backs: how many and the bytes they moved (the viewer's `view3d().readbacks`). */
export interface ReadbackCounter {
  count: number;
  bytes: number;
}

export interface GpuRelight {
  /** The display maps for these weighted bases and indirect terms, combined on the GPU (no read-back). */
  relight(parts: readonly WeightedBasis[], terms: readonly IndirectTerm[], layouts: Readonly<Record<SurfaceName, SurfaceLayout>>, atlas: ObjectAtlas | null): GpuLitMaps;
  /**
   * A grid of any size combined like a receiver: Σ weight ⊙ map over `direct`, then plus Σ scale ⊙ map
   * over `indirect` (RGB per texel, row-major, `width` × `height`). The work plane's statistics use it
   * (workPlaneBases.ts). Its maps are uploaded once as RGBA32F whatever the precision (they are small,
   * and the statistics keep float accuracy) and kept while the next grid relight uses them.
   */
  relightGrid(key: string, width: number, height: number, direct: readonly GridPart[], indirect: readonly GridPart[]): GpuDirectTotal;
  /** One display map read back as RGB floats (3 per texel): counted in `readbacks`. Statistics and tests only. */
  read(target: FloatTarget): Float32Array;
  readonly readbacks: ReadbackCounter;
  /** CPU → GPU uploads of basis and indirect maps (each map once, while a relight uses it) and their bytes. */
  readonly uploads: ReadbackCounter;
  /** Draws of the combine pass so far. */
  readonly draws: number;
  /** Bytes of GPU texture memory held now: basis/indirect textures at their precision, display targets at 16 B/texel. */
  textureBytes(): number;
  dispose(): void;
}

/** One map of a grid relight and its per-channel factor. */
export interface GridPart {
  map: Float32Array;
  weight: Rgb;
}

/** A basis or indirect map uploaded once as a texture (sampled with texelFetch: no filtering needed). */
interface Uploaded {
  texture: WebGLTexture;
  bytes: number;
}

/** Half floats hold ±65 504 (IEEE 754 binary16): larger lux values would overflow, so such a map stays RGBA32F. */
const HALF_MAX = 65504;

/**
 * The relight of relightMaps.ts on the GPU (docs/viewer.md, "Relighting on the GPU"): the bases and
 * the indirect solutions are uploaded once as textures, and every relight (dimming, CCT, filters,
 * crossfade ends, DMX levels: only the weights and scales change) is a few full-screen draws per
 * receiver of relightCombine.glsl.ts into display targets the view samples. Nothing is read back.
 * The weights and the indirect terms (exact, crossfade blend, or the interim Φ_now/Φ_solve scale of
 * indirectTerms.ts) are the CPU relight's, so both show the same light.
 */
export function createGpuRelight(gl: WebGL2RenderingContext, precision: BasisPrecision = 'float'): GpuRelight {
  // The display targets are sampled by the view: linear only where float textures filter (else nearest, as the view's DataTextures).
  const { linear } = requireFloatTargets(gl);
  const program = passProgram(gl, relightCombinePass);
  const uploads = new Map<Float32Array, Uploaded>();
  const outputs = new Map<string, GpuDirectTotal & { scratch: FloatTarget }>();
  const readbacks: ReadbackCounter = { count: 0, bytes: 0 };
  const uploaded: ReadbackCounter = { count: 0, bytes: 0 };
  let draws = 0;
  const zero = createFloatTarget(gl, 1, 1, false);
  // Zero textures of each size: the accumulator of a direct map. Cleared on creation (createFloatTarget).
  const zeros = new Map<string, FloatTarget>();

  // The maps the last grid relight used: kept by the receivers' prune.
  let gridInUse = new Set<Float32Array>();

  const upload = (data: Float32Array, width: number, height: number, float = false): WebGLTexture => {
    const known = uploads.get(data);
    if (known) return known.texture;
    if (data.length !== width * height * 3) throw new Error(`GPU relight: a map has ${data.length / 3} texels, its receiver ${width * height}`);
    let peak = 0;
    for (let i = 0; i < data.length; i++) peak = Math.max(peak, Math.abs(data[i]));
    const half = !float && precision === 'half' && peak <= HALF_MAX;
    const rgba = half ? new Uint16Array(width * height * 4) : new Float32Array(width * height * 4);
    const convert = half ? halfBits : (v: number) => v;
    for (let i = 0, j = 0; i < data.length; i += 3, j += 4) {
      rgba[j] = convert(data[i]);
      rgba[j + 1] = convert(data[i + 1]);
      rgba[j + 2] = convert(data[i + 2]);
      rgba[j + 3] = convert(1);
    }
    const texture = gl.createTexture();
    if (!texture) throw new Error('WebGL: out of resources creating a relight basis');
    gl.bindTexture(gl.TEXTURE_2D, texture);
    if (half) gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA16F, width, height, 0, gl.RGBA, gl.HALF_FLOAT, rgba);
    else gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, height, 0, gl.RGBA, gl.FLOAT, rgba);
    for (const p of [gl.TEXTURE_MIN_FILTER, gl.TEXTURE_MAG_FILTER]) gl.texParameteri(gl.TEXTURE_2D, p, gl.NEAREST);
    uploads.set(data, { texture, bytes: width * height * (half ? 8 : 16) });
    uploaded.count++;
    uploaded.bytes += rgba.byteLength;
    return texture;
  };

  const outputFor = (key: string, width: number, height: number) => {
    let o = outputs.get(key);
    if (o && (o.direct.width !== width || o.direct.height !== height)) {
      for (const t of [o.direct, o.total, o.scratch]) deleteTarget(gl, t);
      o = undefined;
    }
    if (!o) outputs.set(key, (o = { direct: createFloatTarget(gl, width, height, linear), total: createFloatTarget(gl, width, height, linear), scratch: createFloatTarget(gl, width, height, false) }));
    return o;
  };

  const zeroOf = (width: number, height: number): FloatTarget => {
    const key = `${width}x${height}`;
    let z = zeros.get(key);
    if (!z) zeros.set(key, (z = createFloatTarget(gl, width, height, false)));
    return z;
  };

  /**
   * dst = accum + Σ weight_k ⊙ map_k, in chunks of RELIGHT_BASES_PER_DRAW; consecutive chunks alternate
   * between `dst` and `scratch` so that no draw reads the texture it writes and the last lands in dst.
   */
  const combine = (dst: FloatTarget, scratch: FloatTarget, accum: WebGLTexture, maps: readonly { texture: WebGLTexture; weight: Rgb }[]) => {
    const chunks = Math.max(1, Math.ceil(maps.length / RELIGHT_BASES_PER_DRAW));
    let input = accum;
    for (let c = 0; c < chunks; c++) {
      const target = (chunks - 1 - c) % 2 === 0 ? dst : scratch;
      const chunk = maps.slice(c * RELIGHT_BASES_PER_DRAW, (c + 1) * RELIGHT_BASES_PER_DRAW);
      const weights = new Float32Array(RELIGHT_BASES_PER_DRAW * 3);
      const values = { uAccum: input, uWeight: weights, uCount: chunk.length } as Record<string, unknown>;
      RELIGHT_BASIS_SAMPLERS.forEach((name, k) => {
        values[name] = chunk[k]?.texture ?? zero.texture;
        if (chunk[k]) weights.set(chunk[k].weight, k * 3);
      });
      runPass(gl, program, target, values as UniformValues<RelightCombineUniforms>);
      draws++;
      input = target.texture;
    }
  };

  const receiver = (
    key: string,
    width: number,
    height: number,
    parts: readonly WeightedBasis[],
    pickBasis: (b: DirectBasis) => Float32Array | undefined,
    terms: readonly IndirectTerm[],
    pickIndirect: (s: IndirectSolution) => Float32Array | undefined,
  ): GpuDirectTotal => {
    const o = outputFor(key, width, height);
    const direct: { texture: WebGLTexture; weight: Rgb }[] = [];
    for (const { basis, weight } of parts) {
      if (weight[0] === 0 && weight[1] === 0 && weight[2] === 0) continue;
      const map = pickBasis(basis);
      if (!map) throw new Error(`GPU relight: a basis has no ${key} map`);
      direct.push({ texture: upload(map, width, height), weight });
    }
    combine(o.direct, o.scratch, zeroOf(width, height).texture, direct);
    const indirect: { texture: WebGLTexture; weight: Rgb }[] = [];
    for (const { solution, scale } of terms) {
      const map = pickIndirect(solution);
      if (map) indirect.push({ texture: upload(map, width, height), weight: scale });
    }
    combine(o.total, o.scratch, o.direct.texture, indirect);
    return { direct: o.direct, total: o.total };
  };

  const relightReceivers = (parts: readonly WeightedBasis[], terms: readonly IndirectTerm[], layouts: Readonly<Record<SurfaceName, SurfaceLayout>>, atlas: ObjectAtlas | null): GpuLitMaps => {
    const maps = {} as GpuLitMaps;
    for (const name of SURFACE_NAMES) {
      const l = layouts[name];
      maps[name] = receiver(
        name,
        l.width,
        l.height,
        parts,
        (b) => b.surfaces[name],
        terms,
        (s) => s.surfaces[name],
      );
    }
    if (atlas)
      maps.objects = receiver(
        'objects',
        atlas.width,
        atlas.height,
        parts,
        (b) => b.objects?.shown,
        terms,
        (s) => s.objects,
      );
    return maps;
  };

  /** Textures of maps no longer in use (a dropped basis, a replaced preview) are freed. */
  const prune = (inUse: Set<Float32Array>) => {
    for (const [data, u] of uploads) {
      if (inUse.has(data) || gridInUse.has(data)) continue;
      gl.deleteTexture(u.texture);
      uploads.delete(data);
    }
  };

  return {
    relight(parts, terms, layouts, atlas) {
      const inUse = new Set<Float32Array>();
      for (const { basis } of parts) {
        for (const n of SURFACE_NAMES) inUse.add(basis.surfaces[n]);
        if (basis.objects) inUse.add(basis.objects.shown);
      }
      for (const { solution } of terms) {
        for (const n of SURFACE_NAMES) inUse.add(solution.surfaces[n]);
        if (solution.objects) inUse.add(solution.objects);
      }
      prune(inUse);
      return relightReceivers(parts, terms, layouts, atlas);
    },
    relightGrid(key, width, height, direct, indirect) {
      const previous = gridInUse;
      gridInUse = new Set([...direct, ...indirect].map((p) => p.map));
      for (const data of previous) {
        const u = uploads.get(data);
        if (gridInUse.has(data) || !u) continue;
        gl.deleteTexture(u.texture);
        uploads.delete(data);
      }
      const o = outputFor(`grid:${key}`, width, height);
      const upload32 = (parts: readonly GridPart[]) => parts.filter((p) => p.weight.some((w) => w !== 0)).map((p) => ({ texture: upload(p.map, width, height, true), weight: p.weight }));
      combine(o.direct, o.scratch, zeroOf(width, height).texture, upload32(direct));
      combine(o.total, o.scratch, o.direct.texture, upload32(indirect));
      return { direct: o.direct, total: o.total };
    },
    read(target) {
      readbacks.count++;
      readbacks.bytes += target.width * target.height * 16;
      return readRgb(gl, target);
    },
    readbacks,
    uploads: uploaded,
    get draws() {
      return draws;
    },
    textureBytes() {
      let bytes = 0;
      for (const u of uploads.values()) bytes += u.bytes;
      for (const o of outputs.values()) bytes += 3 * o.direct.width * o.direct.height * 16;
      for (const z of zeros.values()) bytes += z.width * z.height * 16;
      return bytes;
    },
    dispose() {
      gridInUse = new Set();
      prune(new Set());
      for (const o of outputs.values()) for (const t of [o.direct, o.total, o.scratch]) deleteTarget(gl, t);
      outputs.clear();
      for (const z of zeros.values()) deleteTarget(gl, z);
      zeros.clear();
      deleteTarget(gl, zero);
    },
  };
}
