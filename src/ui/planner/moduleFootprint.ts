import { findBeam, findModuleType, type Catalog } from '../../core/model/catalogSchema/catalogSchema';
import { type BeamSpec } from '../../core/model/catalogSchema/moduleTypeSchema';
import type { ModuleInstance } from '../../core/model/configuration/configuration';
import { aimAxis } from '../../core/model/modules/aim';
import { coneRoomOutline, type RoomBox } from '../../core/model/modules/coneOutline';
import { rotatePlan, type ModulePlacement } from '../../core/model/rails/geometry';
import { beamFootprint, type FootprintEllipse } from './beamFootprint';
import type { FloorFootprint } from './floorFootprint';
import type { FootprintSource } from './footprintSource';
import type { PlanPoint } from './viewTransform';

/** Rays around a tilted beam cone: a smooth outline at plan zoom, cheap for dozens of modules. */
export const FOOTPRINT_RAYS = 72;

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
 * draws nothing rather than a guess. An aimed module (docs/aiming.md): untilted, its rotation
 * turns the footprint about the vertical; tilted, the catalog beam cone is traced to the room's
 * surfaces (`room`, needed then) and drawn from above.
 */
export function moduleFootprint(placement: ModulePlacement, module: ModuleInstance, catalog: Catalog, heightAboveFloor: number, measured: FloorFootprint | null | undefined, room?: RoomBox): ModuleFootprintShape | null {
  let beam: BeamSpec;
  try {
    beam = findBeam(findModuleType(catalog, module.type), module.beam);
  } catch {
    return null;
  }
  const { beamAngle, roll } = beam;
  const h = Math.max(0, heightAboveFloor);
  const [cx, cz] = placement.centre;
  const aim = module.aim;
  if (aim && aim.tilt !== 0) {
    // A tilted head: the beam cone (catalog beam angle) traced to the room's surfaces, seen from
    // above: the floor's ellipse (or hyperbola) where it lands there, clipped by the walls (coneOutline.ts).
    if (beamAngle === undefined || !room) return null;
    const hits = coneRoomOutline([cx, h, cz], aimAxis(placement.heading, aim), beamAngle / 2, room, FOOTPRINT_RAYS);
    return { kind: 'polygon', points: hits.map(({ point }) => ({ x: point[0], z: point[2] })) };
  }
  if (measured) {
    // An untilted head turned by its rotation: the same footprint turned about the vertical.
    const turn = placement.heading + (aim?.rotation ?? 0) + roll;
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
      axisDeg: -(placement.heading + (aim?.rotation ?? 0)),
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
  // The L3D bodies' plan outlines (catalog `model`), for the module symbols.
  const models = new Set<string>();
  for (const m of modules) {
    const model = catalog.moduleTypes.find((t) => t.id === m.type)?.model;
    if (model) models.add(model);
  }
  if (models.size > 0) source.requestOutlines([...models]);
}
