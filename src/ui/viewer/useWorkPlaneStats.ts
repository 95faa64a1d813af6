import { useEffect, useState, type RefObject } from 'react';
import type { BakeScene } from '../../engines/bake/bakeScene';
import type { LitMaps } from '../../engines/relight/relightMaps';
import type { ViewerController } from '../../engines/view/createViewerController';
import { workPlaneStats, type IlluminanceStats } from '../../engines/view/lightStats';
import type { WorkPlane } from './WorkPlaneField';

/**
 * The work plane's statistics (null: off, or no maps yet): recomputed when the maps settle or the
 * height changes (direct part on the CPU); while the bake runs, 400 ms after the last change.
 */
export function useWorkPlaneStats(plane: WorkPlane, mapsVersion: number, done: boolean, sceneRef: RefObject<BakeScene | null>, litRef: RefObject<LitMaps | null>, controllerRef: RefObject<ViewerController | null>): IlluminanceStats | null {
  const [planeStats, setPlaneStats] = useState<IlluminanceStats | null>(null);
  useEffect(() => {
    if (!plane.on || !litRef.current || !sceneRef.current) {
      setPlaneStats(null);
      return;
    }
    const t = setTimeout(() => setPlaneStats(workPlaneStats(sceneRef.current!, litRef.current!, plane.height, 0.1, {}, controllerRef.current?.objects() ?? null)), done ? 0 : 400);
    return () => clearTimeout(t);
  }, [plane, mapsVersion, done, sceneRef, litRef, controllerRef]);
  return planeStats;
}
