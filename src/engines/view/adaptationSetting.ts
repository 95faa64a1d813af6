/**
 * The viewer's chromatic adaptation setting (chromaticAdaptation.ts computes what it does): `eye`
 * (default), `camera` white balance at a CCT, `none`. Kept apart and free of heavy imports: the
 * page's entry and mountLuxbox parse it for `?adapt=` and the embed option `adapt`.
 */
import { CCT_MAX_K, CCT_MIN_K } from '../../core/photometry/cct';

export type AdaptationSetting = { kind: 'eye' } | { kind: 'camera'; cct: number } | { kind: 'none' };

export const DEFAULT_ADAPTATION: AdaptationSetting = { kind: 'eye' };

/** True for a CCT camera white balance accepts (cctToLinearRgb's range, 1000–20 000 K). */
export function isCameraCct(cct: unknown): cct is number {
  return typeof cct === 'number' && Number.isFinite(cct) && cct >= CCT_MIN_K && cct <= CCT_MAX_K;
}

/** 'eye', 'none' or 'camera:<K>' (the CLI's `--adapt`, the app's `?adapt=`, the embed option); null for anything else. */
export function parseAdaptation(text: string): AdaptationSetting | null {
  const t = text.trim().toLowerCase();
  if (t === 'eye' || t === 'none') return { kind: t };
  const m = /^camera:(\d+(?:\.\d+)?)k?$/.exec(t);
  if (m && isCameraCct(Number(m[1]))) return { kind: 'camera', cct: Number(m[1]) };
  return null;
}

/** The inverse of parseAdaptation. */
export function formatAdaptation(s: AdaptationSetting): string {
  return s.kind === 'camera' ? `camera:${s.cct}` : s.kind;
}
