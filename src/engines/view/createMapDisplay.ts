import type { Rgb, SurfaceName } from '../../core/model/lightingScene';
import type { LitMaps } from '../relight/relightMaps';
import { presentMaps } from './presentMaps';
import type { RoomView, ViewMode } from './roomView';

/** What a host hears when maps are (re)shown: the maps, the exposure applied, the legend levels, the time the relight and upload took. */
export type MapsListener = (lit: LitMaps, info: { exposure: number; levels: number[]; relightMs: number }) => void;

/**
 * The viewer's exposure and mode over the maps on screen: remembers the
 * automatic exposure and legend levels of the last maps shown, so changing
 * the compensation or the mode applies at once without touching the maps.
 */
export interface MapDisplay {
  /** Show new maps; `startedAt` (performance.now()) is when their relight began. */
  show(lit: LitMaps, reflectance: Record<SurfaceName, Rgb>, startedAt: number): void;
  setExposureEv(ev: number): void;
  setMode(mode: ViewMode): void;
}

export function createMapDisplay(view: () => RoomView, onMaps: MapsListener): MapDisplay {
  let exposureEv = 0;
  let mode: ViewMode = 'light';
  let auto = 1;
  let levels: number[] = [1];
  let lastLit: LitMaps | null = null;
  return {
    show(lit, reflectance, startedAt) {
      const shown = presentMaps(view(), lit, reflectance, { exposureEv, mode });
      auto = shown.autoExposure;
      levels = shown.levels;
      lastLit = lit;
      onMaps(lit, { exposure: shown.exposure, levels, relightMs: performance.now() - startedAt });
    },
    setExposureEv(ev) {
      exposureEv = ev;
      view().setExposure(auto * 2 ** ev);
      if (lastLit) onMaps(lastLit, { exposure: auto * 2 ** ev, levels, relightMs: 0 });
    },
    setMode(m) {
      mode = m;
      view().setMode(m, levels);
    },
  };
}
