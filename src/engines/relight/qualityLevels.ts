import type { BakeSettings } from '../bake/bakeSettings';

/**
 * The 3D view's bake quality levels (docs/viewer.md, "Quality levels"). The CLI keeps its
 * explicit flags; these only choose the browser viewer's settings. "balanced" is the
 * quality the viewer always had (VIEWER_BAKE_SETTINGS, measured in docs/viewer.md).
 */
export type QualityLevel = 'fast' | 'balanced' | 'best';

export const QUALITY_LEVEL_NAMES: readonly QualityLevel[] = ['fast', 'balanced', 'best'];

export const QUALITY_LEVELS: Record<QualityLevel, Partial<BakeSettings>> = {
  fast: { texelSize: 0.1, maxTextureSize: 128, samples: 32, bounces: 2, samplesPerDraw: 8, blurRadius: 3 },
  balanced: { texelSize: 0.05, maxTextureSize: 256, samples: 128, bounces: 3, samplesPerDraw: 8, blurRadius: 5 },
  best: { texelSize: 0.035, maxTextureSize: 512, samples: 256, bounces: 4, samplesPerDraw: 8, blurRadius: 6 },
};

export function isQualityLevel(value: unknown): value is QualityLevel {
  return typeof value === 'string' && (QUALITY_LEVEL_NAMES as readonly string[]).includes(value);
}
