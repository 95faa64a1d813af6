/**
 * The configuration as the baker's input (LightingScene v1, v2 with objects, or v3 when the room has
 * a shape: its normalised room with each wall's finish, wallFinishes; docs/scene-format.md): one
 * luminaire per module, at its photometric centre (plan centre of the module,
 * y = ceiling − suspension, or − the surface mount's drop), turned so C0 runs along its rail (yaw = rail
 * heading) plus the optic's roll from the catalog, then aimed (adjustable modules, aim.ts), coloured by its CCT.
 */
import { aimedOrientation } from '../modules/aim';
import { findBeam, findModuleType, type Catalog } from '../catalogSchema/catalogSchema';
import { cctAtLevel } from '../catalogSchema/dimmingCurve';
import type { Configuration } from '../configuration/configuration';
import { modulePlacements } from '../rails/geometry';
import { moduleLightColour } from '../modules/moduleFilter';
import type { LightingLuminaire, LightingObject, LightingScene, Rgb } from '../lightingScene/lightingScene';
import { objectPlacement } from '../objects/objectGeometry';
import { moduleHeight } from '../rails/suspensionPoints';
import { requireRoomShapeSupport } from '../configuration/roomShapeSupport';

/** The mesh reference of a configuration's object in its lighting scene; objectMesh(config, id) resolves it. */
export const OBJECT_MESH_PREFIX = 'object:';

export interface ToLightingSceneOptions {
  /** Prefix for the catalog's photometry paths (e.g. '../public/' when the scene file lives elsewhere). Default ''. */
  readonly photometryBase?: string;
}

export function toLightingScene(config: Configuration, catalog: Catalog, options: ToLightingSceneOptions = {}): LightingScene {
  const base = options.photometryBase ?? '';
  const luminaires: LightingLuminaire[] = [];
  for (const system of config.systems) {
    // Suspended: ceiling − suspension; on the ceiling surface: ceiling − the surface mount's drop.
    const y = moduleHeight(system, config.room, catalog);
    const byId = new Map(system.rails.flatMap((r) => r.modules).map((m) => [m.id, m]));
    for (const p of modulePlacements(system, catalog)) {
      const m = byId.get(p.moduleId)!;
      const type = findModuleType(catalog, m.type);
      const beam = findBeam(type, m.beam);
      // An aimed module turns about the vertical, then tilts (aim.ts derives the angles).
      const { yaw, pitch, roll } = aimedOrientation(p.heading, beam.roll, m.aim);
      luminaires.push({
        id: m.id,
        photometry: base + beam.photometry,
        position: [p.centre[0], y, p.centre[1]],
        yaw,
        pitch,
        roll,
        // Switched off: dimmed to 0, not left out, so the luminaire keeps its group and basis (a relight turns it back on).
        dimming: m.on === false ? 0 : m.dimming,
        // A dim-to-warm type's colour follows its level (dimmingCurve.ts); other types keep their CCT.
        // Through its colour filter, if any (moduleFilter.ts): the colour's luminance carries the filter's τ_v.
        color: [...moduleLightColour({ cct: cctAtLevel(type.dimming, m.dimming, m.cct), filter: m.filter }).linearRgb] as Rgb,
      });
    }
  }
  const { width, depth, height, reflectance } = config.room;
  // A shape (issue 29) makes it version 3; its bounding box is [0, width] × [0, depth] (validate()), so width and depth stay the extents.
  const shape = config.room.shape ? requireRoomShapeSupport().shapedRoom(config.room) : null;
  const room = { width, height, depth, reflectance: { ...reflectance }, ...(shape ? { shape } : {}) };
  // Daylight comes in through windows, which only a room with a shape has (files/lightingDaylight.ts).
  const found = shape ? requireRoomShapeSupport().lightingDaylight(config) : null;
  const daylight = found ? { daylight: found } : {};
  if (config.objects.length === 0) return { version: shape ? 3 : 1, room, luminaires, ...daylight };
  // Objects are a version 2 field (docs/scene-format.md); their finishes travel in the mesh (objectMesh), not as a reflectance override.
  const objects: LightingObject[] = config.objects.map((o) => {
    const { position, yaw, scale } = objectPlacement(o, config.room);
    return { mesh: `${OBJECT_MESH_PREFIX}${o.id}`, position: [position[0], position[1], position[2]], yaw, scale, id: o.id };
  });
  return { version: shape ? 3 : 2, room, luminaires, objects, ...daylight };
}
