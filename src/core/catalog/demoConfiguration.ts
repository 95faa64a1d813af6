import { attemptAction } from '../model/actions/actionDefinitions';
import type { Catalog } from '../model/catalogSchema/catalogSchema';
import { createConfiguration, type Configuration } from '../model/configuration/configuration';

/** The preset the demo places: the L corner shows spots, floods and wall washers at once. */
export const DEMO_PRESET_ID = 'corner-l';

/**
 * The demo: the default 5 × 4 × 2.8 m room with the L-corner preset (or the catalog's first
 * preset) placed where the model's own search puts it, through the same always-valid action
 * the preset panel runs. A catalog whose presets do not fit gives the empty room.
 */
export function demoConfiguration(catalog: Catalog): Configuration {
  const empty = createConfiguration();
  const preset = catalog.presets.find((p) => p.id === DEMO_PRESET_ID) ?? catalog.presets[0];
  if (!preset) return empty;
  const outcome = attemptAction(empty, 'placePreset', { presetId: preset.id }, catalog);
  return outcome.ok ? outcome.next : empty;
}
