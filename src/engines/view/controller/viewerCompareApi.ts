import { showMaps, syncWeights } from './showViewerMaps';
import type { CompareRequest, Viewer } from './viewer';

/** The viewer controller's methods for the A/B compare (docs/viewer.md, "A/B compare"). */
export function viewerCompareApi(v: Viewer) {
  return {
    /**
     * The A/B compare of two light scenes (same luminaires as the scene, other dimming and colour),
     * or null to end it: A left of the wipe, B right, both at the exposure and adaptation held now.
     */
    setCompare(request: CompareRequest | null) {
      const compare = v.compare;
      const scenesChanged = !compare || !request || compare.a !== request.a || compare.b !== request.b;
      v.compare = request;
      if (!request) {
        v.compareView?.dispose();
        v.compareView = null;
      }
      if (scenesChanged) {
        v.shownVersion = -1;
        const engine = v.service.engine;
        if (engine && (engine.progress.lit || engine.progress.done)) showMaps(v, engine);
        if (!request) syncWeights(v);
      }
      v.frames.request();
    },
    /** The compare drawn last: both sides' exposures (the same by construction) and the wipe, or null. */
    compareState(): { exposureA: number; exposureB: number; split: number } | null {
      if (!v.compare || !v.compareView) return null;
      return { exposureA: v.view.display.uExposure.value, exposureB: v.compareView.display.uExposure.value, split: v.compare.split };
    },
  };
}
