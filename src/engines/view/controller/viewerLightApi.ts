import type { LightSources } from '../../relight/daylightGroups';
import type { LitMaps } from '../../relight/relightMaps';
import type { Viewer } from './viewer';
import { syncWindows } from './viewerSceneApi';

/** The viewer controller's methods for which light is shown (issue 30): the light sources, the false colour's fixed levels, the settled maps. */
export function viewerLightApi(v: Viewer) {
  return {
    /**
     * Which light the view shows: 'electric', 'daylight' (the sky and the sun through the windows),
     * 'both' or 'daylight-factor' (lux / 100 = DF %) (issue 30, docs/daylight.md "Daylight in the relight engine"). The bake service's
     * engine re-weights its bases (never a bake); the view draws the relight it announces.
     */
    setLightSources(sources: LightSources) {
      v.service.setLightSources(sources);
      syncWindows(v);
    },
    /** The engine's version once its light has settled (every basis baked, the solve done), else null: when a reader of `settledMaps` has something new. */
    settledVersion(): number | null {
      const engine = v.service.engine;
      return engine && engine.progress.done ? engine.version : null;
    },
    /** The engine's maps at the weights shown, summed on the CPU (null without an engine): for statistics that read the atlas (the daylight factor's work plane). */
    settledMaps(): LitMaps | null {
      return v.service.engine?.maps() ?? null;
    },
    lightSources(): LightSources {
      return v.service.lightSources;
    },
    /** Fixed false-colour levels in lux (the daylight-factor view's, core/daylight/daylightFactor.ts), or null: levels from the maps again. */
    setLuxLevels(levels: readonly number[] | null) {
      v.maps.setFixedLevels(levels);
      v.frames.request();
    },
  };
}
