import { findBeam, findModuleType, type BeamSpec, type Catalog } from '../../core/model/catalogSchema';
import type { ModuleInstance } from '../../core/model/configuration';
import { rotatePlan, type ModulePlacement } from '../../core/model/geometry';
import { beamFootprint, type FootprintEllipse } from './beamFootprint';
import type { FloorFootprint } from './floorFootprint';
import type { FootprintSource } from './footprintSource';
import type { PlanPoint } from './viewTransform';

export type ModuleFootprintShape = { kind: 'polygon'; points: PlanPoint[] } | { kind: 'ellipse'; ellipse: FootprintEllipse };

/** The catalog photometry path of a module's optic, or null for an unknown type/beam. */
export function modulePhotometryPath(module: ModuleInstance, catalog: Catalog): string | null {
  try {
    return findBeam(findModuleType(catalog, module.type), module.beam).photometry;
  } catch {
    return null;
  }
}

/**
 * A module's light footprint on the floor, in plan metres.
 *
 * With the optic's measured footprint (floorFootprint, in units of mounting height in the
 * luminaire frame) the polygon is scaled by the height and turned like the luminaire: the
 * lighting scene gives it yaw = rail heading and the catalog roll, and with pitch 0 both are
 * turns about the vertical, so a local point (u along C0, v toward C90 = local −z) lands at
 * centre + h · Ry(yaw + roll)·(u, −v) (docs/scene-format.md frames). Without it (still loading, or the
 * file failed) the catalog's beam angle gives the cone of beamFootprint; an optic with neither
 * draws nothing rather than a guess.
 */
export function moduleFootprint(
  placement: ModulePlacement,
  module: ModuleInstance,
  catalog: Catalog,
  heightAboveFloor: number,
  measured: FloorFootprint | null | undefined,
): ModuleFootprintShape | null {
  let beam: BeamSpec;
  try {
    beam = findBeam(findModuleType(catalog, module.type), module.beam);
  } catch {
    return null;
  }
  const { beamAngle, roll } = beam;
  const h = Math.max(0, heightAboveFloor);
  const [cx, cz] = placement.centre;
  if (measured) {
    const turn = placement.heading + roll;
    return {
      kind: 'polygon',
      points: measured.polygon.map(([u, v]) => {
        const [dx, dz] = rotatePlan([u * h, -v * h], turn);
        return { x: cx + dx, z: cz + dz };
      }),
    };
  }
  if (beamAngle === undefined) return null;
  return {
    kind: 'ellipse',
    ellipse: beamFootprint({
      center: { x: cx, z: cz },
      // Headings are counterclockwise seen from above; the plan's y axis is +z (down on screen),
      // so the SVG angle from +x towards +z is the negated heading.
      axisDeg: -placement.heading,
      length: 0,
      height: h,
      beamAlongDeg: beamAngle,
      beamAcrossDeg: beamAngle,
    }),
  };
}

/** Requests the footprints of every optic in use (called when the configuration changes). */
export function requestFootprints(source: FootprintSource, modules: readonly ModuleInstance[], catalog: Catalog): void {
  const paths = new Set<string>();
  for (const m of modules) {
    const p = modulePhotometryPath(m, catalog);
    if (p) paths.add(p);
  }
  source.request([...paths]);
}
