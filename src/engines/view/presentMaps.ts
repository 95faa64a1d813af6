import type { Rgb, SurfaceName } from '../../core/model/lightingScene';
import type { LitMaps } from '../relight/relightMaps';
import { autoExposure } from './autoExposure';
import { luxLevels } from './falseColorScale';
import { luxScaleTop } from './luxScaleTop';
import { objectLightOf } from './objectLight';
import type { RoomView, ViewMode } from './roomView';

/** How the maps are shown: exposure compensation in stops over the automatic exposure, light or lux. */
export interface DisplaySettings {
  exposureEv: number;
  mode: ViewMode;
}

/** What presentMaps derived from the maps: the automatic exposure, the one applied (auto · 2^EV), the legend levels. */
export interface PresentedMaps {
  autoExposure: number;
  exposure: number;
  levels: number[];
}

/**
 * Put relit maps on a room view as the viewer shows them (docs/viewer.md,
 * "Display"): the maps and reflectances, automatic exposure times the
 * compensation, and the mode with lux levels up to the maps' 99th percentile.
 * The objects' light (when the maps have it) goes to the objects and counts in
 * the exposure and the percentile by its area. The browser viewer and
 * `luxbox render` both draw through this.
 */
export function presentMaps(view: RoomView, lit: LitMaps, reflectance: Record<SurfaceName, Rgb>, display: DisplaySettings): PresentedMaps {
  view.setMaps(lit, reflectance);
  const objects = objectLightOf(lit);
  view.setObjectLight(objects);
  const auto = autoExposure(lit, reflectance, objects);
  const exposure = auto * 2 ** display.exposureEv;
  view.setExposure(exposure);
  const levels = luxLevels(luxScaleTop(lit, 0.99, objects));
  view.setMode(display.mode, levels);
  return { autoExposure: auto, exposure, levels };
}
