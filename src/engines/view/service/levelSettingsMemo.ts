import { resolveBakeSettings, type BakeSettings } from '../../bake/bakeSettings';
import { QUALITY_LEVELS, type QualityLevel } from '../../relight/qualityLevels';

/** Each quality level's settings resolved once and passed on: the engine and its baker take them as they are. */
export function levelSettingsMemo(): (level: QualityLevel) => BakeSettings {
  const resolvedLevels = new Map<QualityLevel, BakeSettings>();
  return (level) => {
    const known = resolvedLevels.get(level);
    if (known) return known;
    const resolved = resolveBakeSettings(QUALITY_LEVELS[level]);
    resolvedLevels.set(level, resolved);
    return resolved;
  };
}
