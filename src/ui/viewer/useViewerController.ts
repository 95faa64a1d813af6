import { useEffect, type Dispatch, type RefObject, type SetStateAction } from 'react';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { BakeScene } from '../../engines/bake/bakeScene';
import type { LitMaps } from '../../engines/relight/relightMaps';
import type { QualityLevel } from '../../engines/relight/qualityLevels';
import { createViewerController, type ViewerController, type ViewerEvents } from '../../engines/view/createViewerController';
import { floorStats, type IlluminanceStats } from '../../engines/view/lightStats';
import { objectLightOf } from '../../engines/view/objectLight';
import { objectStats } from '../../engines/view/objectStats';
import type { PhotometryNote } from '../shared/PhotometryWarnings';
import type { BakeHost } from './bakeHost';
import type { BakeFeed, ResolvedScene } from './startBakeFeed';
import { aimEvents } from './SpotlightControls';
import type { ViewerStatusRecord } from './useViewerStatus';
import type { ViewerStatus } from './viewerStatus';

/** What View3D shows of the controller's events (its state setters). */
export interface ViewerShown {
  setProgress(p: { fraction: number; done: boolean; lit: boolean }): void;
  setLevels(levels: number[]): void;
  setFloor(floor: IlluminanceStats | null): void;
  setPlaneStats(stats: IlluminanceStats | null): void;
  setMapsVersion: Dispatch<SetStateAction<number>>;
  setLost(lost: boolean): void;
  setError(message: string | null): void;
  setControllerVersion: Dispatch<SetStateAction<number>>;
  setPhotometryNotes(notes: PhotometryNote[]): void;
  setQuality(level: QualityLevel): void;
}

/** What the controller's owner hands it: the feed, the DOM, the refs the rest of the view reads, the status record and the setters. */
export interface ViewerControllerSetup {
  feed: BakeFeed | null;
  store: ConfiguratorStore;
  host: BakeHost;
  canvasRef: RefObject<HTMLCanvasElement | null>;
  wrapRef: RefObject<HTMLDivElement | null>;
  controllerRef: RefObject<ViewerController | null>;
  /** The scene and the maps on screen (the work plane's statistics read them). */
  sceneRef: RefObject<BakeScene | null>;
  litRef: RefObject<LitMaps | null>;
  glareRef: RefObject<boolean>;
  record: ViewerStatusRecord;
  shown: ViewerShown;
}

/** The controller's events: progress, maps (floor and object statistics), frames (first lit), context, errors, picks and aims. */
function viewerEvents({ store, controllerRef, litRef, record, shown }: ViewerControllerSetup): ViewerEvents {
  const { status, mountedAt, framesAtShow, publish } = record;
  return {
    onProgress: (p) => {
      shown.setProgress({ fraction: p.fraction, done: p.done, lit: p.lit });
      publish({ progress: p.fraction, done: p.done, groupBakes: p.groupBakes, relightsOnly: p.relightsOnly });
    },
    onMaps: (lit, info) => {
      litRef.current = lit;
      shown.setLevels(info.levels);
      const prepared = controllerRef.current?.objects() ?? null;
      // The floor a person sees: the texels under furniture standing on it are left out (docs/viewer.md).
      const f = floorStats(lit, prepared);
      shown.setFloor(f);
      shown.setMapsVersion((v) => v + 1);
      const light = objectLightOf(lit);
      const objects = prepared && light && light.atlas.width === prepared.atlas.width && light.atlas.height === prepared.atlas.height ? objectStats(lit, prepared, light) : null;
      publish({ lastRelightMs: info.relightMs, floor: { avg: f.avg, min: f.min, max: f.max, u0: f.u0 }, objects });
    },
    // A relight on the GPU: no CPU maps; the floor's statistics arrive from the GPU reduction, the rest with the settled CPU relight.
    onGpuRelight: (info) => publish({ lastRelightMs: info.relightMs, gpu: controllerRef.current?.gpuStatus() ?? null }),
    onFloorStats: (f) => {
      shown.setFloor(f);
      publish({ floor: { avg: f.avg, min: f.min, max: f.max, u0: f.u0 }, gpu: controllerRef.current?.gpuStatus() ?? null });
    },
    onWorkPlaneStats: (p) => {
      shown.setPlaneStats(p);
      publish({ plane: { height: p.height, avg: p.avg, min: p.min, max: p.max, u0: p.u0, source: 'gpu' }, gpu: controllerRef.current?.gpuStatus() ?? null });
    },
    onFrame: (frames) => {
      const patch: Partial<ViewerStatus> = { frames, compare: controllerRef.current?.compareState() ?? null, gpu: controllerRef.current?.gpuStatus() ?? null };
      if (!status.current.lit && litRef.current) {
        patch.lit = true;
        patch.firstLitMs = performance.now() - mountedAt.current;
        patch.firstLitFrame = frames - framesAtShow.current;
      }
      publish(patch);
    },
    onContext: (state) => {
      shown.setLost(state === 'lost');
      if (state === 'lost') publish({ contextLosses: status.current.contextLosses + 1 });
    },
    onError: (message) => {
      shown.setError(message);
      publish({ error: message });
    },
    // A tap on an object or a module selects it, as a tap in the plan does; a tap on the room clears the selection.
    onPick: (target) => store.getState().select(target),
    // Aiming (docs/aiming.md): a drag in the spotlight view, a tap in aim-at mode.
    ...aimEvents(store),
  };
}

/** The page's exposure and adaptation and the view's glare switch on a new controller. */
function applyPageSettings(controller: ViewerController, { host, glareRef }: ViewerControllerSetup): void {
  // A fixed EV100 from the page (embed option `exposure`) holds from the first frame.
  if (typeof host.exposure === 'number') controller.setEv100(host.exposure);
  // The chromatic adaptation the page asked for (embed option `adapt`, default eye).
  controller.setAdaptation(host.adaptation);
  controller.setGlare(glareRef.current);
}

/**
 * The viewer controller (engines/view) for the feed's service, made once the feed is there and
 * disposed with the view (the display only: the service keeps its engine, maps and pending bake).
 * It shows every configuration the feed resolves.
 */
export function useViewerController(setup: ViewerControllerSetup): void {
  const { feed, controllerRef, canvasRef, wrapRef, sceneRef, record, shown } = setup;
  useEffect(() => {
    if (!feed) return;
    const canvas = canvasRef.current!;
    let controller: ViewerController;
    try {
      controller = createViewerController(canvas, feed.service, viewerEvents(setup));
    } catch (e) {
      const message = `The 3D view could not start: ${(e as Error).message}`;
      record.publish({ error: message });
      queueMicrotask(() => shown.setError(message));
      return;
    }
    applyPageSettings(controller, setup);
    controllerRef.current = controller;
    queueMicrotask(() => shown.setControllerVersion((v) => v + 1));
    // Made while hidden (the feed arrived after the user went back to the plan): no frames until shown.
    controller.setActive(record.visibleRef.current);
    const wrap = wrapRef.current!;
    const ro = new ResizeObserver(() => {
      const r = wrap.getBoundingClientRect();
      // Hidden behind the plan the box is 0 × 0: keep the last size (the next show resizes anyway).
      if (r.width > 0 && r.height > 0) controller.resize(Math.round(r.width), Math.round(r.height));
    });
    ro.observe(wrap);
    // Every configuration the feed resolved (and handed to the service): the room, fixtures and objects on screen.
    const show = (r: ResolvedScene | null) => {
      if (!r) return;
      sceneRef.current = r.bake;
      controller.setScene(r.bake, r.fixtures, r.ids);
      shown.setPhotometryNotes(r.notes);
    };
    show(feed.latest());
    // The level the service runs at (the device's calibration picks it when nobody chose one).
    const level = feed.service.quality;
    queueMicrotask(() => shown.setQuality(level));
    const failed = feed.error();
    if (failed) queueMicrotask(() => shown.setError(failed));
    const unsubscribe = feed.subscribe(() => {
      shown.setError(feed.error());
      if (!feed.error()) show(feed.latest());
    });
    return () => {
      unsubscribe();
      ro.disconnect();
      // The display only: the service keeps the engine, the maps and any pending bake.
      controller.dispose();
      controllerRef.current = null;
    };
    // eslint-disable-next-line react-hooks/exhaustive-deps
  }, [feed]);
}
