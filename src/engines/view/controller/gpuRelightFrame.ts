import type { SurfaceLayout } from '../../bake/surfaceLayout';
import type { PreparedObjects } from '../../bake/objects/preparedObjects';
import type { BasisPrecision } from '../../relight/createGpuRelight';
import type { RelightEngine } from '../../relight/RelightEngine';
import type { LitMaps } from '../../relight/relightMaps';
import { createViewRelight, type ViewRelight, type ViewRelightMaps } from '../createViewRelight';
import { shapedFloorWeights } from '../shapedFloorWeights';
import type { CompileCounters } from '../createCompileGate';
import type { PendingStats } from '../createGpuStats';
import type { IlluminanceStats } from '../lightStats';
import { floorUnderObjects } from '../lightStats';
import { sceneGeometryKey } from '../sceneGeometryKey';
import type { Viewer } from './viewer';
import { createWorkPlaneBases, type WorkPlaneBases } from '../workPlaneBases';
import type { BakeScene } from '../../bake/bakeScene';

/**
 * After the last GPU relight of a stream (a crossfade, a dimming drag, a DMX stream) has stood this
 * long, the maps are relit once on the CPU as well, for what still reads CPU maps: the legend's
 * percentile, the work plane, the objects' statistics, the housings' ambient light. A stream never
 * waits for it; the floor's statistics follow every GPU relight (createGpuStats).
 */
export const GPU_SETTLE_MS = 400;

/** Bytes the CPU path uploads for a relit map set: RGBA32F per texel of every receiver shown (createRoomSurfaces, createRoomObjects). */
export function displayUploadBytes(lit: LitMaps): number {
  let texels = 0;
  for (const l of Object.values(lit.layouts)) texels += l.width * l.height;
  const objects = lit.maps.objects;
  if (objects) texels += objects.atlas.width * objects.atlas.height;
  return texels * 16;
}

/** What `view3d().gpu` reports (docs/viewer.md, "Relighting on the GPU"). */
export interface GpuViewStatus {
  /** Precision of the bases in the view's context. */
  precision: BasisPrecision;
  /** Relights combined on the GPU, and relights summed on the CPU and uploaded. */
  gpuRelights: number;
  cpuRelights: number;
  /** Maps read back from the view's context (0: the relight writes textures three samples). */
  mapReadbacks: number;
  mapReadbackBytes: number;
  /** Statistics texels read back (16 bytes each, after their fence). */
  statsReadbacks: number;
  /** Bytes uploaded to the view's context: bases and solutions (each once) and the CPU path's display maps. */
  uploadBytes: number;
  /** The last drawn frame: read-backs and bytes read back and uploaded since the frame before it. */
  frame: { readbacks: number; readbackBytes: number; uploadBytes: number };
  /** GPU texture memory the relight holds (bases, solutions, display targets). */
  textureBytes: number;
  /** Three's programs compiled before a frame draws them, without blocking (createCompileGate.ts): compiles started and finished, frames held for them, compiles finished when the first frame was drawn. */
  compiles: CompileCounters;
}

/** The GPU side of the viewer: the view's relight, what the CPU path showed last, the settle timer and the floor mask. */
export interface ViewerGpu {
  relight: ViewRelight;
  /** The layouts and geometry key of the last CPU show: a GPU relight draws onto those surfaces. */
  layouts: LitMaps['layouts'] | null;
  key: string | null;
  cpuRelights: number;
  cpuUploadBytes: number;
  settle: ReturnType<typeof setTimeout> | null;
  mask: { layout: SurfaceLayout; prepared: PreparedObjects | null; covered: Uint8Array } | null;
  /** A shaped room's floor weights in the atlas for the prepared objects in force (shapedFloorWeights.ts). */
  floorWeights: { prepared: PreparedObjects; weights: Float32Array | null } | null;
  pending: PendingStats | null;
  /** The work plane's height the host shows statistics for (setWorkPlane), or null: off. */
  workPlaneHeight: number | null;
  /** The work plane's part grids for the room, objects and height in force (workPlaneBases.ts). */
  plane: { room: BakeScene['room']; prepared: PreparedObjects | null; bases: WorkPlaneBases } | null;
  planePending: PendingStats | null;
  /** Counts at the previous frame (for the per-frame numbers). */
  lastTotals: { readbacks: number; readbackBytes: number; uploadBytes: number };
  frame: GpuViewStatus['frame'];
  /** The view was disposed: pending statistics are not polled any more. */
  disposed: boolean;
}

export function createViewerGpu(v: Pick<Viewer, 'renderer'>): ViewerGpu {
  return {
    relight: createViewRelight(v.renderer),
    layouts: null,
    key: null,
    cpuRelights: 0,
    cpuUploadBytes: 0,
    settle: null,
    mask: null,
    floorWeights: null,
    pending: null,
    workPlaneHeight: null,
    plane: null,
    planePending: null,
    lastTotals: { readbacks: 0, readbackBytes: 0, uploadBytes: 0 },
    frame: { readbacks: 0, readbackBytes: 0, uploadBytes: 0 },
    disposed: false,
  };
}

/** The CPU path showed these maps: GPU relights may follow on the same surfaces. */
export function noteCpuShow(g: ViewerGpu, lit: LitMaps, key: string): void {
  g.layouts = lit.layouts;
  g.key = key;
  g.cpuRelights++;
  g.cpuUploadBytes += displayUploadBytes(lit);
}

/** A shaped room's floor statistics from the atlas (shapedFloorWeights.ts), or null without the atlas or its floor. */
function shapedFloorStats(g: ViewerGpu, maps: ViewRelightMaps, prepared: PreparedObjects | null): PendingStats | null {
  if (!prepared) return null;
  if (!g.floorWeights || g.floorWeights.prepared !== prepared) g.floorWeights = { prepared, weights: shapedFloorWeights(prepared) };
  const { weights } = g.floorWeights;
  return weights ? g.relight.shapedFloorStats(maps, weights) : null;
}

function floorMask(g: ViewerGpu, layout: SurfaceLayout, prepared: PreparedObjects | null): Uint8Array {
  if (!g.mask || g.mask.layout !== layout || g.mask.prepared !== prepared) g.mask = { layout, prepared, covered: floorUnderObjects(layout, prepared) };
  return g.mask.covered;
}

/**
 * Show the engine's maps by the GPU combine when this is a relight of what is on screen: the same
 * geometry and layouts the CPU path showed last, not yet the final look (light not done, or a
 * crossfade under way), the eye held (so no exposure is taken from the
 * maps), no A/B compare, the relight's programs compiled (programsReady: never a wait on the driver), the textures within the device's budget. Returns false when the CPU path
 * must show them. Nothing is read back: the floor's statistics are requested (16 bytes after a
 * fence) and reported when they arrive; the CPU relight follows once after GPU_SETTLE_MS of quiet.
 */
export function showRelightOnGpu(v: Viewer, engine: RelightEngine, showOnCpu: () => void): boolean {
  const g = v.gpu;
  if (!v.scene || v.compare || !v.maps.held() || g.key !== sceneGeometryKey(v.scene)) return false;
  const parts = engine.relightParts();
  // The final look (done, no crossfade under way) is shown on the CPU at once: its statistics, legend and work plane are final with it.
  if (!parts || (engine.progress.done && parts.fade === null)) return false;
  // A room's first solve shows previews (not final solutions): bake progress, shown on the CPU as it was baked, not a relight.
  if (parts.terms.some((t) => !t.solution.final)) return false;
  if (parts.layouts !== g.layouts || !g.relight.ready() || !g.relight.fits(parts)) return false;
  const t0 = performance.now();
  const maps = g.relight.relight(parts);
  v.view.setLightTextures(maps.surfaces, maps.objects);
  v.events.onGpuRelight?.({ relightMs: performance.now() - t0 });
  // A room of any shape has its floor in the atlas: its texels there, each weighed by its coverage.
  g.pending = parts.layouts.floor.sink ? shapedFloorStats(g, maps, v.prepared) : g.relight.floorStats(maps, floorMask(g, parts.layouts.floor, v.prepared));
  if (g.pending) pollFloorStats(v, g.pending);
  requestWorkPlaneStats(v, parts);
  if (g.settle) clearTimeout(g.settle);
  g.settle = setTimeout(() => {
    g.settle = null;
    if (v.service.engine === engine) showOnCpu();
  }, GPU_SETTLE_MS);
  return true;
}

/** The work plane's part grids for the scene's room, the prepared objects and the height asked for (made anew when one of them changes). */
function workPlaneBasesOf(g: ViewerGpu, scene: BakeScene, prepared: PreparedObjects | null, height: number): WorkPlaneBases {
  const p = g.plane;
  if (!p || p.room !== scene.room || p.prepared !== prepared || p.bases.grid.height !== height) g.plane = { room: scene.room, prepared, bases: createWorkPlaneBases(scene, height, WORK_PLANE_SPACING, prepared) };
  return g.plane!.bases;
}

/** The work-plane grid spacing of the statistics (metres), as the CPU's (useWorkPlaneStats). */
export const WORK_PLANE_SPACING = 0.1;

/**
 * The work plane's statistics of this GPU relight (the plane on; a box room or one of any shape): its part grids combined
 * with the same weights and reduced (createViewRelight workPlaneStats), reported by onWorkPlaneStats
 * once read. Nothing is requested when a basis lacks its luminaires.
 */
function requestWorkPlaneStats(v: Viewer, parts: NonNullable<ReturnType<RelightEngine['relightParts']>>): void {
  const g = v.gpu;
  const height = g.workPlaneHeight;
  if (height === null || !v.scene) return;
  const pending = g.relight.workPlaneStats(parts, workPlaneBasesOf(g, v.scene, v.prepared, height));
  if (!pending) return;
  g.planePending = pending;
  pollStats(
    v,
    pending,
    () => g.planePending === pending,
    (stats) => {
      g.planePending = null;
      v.events.onWorkPlaneStats?.({ ...stats, height });
    },
  );
}

/**
 * Poll a floor statistics request once per animation frame until the GPU has finished it (never
 * waits). A request superseded by a newer one is still polled to its end (that frees its fence and
 * texel) but not reported.
 */
function pollFloorStats(v: Viewer, pending: PendingStats): void {
  pollStats(
    v,
    pending,
    () => v.gpu.pending === pending,
    (stats) => {
      v.gpu.pending = null;
      v.events.onFloorStats?.(stats);
    },
  );
}

/** Poll a statistics request once per animation frame until it is read; `report` it unless `current` says a newer one superseded it. */
function pollStats(v: Viewer, pending: PendingStats, current: () => boolean, report: (stats: IlluminanceStats) => void): void {
  const gpu = v.gpu;
  const relight = gpu.relight;
  const tick = () => {
    // A context lost and restored meanwhile: the request's objects belong to the disposed relight.
    if (gpu.relight !== relight || gpu.disposed) return;
    const stats = pending.poll();
    if (!stats) {
      requestAnimationFrame(tick);
      return;
    }
    if (current()) report(stats);
  };
  requestAnimationFrame(tick);
}

/** Cancel the settle timer (a CPU show replaces it, the view is disposed). */
export function cancelSettle(g: ViewerGpu): void {
  if (g.settle) clearTimeout(g.settle);
  g.settle = null;
  g.pending = null;
  g.planePending = null;
}

/** The counters of `view3d().gpu`, with the per-frame numbers of the last drawn frame. */
export function gpuViewStatus(g: ViewerGpu, compiles: CompileCounters): GpuViewStatus {
  const c = g.relight.counters;
  return {
    precision: g.relight.precision,
    gpuRelights: c.relights,
    cpuRelights: g.cpuRelights,
    mapReadbacks: c.mapReadbacks.count,
    mapReadbackBytes: c.mapReadbacks.bytes,
    statsReadbacks: c.statsReadbacks.count,
    uploadBytes: c.uploads.bytes + g.cpuUploadBytes,
    frame: { ...g.frame },
    textureBytes: g.relight.textureBytes(),
    compiles: { ...compiles },
  };
}

/** At each drawn frame: what was read back and uploaded since the previous one. */
export function countGpuFrame(g: ViewerGpu): void {
  const c = g.relight.counters;
  const now = { readbacks: c.mapReadbacks.count + c.statsReadbacks.count, readbackBytes: c.mapReadbacks.bytes + c.statsReadbacks.bytes, uploadBytes: c.uploads.bytes + g.cpuUploadBytes };
  g.frame = { readbacks: now.readbacks - g.lastTotals.readbacks, readbackBytes: now.readbackBytes - g.lastTotals.readbackBytes, uploadBytes: now.uploadBytes - g.lastTotals.uploadBytes };
  g.lastTotals = now;
}

/** The view is going: no more statistics polls, the relight's textures and programs freed. */
export function disposeViewerGpu(g: ViewerGpu): void {
  cancelSettle(g);
  g.disposed = true;
  g.relight.dispose();
}

/** After a context loss the relight's textures are gone: a fresh one (the next show is on the CPU). */
export function resetViewerGpu(v: Viewer): void {
  cancelSettle(v.gpu);
  v.gpu.relight.dispose();
  Object.assign(v.gpu, createViewerGpu(v), { cpuRelights: v.gpu.cpuRelights, cpuUploadBytes: v.gpu.cpuUploadBytes, workPlaneHeight: v.gpu.workPlaneHeight });
}
