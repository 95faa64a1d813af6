import { demoConfiguration } from '../../core/catalog/demoConfiguration';
import { livingRoom } from '../../core/catalog/furnishedPresets';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';

/**
 * What the demo opens (`?demo`, the dev server, room setup's "Try the demo"): the furnished
 * living room (src/core/catalog/furnishedPresets.ts), so the 3D view's first picture shows
 * furniture catching light and casting shadows. A catalog without the presets the living room is
 * built from (a shop's own catalog) gets the plain demo (demoConfiguration) instead.
 */
export function firstImpression(catalog: Catalog): Configuration {
  try {
    return livingRoom(catalog);
  } catch {
    return demoConfiguration(catalog);
  }
}
