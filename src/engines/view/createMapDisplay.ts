import type { Rgb, SurfaceName } from '../../core/model/lightingScene/lightingScene';
import type { LitMaps } from '../relight/relightMaps';
import { DEFAULT_ADAPTATION, type AdaptationSetting } from './adaptationSetting';
import type { Vec3 } from './colourMatrices';
import { createEyeAdaptation, type AdaptationState } from './eyeAdaptation';
import { ev100FromExposure } from './photographicExposure';
import { appliedExposure, applyAdaptationState, presentMaps } from './presentMaps';
import type { RoomView, ViewMode } from './roomView';

/** What a host hears when maps are (re)shown: the maps, the exposure applied, the legend levels, the time the relight and upload took. */
export type MapsListener = (lit: LitMaps, info: { exposure: number; ev100: number; levels: number[]; relightMs: number }) => void;

/** What the display needs to know about maps beyond their texels: the scene's adopted white, its geometry key, whether its light is done. */
export interface MapsContext {
  white: Vec3 | null;
  /** Room, objects and module positions (sceneGeometryKey): the same key is a relight. */
  key: string;
  done: boolean;
}

/**
 * The viewer's exposure, adaptation and mode over the maps on screen. Automatic exposure and the
 * adopted white go through an eye (eyeAdaptation.ts): they follow a configuration's maps until
 * its light is done, then hold, so dimming and light scenes make the picture darker; a new
 * geometry key or `reAdapt()` adapts again, slowly (`advance` moves it; the host draws frames
 * while it returns true). With a fixed EV100 (photographicExposure.ts) new maps keep it.
 */
export interface MapDisplay {
  /** Show new maps; `startedAt` (performance.now()) is when their relight began. */
  show(lit: LitMaps, reflectance: Record<SurfaceName, Rgb>, startedAt: number, context: MapsContext): void;
  setExposureEv(ev: number): void;
  /** Absolute exposure (EV100), or null for automatic exposure with the compensation. */
  setEv100(ev100: number | null): void;
  /** The EV100 of the exposure applied now (for "lock exposure at the current value"). */
  currentEv100(): number;
  setMode(mode: ViewMode): void;
  setAdaptation(setting: AdaptationSetting): void;
  /** Adapt to the maps on screen again (camera cut, the Re-adapt button). */
  reAdapt(): void;
  /** Fixed legend levels in lux (the daylight-factor view), or null: the maps' own levels again with the next maps shown. */
  setFixedLevels(levels: readonly number[] | null): void;
  /** Move the adaptation to `nowMs`; true while it still moves. */
  advance(nowMs: number): boolean;
  /** Whether the automatic exposure is held (the configuration's light was done; relights keep it). */
  held(): boolean;
}

export function createMapDisplay(view: () => RoomView, onMaps: MapsListener, now: () => number = () => performance.now()): MapDisplay {
  let exposureEv = 0;
  let ev100: number | null = null;
  let mode: ViewMode = 'light';
  let adaptation: AdaptationSetting = DEFAULT_ADAPTATION;
  let levels: number[] = [1];
  let fixedLevels: readonly number[] | null = null;
  let lastLit: LitMaps | null = null;
  let shown: AdaptationState = { auto: 1, white: null };
  const eye = createEyeAdaptation();
  const settings = () => ({ exposureEv, ev100, adaptation });
  function reapply(notify: boolean): void {
    const { exposure } = applyAdaptationState(view(), shown, settings());
    if (notify && lastLit) onMaps(lastLit, { exposure, ev100: ev100FromExposure(exposure), levels, relightMs: 0 });
  }
  return {
    show(lit, reflectance, startedAt, context) {
      const t = now();
      const presented = presentMaps(view(), lit, reflectance, {
        ...settings(),
        mode,
        levels: fixedLevels,
        white: context.white,
        adapt(target) {
          eye.update(target, context.key, context.done, t);
          shown = eye.state(t) ?? target;
          return shown;
        },
      });
      levels = presented.levels;
      lastLit = lit;
      onMaps(lit, { exposure: presented.exposure, ev100: presented.ev100, levels, relightMs: now() - startedAt });
    },
    setExposureEv(ev) {
      exposureEv = ev;
      reapply(true);
    },
    setEv100(value) {
      ev100 = value;
      reapply(true);
    },
    currentEv100() {
      return ev100FromExposure(appliedExposure(shown.auto, { exposureEv, ev100 }));
    },
    setMode(m) {
      mode = m;
      view().setMode(m, levels);
    },
    setFixedLevels(next) {
      fixedLevels = next;
      if (next) levels = [...next];
      view().setMode(mode, levels);
      // The legend follows at once; maps computed levels come back with the next maps shown.
      const exposure = appliedExposure(shown.auto, settings());
      if (lastLit) onMaps(lastLit, { exposure, ev100: ev100FromExposure(exposure), levels, relightMs: 0 });
    },
    setAdaptation(setting) {
      adaptation = setting;
      reapply(false);
    },
    reAdapt() {
      eye.reAdapt(now());
    },
    advance(nowMs) {
      const state = eye.state(nowMs);
      if (!state) return false;
      const moving = eye.moving(nowMs);
      if (state.auto !== shown.auto || state.white !== shown.white) {
        shown = state;
        // The last step of a move tells the host the exposure it settled on.
        reapply(!moving);
      }
      return moving;
    },
    held() {
      return eye.held;
    },
  };
}
