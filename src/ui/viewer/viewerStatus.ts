import type { BakeStatus } from '../../engines/view/createBakeService';
import type { GpuViewStatus } from '../../engines/view/controller/gpuRelightFrame';

/**
 * What the 3D view reports about itself, readable without loading three.js
 * (window.luxbox.view3d() in the app; the e2e tests wait on it). Keyed by the
 * configurator store, so several embedded configurators keep separate status.
 */
export interface ViewerStatus {
  /** The 3D view is mounted. */
  open: boolean;
  /** A first lit frame has been drawn for the current scene. */
  lit: boolean;
  /** Every group's basis is final (progressive refinement finished). */
  done: boolean;
  /** 0..1 of the bake work for the current scene. */
  progress: number;
  /** Group bakes started since the view opened (a relight-only change leaves it unchanged). */
  groupBakes: number;
  /** Scene changes served by a relight alone. */
  relightsOnly: number;
  /** Frames drawn (render on demand: stays still while idle). */
  frames: number;
  /** Milliseconds from mounting the view to the first lit frame (null until then). */
  firstLitMs: number | null;
  /**
   * Which frame since mounting was the first lit one (null until then): 1 when the view opened on
   * light the service had already baked (nothing was waited for).
   */
  firstLitFrame: number | null;
  /** Milliseconds of the last relight (weighted sum + texture upload on the CPU path; the combine's draws on the GPU path). */
  lastRelightMs: number | null;
  /** WebGL contexts lost and recovered. */
  contextLosses: number;
  /** Why 3D is unavailable, or null. */
  error: string | null;
  /** Floor statistics in lux (null until lit). */
  floor: { avg: number; min: number; max: number; u0: number } | null;
  /**
   * Work-plane statistics in lux while the work plane is on (null: off, or not computed yet), and
   * where they came from: `gpu`, the reduction that follows each GPU relight (a crossfade, a dimming
   * drag, a DMX stream; docs/viewer.md "Work-plane statistics on the GPU"), or `cpu`, the formula
   * on the settled maps.
   */
  plane: { height: number; avg: number; min: number; max: number; u0: number; source: 'gpu' | 'cpu' } | null;
  /**
   * The work plane's daylight factor (%) in the daylight-factor view, null elsewhere or before the
   * maps settle: mean, min, U0 = min / mean, median and EN 17037's shares (0 … 1) of the plane at
   * DF ≥ 2 % (300 lx at 15 klx) and ≥ 0.7 %, as `luxbox bake`'s report computes them
   * (engines/bake/daylight/workPlaneDaylightFactor.ts; docs/daylight.md).
   */
  daylightFactor: { mean: number; min: number; max: number; u0: number; median: number; shareAbove2: number; shareAbove07: number; points: number } | null;
  /**
   * Live control (docs/live-control.md), null while off: the bridge connection, frames
   * received, and overlays applied to the view (at most one per animation frame, only when
   * the levels changed).
   */
  live: { state: 'connecting' | 'connected' | 'no-bridge' | 'lost'; received: number; applied: number } | null;
  /** The A/B compare of two light scenes drawn last (docs/viewer.md, "A/B compare"): each side's exposure and the wipe, or null. */
  compare: { exposureA: number; exposureB: number; split: number } | null;
  /**
   * Per object once its light is on screen (null before, or without objects): mean lux over the
   * object, over its top (null if it has no flat top) and of the floor under its plan bounds
   * (src/engines/view/objectStats.ts).
   */
  objects: { id: string; avg: number; top: number | null; floorUnder: number | null }[] | null;
  /**
   * The background bake service (docs/viewer.md, "Always ready: the bake service"), readable while
   * 3D is closed: work pending and not paused, paused (page hidden), done, its counters since the
   * configurator started, and the quality level.
   */
  bake: BakeStatus;
  /**
   * The relight in the view's context (docs/viewer.md, "Relighting on the GPU"), null while closed:
   * GPU and CPU relights, maps and statistics texels read back, bytes uploaded, the last frame's
   * read-backs and bytes, the texture memory held and the bases' precision.
   */
  gpu: GpuViewStatus | null;
}

const statuses = new WeakMap<object, ViewerStatus>();
const bakeSources = new WeakMap<object, () => BakeStatus>();

/** The bake status before a service exists. */
export const IDLE_BAKE: BakeStatus = { running: false, paused: false, done: false, groupBakes: 0, relightsOnly: 0, indirectSolves: 0, restarts: 0, quality: 'balanced' };

export const CLOSED_STATUS: ViewerStatus = {
  open: false,
  lit: false,
  done: false,
  progress: 0,
  groupBakes: 0,
  relightsOnly: 0,
  frames: 0,
  firstLitMs: null,
  firstLitFrame: null,
  lastRelightMs: null,
  contextLosses: 0,
  error: null,
  floor: null,
  plane: null,
  daylightFactor: null,
  live: null,
  compare: null,
  objects: null,
  bake: IDLE_BAKE,
  gpu: null,
};

export function setViewerStatus(owner: object, status: ViewerStatus): void {
  statuses.set(owner, status);
}

/** Where the bake part of the status comes from (the bake host), or null to remove it. */
export function setBakeStatusSource(owner: object, source: (() => BakeStatus) | null): void {
  if (source) bakeSources.set(owner, source);
  else bakeSources.delete(owner);
}

export function getViewerStatus(owner: object): ViewerStatus {
  const bake = bakeSources.get(owner)?.() ?? IDLE_BAKE;
  return { ...(statuses.get(owner) ?? CLOSED_STATUS), bake: { ...bake } };
}
