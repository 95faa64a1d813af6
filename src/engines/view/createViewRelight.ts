import * as THREE from 'three';
import { SURFACE_NAMES, type SurfaceName } from '../../core/model/lightingScene/lightingScene';
import type { FloatTarget } from '../bake/floatTarget';
import { createGpuRelight, type BasisPrecision, type GpuRelight, type GridPart, type ReadbackCounter } from '../relight/createGpuRelight';
import type { RelightParts } from '../relight/RelightEngine';
import { createGpuStats, type GpuStats, type PendingStats, type StatsMask } from './createGpuStats';
import { programsReady, startPrograms } from '../bake/glResources';
import { relightCombinePass } from '../../../shaders/relightCombine.glsl';
import { statsBlockPass, statsMergePass } from '../../../shaders/statsReduce.glsl';
import { lowMemoryDevice } from './lowMemoryDevice';
import type { WorkPlaneBases } from './workPlaneBases';

/**
 * Texture memory the view's GPU relight may hold on a low-memory device (`navigator.deviceMemory`
 * ≤ 2 GB, lowMemoryDevice.ts): bases, indirect solutions and display targets together. A configuration
 * over it is relit on the CPU (one display texture per receiver, as before issue 34). 64 MiB holds
 * 12 modules of a 5 × 4 × 2.7 m room at the viewer's 5 cm about ten times (5.4 MiB, docs/viewer.md).
 */
export const LOW_MEMORY_RELIGHT_BYTES = 64 * 1024 * 1024;

/** The bytes per texel the relight holds for a map at each precision, and for a receiver's display targets (direct, total, scratch: RGBA32F). */
const BASIS_BYTES: Record<BasisPrecision, number> = { float: 16, half: 8 };
const DISPLAY_BYTES = 3 * 16;

/** The display maps a GPU relight wrote, as textures three samples (and the floor's total for the statistics). */
export interface ViewRelightMaps {
  surfaces: Record<SurfaceName, THREE.Texture>;
  objects: THREE.Texture | null;
  floor: FloatTarget;
  /** The objects' atlas total (a shaped room's floor is in it), null without objects. */
  atlas: FloatTarget | null;
}

/** The counters `view3d().gpu` reports (docs/viewer.md, "Relighting on the GPU"). */
export interface ViewRelightCounters {
  /** Relights combined on the GPU. */
  relights: number;
  /** Maps read back from the view's context (never, by construction: the relight writes textures three samples). */
  mapReadbacks: ReadbackCounter;
  /** The statistics texels read back (16 bytes each). */
  statsReadbacks: ReadbackCounter;
  /** Basis and indirect maps uploaded (each once), and their bytes. */
  uploads: ReadbackCounter;
}

/** The programs the view's relight and statistics draw with: compiled in the background from the view's start (startPrograms). */
const VIEW_RELIGHT_PROGRAMS = [relightCombinePass.source, statsBlockPass.source, statsMergePass.source];

export interface ViewRelight {
  readonly precision: BasisPrecision;
  /**
   * Whether the relight's programs can be used without waiting for the driver (programsReady:
   * KHR_parallel_shader_compile's COMPLETION_STATUS_KHR where the context has it). Until then the
   * view relights on the CPU, so a first relight never blocks the page on a compile.
   */
  ready(): boolean;
  /** Whether these parts fit the device's texture budget (LOW_MEMORY_RELIGHT_BYTES on low-memory devices, else always). */
  fits(parts: RelightParts): boolean;
  /** Combine the parts on the GPU into the display textures (draws only: nothing is read back). */
  relight(parts: RelightParts): ViewRelightMaps;
  /** Ē, Emin, Emax, U0 of the floor's total (texels `covered` left out), read once the GPU is done (createGpuStats.ts). */
  floorStats(maps: ViewRelightMaps, covered: Uint8Array | null): PendingStats;
  /** The same of a shaped room's floor in the atlas, each texel weighed by `weights` (shapedFloorWeights.ts); null without an atlas. */
  shapedFloorStats(maps: ViewRelightMaps, weights: Float32Array): PendingStats | null;
  /**
   * Ē, Emin, Emax, U0 of the work plane at the parts' weights: the per-part grids of `plane`
   * (workPlaneBases.ts) combined on the GPU with the weights and scales of the display maps, then
   * reduced like the floor (its points inside furniture left out); null when a basis does not carry
   * its luminaires (its work-plane light cannot be formed).
   */
  workPlaneStats(parts: RelightParts, plane: WorkPlaneBases): PendingStats | null;
  readonly counters: ViewRelightCounters;
  /** GPU texture memory held now. */
  textureBytes(): number;
  dispose(): void;
}

/** Texture bytes the relight would hold for these parts: every basis and solution map at `precision`, and the display targets. */
function relightBytes(parts: RelightParts, precision: BasisPrecision): number {
  let texels = 0;
  for (const n of SURFACE_NAMES) texels += parts.layouts[n].width * parts.layouts[n].height;
  const atlas = parts.atlas ? parts.atlas.width * parts.atlas.height : 0;
  const maps = parts.parts.length + parts.terms.length;
  return maps * (texels + atlas) * BASIS_BYTES[precision] + (texels + atlas) * DISPLAY_BYTES;
}

/** The work plane's grids of these parts with their weights and scales (workPlaneBases.ts), or null when a basis does not carry its luminaires. */
function workPlaneGridParts(parts: RelightParts, plane: WorkPlaneBases): { direct: GridPart[]; indirect: GridPart[] } | null {
  const direct: GridPart[] = [];
  for (const { basis, weight } of parts.parts) {
    const map = plane.direct(basis);
    if (!map) return null;
    direct.push({ map, weight });
  }
  const indirect = parts.terms.map(({ solution, scale }): GridPart => ({ map: plane.indirect(solution, parts.layouts.floor), weight: scale }));
  return { direct, indirect };
}

/**
 * Bases are sampled with texelFetch only, which WebGL2 allows for RGBA16F on every device; half
 * floats err at most 2⁻¹¹ of a value (0.026 % of the peak measured, docs/viewer.md "Half floats"),
 * within the 0.1 %, so the view keeps its bases in half floats everywhere. Maps over
 * 65 504 lx stay RGBA32F (createGpuRelight).
 */
export const VIEW_BASIS_PRECISION: BasisPrecision = 'half';

/**
 * The relight of the 3D view in the view's own context (three.js's): the engine's bases and indirect
 * solutions, read back once from the baker's context when they were finished, are uploaded once
 * here, and every relight (dimming, CCT, filters, crossfades, DMX levels) is draws of the combine
 * pass into display textures three samples through THREE.ExternalTexture. After each batch of raw
 * WebGL calls three's state cache is reset (WebGLRenderer.resetState), since three does not know
 * what the passes bound.
 */
export function createViewRelight(renderer: THREE.WebGLRenderer, precision: BasisPrecision = VIEW_BASIS_PRECISION, budget: number | null = lowMemoryDevice() ? LOW_MEMORY_RELIGHT_BYTES : null): ViewRelight {
  const gl = renderer.getContext() as WebGL2RenderingContext;
  let gpu: GpuRelight | null = null;
  let stats: GpuStats | null = null;
  const wrapped = new Map<WebGLTexture, THREE.ExternalTexture>();
  // Issued now, waited for by nobody: the driver compiles them beside the first frames (ANGLE has a worker pool).
  startPrograms(gl, VIEW_RELIGHT_PROGRAMS);
  renderer.resetState();
  const counters: ViewRelightCounters = { relights: 0, mapReadbacks: { count: 0, bytes: 0 }, statsReadbacks: { count: 0, bytes: 0 }, uploads: { count: 0, bytes: 0 } };

  const gpuRelight = (): GpuRelight => {
    if (!gpu) {
      gpu = createGpuRelight(gl, precision);
      // The relight's own counters are the view's: the same objects, live.
      counters.mapReadbacks = gpu.readbacks;
      counters.uploads = gpu.uploads;
    }
    return gpu;
  };
  const textureOf = (target: FloatTarget): THREE.Texture => {
    let t = wrapped.get(target.texture);
    if (!t) wrapped.set(target.texture, (t = new THREE.ExternalTexture(target.texture)));
    // three's typings give ExternalTexture another image type than Texture; the renderer binds its sourceTexture (setTexture2D).
    return t as unknown as THREE.Texture;
  };

  return {
    precision,
    ready: () => programsReady(gl, VIEW_RELIGHT_PROGRAMS),
    fits: (parts) => budget === null || relightBytes(parts, precision) <= budget,
    relight(parts) {
      const maps = gpuRelight().relight(parts.parts, parts.terms, parts.layouts, parts.atlas);
      renderer.resetState();
      counters.relights++;
      const surfaces = Object.fromEntries(SURFACE_NAMES.map((n) => [n, textureOf(maps[n].total)])) as Record<SurfaceName, THREE.Texture>;
      return { surfaces, objects: maps.objects ? textureOf(maps.objects.total) : null, floor: maps.floor.total, atlas: maps.objects?.total ?? null };
    },
    floorStats(maps, covered) {
      return requestStats(maps.floor, covered);
    },
    shapedFloorStats(maps, weights) {
      return maps.atlas ? requestStats(maps.atlas, weights) : null;
    },
    workPlaneStats(parts, plane) {
      const grids = workPlaneGridParts(parts, plane);
      if (!grids) return null;
      const { nx, nz, covered } = plane.grid;
      const maps = gpuRelight().relightGrid('workPlane', nx, nz, grids.direct, grids.indirect);
      renderer.resetState();
      return requestStats(maps.total, covered);
    },
    get counters() {
      return counters;
    },
    textureBytes: () => gpu?.textureBytes() ?? 0,
    dispose() {
      // The ExternalTextures are not disposed: three would delete the relight's GL textures, which the relight frees itself.
      wrapped.clear();
      gpu?.dispose();
      stats?.dispose();
      gpu = null;
      stats = null;
      renderer.resetState();
    },
  };

  function requestStats(map: FloatTarget, covered: StatsMask): PendingStats {
    stats ??= createGpuStats(gl);
    counters.statsReadbacks = stats.readbacks;
    const pending = stats.request(map, covered);
    renderer.resetState();
    return {
      poll() {
        const result = pending.poll();
        renderer.resetState();
        return result;
      },
    };
  }
}
