import { useEffect, useState, type RefObject } from 'react';
import { DAYLIGHT_FACTOR_SKY_ILLUMINANCE, daylightFactorLuxLevels } from '../../core/daylight/daylightFactor';
import type { BakeScene } from '../../engines/bake/bakeScene';
import { daylightFactorDaylight, workPlaneDaylight, workPlaneDaylightFactorStatistics } from '../../engines/bake/daylight/workPlaneDaylightFactor';
import type { PreparedObjects } from '../../engines/bake/objects/preparedObjects';
import type { LightSources } from '../../engines/relight/daylightGroups';
import type { LitMaps } from '../../engines/relight/relightMaps';
import type { ViewerController } from '../../engines/view/createViewerController';
import type { ViewerStatus } from './viewerStatus';

export type DaylightFactorValues = NonNullable<ViewerStatus['daylightFactor']>;

export interface DaylightFactorViewSetup {
  /** Whether the mode may be chosen: daylight on and a window in the room. */
  available: boolean;
  /** The panel's choice, shown again when the mode is left. */
  lightSources: 'electric' | 'daylight' | 'both';
  controllerRef: RefObject<ViewerController | null>;
  controllerVersion: number;
  sceneRef: RefObject<BakeScene | null>;
  litRef: RefObject<LitMaps | null>;
  mapsVersion: number;
  done: boolean;
  publish(patch: Partial<ViewerStatus>): void;
}

/**
 * The work plane's DF from the maps on screen (the overcast basis alone, lux under
 * DAYLIGHT_FACTOR_SKY_ILLUMINANCE) with the report's own functions, or null when the scene has
 * no daylight or the maps have no atlas; `prepared`: the enclosed scene's objects the maps were baked on (the service's).
 */
export function daylightFactorOfView(scene: BakeScene, lit: LitMaps, prepared: PreparedObjects | null): DaylightFactorValues | null {
  const light = lit.maps.objects;
  if (!scene.daylight || !prepared || !light || light.total.length === 0) return null;
  const lux = workPlaneDaylight(scene, prepared, light, daylightFactorDaylight(scene.daylight));
  const s = workPlaneDaylightFactorStatistics(lux, DAYLIGHT_FACTOR_SKY_ILLUMINANCE);
  if (!s) return null;
  return { mean: s.average, min: s.minimum, max: s.maximum, u0: s.uniformity, median: s.median, shareAbove2: s.shareAtTarget, shareAbove07: s.shareAtMinimumTarget, points: lux.length };
}

/**
 * The 3D view's daylight-factor mode (docs/viewer.md, "Daylight factor"): on, the engine shows the
 * overcast basis alone ('daylight-factor') with the legend fixed at DAYLIGHT_FACTOR_LEVELS; off (or
 * no longer available), the panel's light sources and the maps' own levels again. The work plane's
 * DF is computed when the maps settle.
 */
export function useDaylightFactorView(setup: DaylightFactorViewSetup) {
  const { available, lightSources, controllerRef, controllerVersion, sceneRef, litRef, mapsVersion, done, publish } = setup;
  const [chosen, setChosen] = useState(false);
  const [values, setValues] = useState<DaylightFactorValues | null>(null);
  const on = chosen && available;
  useEffect(() => {
    const c = controllerRef.current;
    if (!c) return;
    const sources: LightSources = on ? 'daylight-factor' : lightSources;
    c.setLightSources(sources);
    c.setLuxLevels(on ? daylightFactorLuxLevels() : null);
  }, [on, lightSources, controllerRef, controllerVersion]);
  useEffect(() => {
    if (!on || !done || !sceneRef.current || !litRef.current || !controllerRef.current) {
      setValues(null);
      publish({ daylightFactor: null });
      return;
    }
    const v = daylightFactorOfView(sceneRef.current, litRef.current, controllerRef.current.objects());
    setValues(v);
    publish({ daylightFactor: v });
    // publish is made anew each render; the values follow the maps, not the record.
    // eslint-disable-next-line react-hooks/exhaustive-deps
  }, [on, done, mapsVersion, sceneRef, litRef, controllerRef]);
  return { on, values, choose: setChosen };
}
