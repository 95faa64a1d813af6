import { useEffect, useRef, type RefObject } from 'react';
import type { BakeScene } from '../../engines/bake/bakeScene';
import type { LitMaps } from '../../engines/relight/relightMaps';
import type { ViewerController } from '../../engines/view/createViewerController';
import { workPlaneStats, type IlluminanceStats } from '../../engines/view/lightStats';
import type { ViewerStatus } from './viewerStatus';
import type { WorkPlane } from './WorkPlaneField';

export interface WorkPlaneStatsSetup {
  plane: WorkPlane;
  mapsVersion: number;
  done: boolean;
  sceneRef: RefObject<BakeScene | null>;
  litRef: RefObject<LitMaps | null>;
  controllerRef: RefObject<ViewerController | null>;
  /** Bumped when a controller is made (a fresh one must be told the plane). */
  controllerVersion: number;
  setPlaneStats(stats: IlluminanceStats | null): void;
  publish(patch: Partial<ViewerStatus>): void;
}

/**
 * The work plane's statistics (null: off, or no maps yet). The controller is told the plane, so each
 * GPU relight (crossfade, dimming drag, DMX stream) brings its statistics from the GPU reduction
 * (onWorkPlaneStats, useViewerController). The CPU maps' statistics are recomputed when the maps
 * settle or the height changes (direct part on the CPU); while the bake runs, 400 ms after the last change.
 */
export function useWorkPlaneStats({ plane, mapsVersion, done, sceneRef, litRef, controllerRef, controllerVersion, setPlaneStats, publish }: WorkPlaneStatsSetup): void {
  // The status record's publish is made anew each render: read through a ref, so it does not restart the timer.
  const publishRef = useRef(publish);
  useEffect(() => {
    publishRef.current = publish;
  });
  useEffect(() => {
    controllerRef.current?.setWorkPlane(plane.on ? plane.height : null);
  }, [plane, controllerRef, controllerVersion]);
  useEffect(() => {
    if (!plane.on || !litRef.current || !sceneRef.current) {
      setPlaneStats(null);
      publishRef.current({ plane: null });
      return;
    }
    const t = setTimeout(
      () => {
        const s = workPlaneStats(sceneRef.current!, litRef.current!, plane.height, 0.1, {}, controllerRef.current?.objects() ?? null);
        setPlaneStats(s);
        publishRef.current({ plane: { height: plane.height, avg: s.avg, min: s.min, max: s.max, u0: s.u0, source: 'cpu' } });
      },
      done ? 0 : 400,
    );
    return () => clearTimeout(t);
  }, [plane, mapsVersion, done, sceneRef, litRef, controllerRef, setPlaneStats]);
}
