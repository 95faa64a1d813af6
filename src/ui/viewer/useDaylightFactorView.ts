import { useEffect, useRef, useState, type RefObject } from 'react';
import { DAYLIGHT_FACTOR_SKY_ILLUMINANCE, daylightFactorLuxLevels } from '../../core/daylight/daylightFactor';
import type { BakeScene } from '../../engines/bake/bakeScene';
import { daylightFactorDaylight, workPlaneDaylight, workPlaneDaylightFactorStatistics } from '../../engines/bake/daylight/workPlaneDaylightFactor';
import type { PreparedObjects } from '../../engines/bake/objects/preparedObjects';
import type { LightSources } from '../../engines/relight/daylightGroups';
import type { LitMaps } from '../../engines/relight/relightMaps';
import type { ViewerController } from '../../engines/view/createViewerController';
import type { ViewerStatus } from './viewerStatus';

/** How often the mode looks for settled light (ms): a basis bake takes a fraction of a second to seconds. */
const SETTLE_POLL_MS = 300;

export type DaylightFactorValues = NonNullable<ViewerStatus['daylightFactor']>;

export interface DaylightFactorViewSetup {
  /** Whether the mode may be chosen: daylight on and a window in the room. */
  available: boolean;
  /**
   * The view is on screen: only then does it hand its light sources to the shared bake service (the
   * plan's daylight-factor overlay hands its own while the plan is shown); shown again, it hands them again.
   */
  visible: boolean;
  /** The panel's choice, shown again when the mode is left. */
  lightSources: 'electric' | 'daylight' | 'both';
  controllerRef: RefObject<ViewerController | null>;
  controllerVersion: number;
  sceneRef: RefObject<BakeScene | null>;
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
  return daylightFactorValuesOf(workPlaneDaylight(scene, prepared, light, daylightFactorDaylight(scene.daylight)));
}

/** The DF statistics shown (the 3D view's table, the plan's overlay) of work-plane lux under the overcast sky of DAYLIGHT_FACTOR_SKY_ILLUMINANCE; null without points. */
export function daylightFactorValuesOf(lux: ArrayLike<number>): DaylightFactorValues | null {
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
  const { available, visible, lightSources, controllerRef, controllerVersion, sceneRef, publish } = setup;
  const [chosen, setChosen] = useState(false);
  const [values, setValues] = useState<DaylightFactorValues | null>(null);
  const on = chosen && available;
  // The status record's publish is made anew each render: read through a ref, so it does not restart the poll.
  const publishRef = useRef(publish);
  useEffect(() => {
    publishRef.current = publish;
  });
  useEffect(() => {
    const c = controllerRef.current;
    if (!c || !visible) return;
    const sources: LightSources = on ? 'daylight-factor' : lightSources;
    c.setLightSources(sources);
    c.setLuxLevels(on ? daylightFactorLuxLevels() : null);
  }, [on, visible, lightSources, controllerRef, controllerVersion]);
  // The work plane's DF once the overcast basis is baked and solved: the engine's settled version is
  // polled (a GPU relight shows new light without new CPU maps), and its maps are summed once per version.
  useEffect(() => {
    if (!on) {
      publishRef.current({ daylightFactor: null });
      return;
    }
    let computed: number | null = null;
    const poll = () => {
      const c = controllerRef.current;
      const version = c?.settledVersion() ?? null;
      if (!c || version === null || version === computed || !sceneRef.current) return;
      const lit = c.settledMaps();
      if (!lit) return;
      computed = version;
      const v = daylightFactorOfView(sceneRef.current, lit, c.objects());
      setValues(v);
      publishRef.current({ daylightFactor: v });
    };
    poll();
    const timer = setInterval(poll, SETTLE_POLL_MS);
    return () => {
      clearInterval(timer);
      setValues(null);
    };
  }, [on, sceneRef, controllerRef, controllerVersion]);
  return { on, values: on ? values : null, choose: setChosen };
}
