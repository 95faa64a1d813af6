import { calibrateBakeSpeed, chooseQuality, glRenderer, type BakeCalibration } from '../../engines/relight/calibrateBakeSpeed';
import type { QualityLevel } from '../../engines/relight/qualityLevels';

/** Where this browser's calibration is kept, keyed by the GL renderer it was measured on. */
export const CALIBRATION_STORAGE_KEY = 'luxbox.calibration';

/** The calibration kept for `renderer`, or null: none, another renderer's, unreadable, or outdated (refused by chooseQuality). */
export function readCachedCalibration(renderer: string): BakeCalibration | null {
  try {
    const parsed = JSON.parse(localStorage.getItem(CALIBRATION_STORAGE_KEY) ?? 'null') as BakeCalibration | null;
    if (!parsed || parsed.renderer !== renderer) return null;
    // An entry an older luxbox wrote may lack fields chooseQuality needs: it refuses it, and we calibrate again.
    chooseQuality(parsed);
    return parsed;
  } catch {
    return null; // storage blocked, an unreadable or outdated entry: calibrate again
  }
}

/**
 * The quality level fitted to this device (docs/viewer.md, "Quality levels"): the calibration bake
 * (calibrateBakeSpeed, about 1–4 s on a software renderer, tens of ms on a GPU) runs once per
 * renderer on a throwaway context and is kept in localStorage when `remember` (else it runs once
 * per configurator); chooseQuality picks the best level
 * whose predicted first lit frame and solve fit their targets. 'balanced' when it cannot run.
 */
export function deviceQuality(remember: boolean): QualityLevel {
  const canvas = document.createElement('canvas');
  const gl = canvas.getContext('webgl2');
  if (!gl) return 'balanced';
  try {
    const renderer = glRenderer(gl);
    let calibration = remember ? readCachedCalibration(renderer) : null;
    if (!calibration) {
      calibration = calibrateBakeSpeed(gl);
      if (remember) {
        try {
          localStorage.setItem(CALIBRATION_STORAGE_KEY, JSON.stringify(calibration));
        } catch {
          // Storage blocked: calibrate again next time.
        }
      }
    }
    return chooseQuality(calibration);
  } catch {
    return 'balanced'; // no float targets or a failed bake: the 3D view reports its own problems
  } finally {
    gl.getExtension('WEBGL_lose_context')?.loseContext();
  }
}
