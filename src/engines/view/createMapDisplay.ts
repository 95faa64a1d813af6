import type { Rgb, SurfaceName } from '../../core/model/lightingScene';
import type { LitMaps } from '../relight/relightMaps';
import { ev100FromExposure } from './photographicExposure';
import { appliedExposure, presentMaps } from './presentMaps';
import type { RoomView, ViewMode } from './roomView';

/** What a host hears when maps are (re)shown: the maps, the exposure applied, the legend levels, the time the relight and upload took. */
export type MapsListener = (lit: LitMaps, info: { exposure: number; ev100: number; levels: number[]; relightMs: number }) => void;

/**
 * The viewer's exposure and mode over the maps on screen: remembers the
 * automatic exposure and legend levels of the last maps shown, so changing
 * the compensation, the fixed EV100 or the mode applies at once without
 * touching the maps. With a fixed EV100 (photographicExposure.ts) new maps keep
 * it: a dimmed configuration is shown darker.
 */
export interface MapDisplay {
  /** Show new maps; `startedAt` (performance.now()) is when their relight began. */
  show(lit: LitMaps, reflectance: Record<SurfaceName, Rgb>, startedAt: number): void;
  setExposureEv(ev: number): void;
  /** Absolute exposure (EV100), or null for automatic exposure with the compensation. */
  setEv100(ev100: number | null): void;
  /** The EV100 of the exposure applied now (for "lock exposure at the current value"). */
  currentEv100(): number;
  setMode(mode: ViewMode): void;
}

export function createMapDisplay(view: () => RoomView, onMaps: MapsListener): MapDisplay {
  let exposureEv = 0;
  let ev100: number | null = null;
  let mode: ViewMode = 'light';
  let auto = 1;
  let levels: number[] = [1];
  let lastLit: LitMaps | null = null;
  function reapply(): void {
    const exposure = appliedExposure(auto, { exposureEv, ev100 });
    view().setExposure(exposure);
    if (lastLit) onMaps(lastLit, { exposure, ev100: ev100FromExposure(exposure), levels, relightMs: 0 });
  }
  return {
    show(lit, reflectance, startedAt) {
      const shown = presentMaps(view(), lit, reflectance, { exposureEv, ev100, mode });
      auto = shown.autoExposure;
      levels = shown.levels;
      lastLit = lit;
      onMaps(lit, { exposure: shown.exposure, ev100: shown.ev100, levels, relightMs: performance.now() - startedAt });
    },
    setExposureEv(ev) {
      exposureEv = ev;
      reapply();
    },
    setEv100(value) {
      ev100 = value;
      reapply();
    },
    currentEv100() {
      return ev100FromExposure(appliedExposure(auto, { exposureEv, ev100 }));
    },
    setMode(m) {
      mode = m;
      view().setMode(m, levels);
    },
  };
}
