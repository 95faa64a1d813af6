import { findBeam, findModuleType, type Catalog } from '../model/catalogSchema';
import type { ModuleInstance } from '../model/configuration';
import type { ModulePlacement } from '../model/geometry';
import { beamFootprint, type FootprintEllipse } from './beamFootprint';

/**
 * Full beam angle assumed when the catalog gives none (diffusers, washers, direct/indirect
 * modules): the half-intensity angle of a Lambertian emitter, I(θ) = I₀·cos θ = I₀/2 at
 * θ = 60°, so 120° full. It marks the floor area such an optic lights most.
 */
export const DIFFUSE_BEAM_DEG = 120;

/**
 * The floor footprint of a placed module (see beamFootprint): beam from the catalog, mounted
 * `heightAboveFloor` metres up, spread along the rail by the module's own length.
 */
export function moduleFootprint(placement: ModulePlacement, module: ModuleInstance, catalog: Catalog, heightAboveFloor: number): FootprintEllipse {
  let beam = DIFFUSE_BEAM_DEG;
  try {
    beam = findBeam(findModuleType(catalog, module.type), module.beam).beamAngle ?? DIFFUSE_BEAM_DEG;
  } catch {
    // A module the catalog does not know is already reported by validate(); draw it diffuse.
  }
  return beamFootprint({
    center: { x: placement.centre[0], z: placement.centre[1] },
    // Headings are counterclockwise seen from above; the plan's y axis points to +z (down on
    // screen), so the SVG angle from +x towards +z is the negated heading.
    axisDeg: -placement.heading,
    length: placement.length,
    height: heightAboveFloor,
    beamAlongDeg: beam,
    beamAcrossDeg: beam,
  });
}
