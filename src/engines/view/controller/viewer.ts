import type * as THREE from 'three';
import type { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import type { BakeScene } from '../../bake/bakeScene';
import type { PreparedObjects } from '../../bake/objects/preparedObjects';
import type { ModuleAim } from '../../../core/model/configuration/configuration';
import type { Vec3 } from '../../../core/model/lightingScene/lightingScene';
import type { BakeService } from '../createBakeService';
import type { CameraRig } from '../createCameraRig';
import type { FrameScheduler } from '../createFrameScheduler';
import type { MapDisplay, MapsListener } from '../createMapDisplay';
import type { Spotlight, SpotlightRequest } from '../createSpotlight';
import type { Fixtures } from '../fixtures';
import type { LiveLevel } from '../liveLevels';
import type { PickTarget, RoomView } from '../roomView';
import type { ContextWatch } from '../watchContextLoss';
import type { IlluminanceStats } from '../lightStats';
import type { ViewerGpu } from './gpuRelightFrame';

/** The A/B compare (docs/viewer.md, "A/B compare"): two light scenes of the configuration, A left of the wipe at `split` (0…1 of the width), B right of it. */
export interface CompareRequest {
  a: BakeScene;
  b: BakeScene;
  split: number;
}

export interface ViewerEvents {
  /** Bake progress and counters changed. */
  onProgress(p: { fraction: number; done: boolean; lit: boolean; groupBakes: number; relightsOnly: number; indirectSolves: number }): void;
  /** New relit maps are on screen (for statistics and the legend). */
  onMaps: MapsListener;
  /** A relight combined on the GPU is on screen (no CPU maps: createViewRelight.ts); `relightMs` is the time its draws took to issue. */
  onGpuRelight?(info: { relightMs: number }): void;
  /** The floor's statistics of the GPU relight on screen, once its reduction is read (createGpuStats.ts). */
  onFloorStats?(stats: IlluminanceStats): void;
  /** The work plane's statistics (at `height`, set by setWorkPlane) of the GPU relight on screen, once its reduction is read. */
  onWorkPlaneStats?(stats: IlluminanceStats & { height: number }): void;
  onFrame(frames: number): void;
  onContext(state: 'lost' | 'restored'): void;
  onError(message: string): void;
  /** A tap or click picked an object or a module (null: nothing, or only the room). */
  onPick?(target: PickTarget | null): void;
  /** A drag in the spotlight view ended on a new aim (docs/aiming.md): the host dispatches setAim. */
  onAim?(moduleId: string, aim: ModuleAim): void;
  /** In aim-at mode, a tap hit this world point of the room or an object: the host dispatches aimAt. */
  onAimAt?(point: Vec3): void;
}

/** What the viewer controller's pieces change as the host and the bake service talk to it. */
export interface ViewerState {
  /** The room on screen; rebuilt when the WebGL context comes back. */
  view: RoomView;
  /** The A/B compare, or null; its B side is a second room view over the same renderer, camera pose and display uniforms. */
  compare: CompareRequest | null;
  compareView: RoomView | null;
  /**
   * Veiling glare round bright sources in light mode (docs/viewer.md, "Glare"); lux mode never shows
   * it. Drawn once the configuration's light is done (`lightDone`): while it bakes, frames come with
   * every slice and the pass's extra passes would take the bake's time on a slow GPU (a software
   * renderer's frames cost several times more with it).
   */
  glare: boolean;
  lightDone: boolean;
  scene: BakeScene | null;
  /** Module id per luminaire of `scene`, for the live overlay. */
  ids: readonly string[];
  /** Live control's levels over the scene's own dimming (transient: never in the configuration), or null. */
  live: ReadonlyMap<string, LiveLevel> | null;
  /** The module the spotlight view's preview lights from the shader while it is dragged (out of the relit maps), or null. */
  dimmed: string | null;
  /** Aim-at mode: the next tap aims the selected module at the point instead of picking. */
  aimAt: boolean;
  /** The spotlight view the host asked for; shown once the scene has the module's luminaire (its beam and field come from its photometry). */
  spotRequest: SpotlightRequest | null;
  fixtures: Fixtures | null;
  /** The engine version on screen; -1 forces the next slice to show the maps. */
  shownVersion: number;
  /** The objects' geometry as the baker lays out their atlas (null: no objects; the service's), and the highlighted one. */
  prepared: PreparedObjects | null;
  selectedObject: string | null;
  selectedModule: string | null;
  /** False while the view is kept but hidden (the 2D plan is on screen): no frames are drawn. */
  active: boolean;
}

/** The viewer controller's state with the parts it drives (createViewerController wires them). */
export interface Viewer extends ViewerState {
  readonly renderer: THREE.WebGLRenderer;
  readonly service: BakeService;
  readonly events: ViewerEvents;
  readonly controls: OrbitControls;
  readonly display: ContextWatch;
  readonly frames: FrameScheduler;
  readonly camera: CameraRig;
  readonly spotlight: Spotlight;
  readonly maps: MapDisplay;
  /** The relight in the view's context and its counters (gpuRelightFrame.ts). */
  readonly gpu: ViewerGpu;
}

/** A viewer before any scene: glare on, nothing shown yet. */
export function initialViewerState(view: RoomView): ViewerState {
  return {
    view,
    compare: null,
    compareView: null,
    glare: true,
    lightDone: false,
    scene: null,
    ids: [],
    live: null,
    dimmed: null,
    aimAt: false,
    spotRequest: null,
    fixtures: null,
    shownVersion: -1,
    prepared: null,
    selectedObject: null,
    selectedModule: null,
    active: true,
  };
}

/** Whether glare shows now: switched on, and the light done. */
export function glareNow(v: ViewerState): boolean {
  return v.glare && v.lightDone;
}

/** Glare on both room views as glareNow says. */
export function syncGlare(v: ViewerState): void {
  v.view.setGlare(glareNow(v));
  v.compareView?.setGlare(glareNow(v));
}
