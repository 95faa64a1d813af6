/**
 * What the 3D view's spotlight mode needs of a module (docs/aiming.md), from the configuration:
 * its photometric centre, rail heading, optic roll, aim and limits; null for an unknown or fixed
 * (non-adjustable) module.
 */
import { findBeam, type Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import { modulePlacements } from '../../core/model/rails/geometry';
import { moduleHeight } from '../../core/model/rails/suspensionPoints';
import type { SpotlightRequest } from '../../engines/view/createSpotlight';

export function spotlightRequest(config: Configuration, catalog: Catalog, moduleId: string): SpotlightRequest | null {
  for (const system of config.systems) {
    const module = system.rails.flatMap((r) => r.modules).find((m) => m.id === moduleId);
    if (!module) continue;
    const type = catalog.moduleTypes.find((t) => t.id === module.type);
    const placement = modulePlacements(system, catalog).find((p) => p.moduleId === moduleId);
    if (!type?.adjustable || !placement) return null;
    return {
      moduleId,
      position: [placement.centre[0], moduleHeight(system, config.room, catalog), placement.centre[1]],
      heading: placement.heading,
      roll: findBeam(type, module.beam).roll,
      aim: module.aim ?? { rotation: 0, tilt: 0 },
      limits: type.adjustable,
    };
  }
  return null;
}
