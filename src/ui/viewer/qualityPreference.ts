import { isQualityLevel, type QualityLevel } from '../../engines/relight/qualityLevels';

/** Where the user's choice of bake quality is kept (per browser, across configurations). */
export const QUALITY_STORAGE_KEY = 'luxbox.quality';

/** The user's stored choice, or null (none, unreadable, or no storage). */
export function storedQuality(): QualityLevel | null {
  try {
    const v = typeof localStorage === 'undefined' ? null : localStorage.getItem(QUALITY_STORAGE_KEY);
    return isQualityLevel(v) ? v : null;
  } catch {
    return null; // storage blocked (privacy settings, sandboxed frame)
  }
}

export function storeQuality(level: QualityLevel): void {
  try {
    localStorage.setItem(QUALITY_STORAGE_KEY, level);
  } catch {
    // Storage blocked: the choice holds for this page only.
  }
}

/**
 * The quality the bake starts with: the host's pin (a `quality` URL parameter or embed option:
 * tests pin 'balanced' so lux values stay deterministic), else the user's stored choice (when the
 * host lets luxbox remember it), else
 * 'device': the level the device's calibration picks once the bake chunk has loaded
 * (deviceQuality; 'balanced' until then).
 */
export function initialQuality(pinned: QualityLevel | null | undefined, remember: boolean): QualityLevel | 'device' {
  return pinned ?? (remember ? storedQuality() : null) ?? 'device';
}
