import type { Rgb, SurfaceName } from '../../core/model/lightingScene/lightingScene';
import type { LitMaps } from '../relight/relightMaps';
import { autoExposure } from './autoExposure';
import { adaptationFor, adaptingLuminance, type Adaptation } from './chromaticAdaptation';
import { DEFAULT_ADAPTATION, type AdaptationSetting } from './adaptationSetting';
import type { Vec3 } from './colourMatrices';
import { limitAutoExposure, type AdaptationState } from './eyeAdaptation';
import { luxLevels } from './falseColorScale';
import { luxScaleTop } from './luxScaleTop';
import { objectLightOf } from './objectLight';
import { ev100FromExposure, exposureFromEv100 } from './photographicExposure';
import type { RoomView, ViewMode } from './roomView';

/**
 * How the maps are shown: light or lux, the exposure (automatic with a compensation in stops,
 * `exposureEv`, or absolute when `ev100` is a number: photographicExposure.ts) and the chromatic
 * adaptation (chromaticAdaptation.ts; default `eye`) to the scene's adopted white `white`
 * (adoptedWhite.ts; null or absent: no white lamp, nothing to adapt to).
 */
export interface DisplaySettings {
  exposureEv: number;
  ev100?: number | null;
  mode: ViewMode;
  adaptation?: AdaptationSetting;
  white?: Vec3 | null;
  /** Given these maps' own target, the state to show (the browser's held or moving eye, eyeAdaptation.ts); absent: the target itself. */
  adapt?: (target: AdaptationState) => AdaptationState;
  /** Fixed legend levels in lux (the daylight-factor view's, core/daylight/daylightFactor.ts); absent: from the maps' 99th percentile. */
  levels?: readonly number[] | null;
}

/** What presentMaps derived from the maps: their own adaptation target, the state shown, the exposure applied, its EV100, the adaptation, the legend levels. */
export interface PresentedMaps {
  /** The maps' own automatic exposure, within the limits (eyeAdaptation.ts). */
  autoExposure: number;
  /** What these maps ask to adapt to (auto exposure and adopted white). */
  target: AdaptationState;
  exposure: number;
  /** EV100 of the applied exposure (ev100FromExposure): the value "lock exposure" keeps. */
  ev100: number;
  adaptation: Adaptation;
  levels: number[];
}

/** The exposure applied: 1 / (1.2 · 2^EV100) when an EV100 is fixed, else auto · 2^compensation. */
export function appliedExposure(auto: number, display: Pick<DisplaySettings, 'exposureEv' | 'ev100'>): number {
  return typeof display.ev100 === 'number' ? exposureFromEv100(display.ev100) : auto * 2 ** display.exposureEv;
}

/**
 * Set a view's exposure and chromatic adaptation for an adaptation state: the exposure from its
 * automatic exposure (or the fixed EV100), the adaptation from its white at L_A = 0.2 / auto
 * (chromaticAdaptation.ts; the scene's own adapting luminance even when the EV100 is fixed).
 */
export function applyAdaptationState(view: Pick<RoomView, 'setExposure' | 'setAdaptation'>, state: AdaptationState, display: Pick<DisplaySettings, 'exposureEv' | 'ev100' | 'adaptation'>): { exposure: number; adaptation: Adaptation } {
  const exposure = appliedExposure(state.auto, display);
  const adaptation = adaptationFor(display.adaptation ?? DEFAULT_ADAPTATION, state.white, adaptingLuminance(state.auto));
  view.setExposure(exposure);
  view.setAdaptation(adaptation.matrix);
  return { exposure, adaptation };
}

/**
 * Put relit maps on a room view as the viewer shows them (docs/viewer.md,
 * "Display"): the maps and reflectances, automatic exposure (within limits) times the
 * compensation (or the fixed EV100's exposure), the chromatic adaptation, and the mode with lux
 * levels up to the maps' 99th percentile. The objects' light (when the maps have it) goes to the
 * objects and counts in the exposure and the percentile by its area. The browser viewer and
 * `luxbox render` both draw through this; the browser passes its held or moving eye as `adapt`.
 */
export function presentMaps(view: RoomView, lit: LitMaps, reflectance: Record<SurfaceName, Rgb>, display: DisplaySettings): PresentedMaps {
  view.setMaps(lit, reflectance);
  const objects = objectLightOf(lit);
  view.setObjectLight(objects);
  const auto = limitAutoExposure(autoExposure(lit, reflectance, objects));
  const target: AdaptationState = { auto, white: display.white ?? null };
  const { exposure, adaptation } = applyAdaptationState(view, display.adapt ? display.adapt(target) : target, display);
  const levels = display.levels ? [...display.levels] : luxLevels(luxScaleTop(lit, 0.99, objects));
  view.setMode(display.mode, levels);
  return { autoExposure: auto, target, exposure, ev100: ev100FromExposure(exposure), adaptation, levels };
}
