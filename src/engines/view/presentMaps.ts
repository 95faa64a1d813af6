import type { Rgb, SurfaceName } from '../../core/model/lightingScene';
import type { LitMaps } from '../relight/relightMaps';
import { autoExposure } from './autoExposure';
import { luxLevels } from './falseColorScale';
import { luxScaleTop } from './luxScaleTop';
import { objectLightOf } from './objectLight';
import { ev100FromExposure, exposureFromEv100 } from './photographicExposure';
import type { RoomView, ViewMode } from './roomView';

/**
 * How the maps are shown: light or lux, and the exposure: automatic with a
 * compensation in stops (`exposureEv`), or absolute when `ev100` is a number
 * (photographicExposure.ts; then the compensation is not used).
 */
export interface DisplaySettings {
  exposureEv: number;
  ev100?: number | null;
  mode: ViewMode;
}

/** What presentMaps derived from the maps: the automatic exposure, the one applied, its EV100, the legend levels. */
export interface PresentedMaps {
  autoExposure: number;
  exposure: number;
  /** EV100 of the applied exposure (ev100FromExposure): the value "lock exposure" keeps. */
  ev100: number;
  levels: number[];
}

/** The exposure applied: 1 / (1.2 · 2^EV100) when an EV100 is fixed, else auto · 2^compensation. */
export function appliedExposure(auto: number, display: Pick<DisplaySettings, 'exposureEv' | 'ev100'>): number {
  return typeof display.ev100 === 'number' ? exposureFromEv100(display.ev100) : auto * 2 ** display.exposureEv;
}

/**
 * Put relit maps on a room view as the viewer shows them (docs/viewer.md,
 * "Display"): the maps and reflectances, automatic exposure times the
 * compensation (or the fixed EV100's exposure), and the mode with lux levels up to the maps' 99th percentile.
 * The objects' light (when the maps have it) goes to the objects and counts in
 * the exposure and the percentile by its area. The browser viewer and
 * `luxbox render` both draw through this.
 */
export function presentMaps(view: RoomView, lit: LitMaps, reflectance: Record<SurfaceName, Rgb>, display: DisplaySettings): PresentedMaps {
  view.setMaps(lit, reflectance);
  const objects = objectLightOf(lit);
  view.setObjectLight(objects);
  const auto = autoExposure(lit, reflectance, objects);
  const exposure = appliedExposure(auto, display);
  view.setExposure(exposure);
  const levels = luxLevels(luxScaleTop(lit, 0.99, objects));
  view.setMode(display.mode, levels);
  return { autoExposure: auto, exposure, ev100: ev100FromExposure(exposure), levels };
}
