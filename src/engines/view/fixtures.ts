import type { Catalog } from '../../core/model/catalogSchema';
import type { Configuration } from '../../core/model/configuration';
import { modulePlacements, railPlacements } from '../../core/model/geometry';
import type { LightingScene, Vec3 } from '../../core/model/lightingScene';
import { moduleHeight, suspensionPoints } from '../../core/model/suspensionPoints';

/** What the 3D view draws of the hardware: simple boxes at true positions (metres, world frame). */
export interface Fixtures {
  rails: { start: Vec3; end: Vec3 }[];
  /** centre = photometric centre; heading in degrees (C0 direction, counterclockwise from above). */
  modules: { id: string; centre: Vec3; heading: number; length: number; on: boolean }[];
  /** Suspension cables, ceiling to rail (none for a ceiling-surface system: its clips sit on the rail's top). */
  cables: { top: Vec3; bottom: Vec3 }[];
}

/** Rail profile cross-section (m): the catalog's width, a typical 35 mm height. */
export const RAIL_HEIGHT = 0.035;
export const MODULE_HEIGHT = 0.03;

/**
 * Rails, modules and suspension cables of a configuration, from the model's own geometry: module
 * boxes at the photometric centres the baker uses (moduleHeight: ceiling − suspension, or − the
 * surface mount's drop), cables at the derived fixing points the bill of materials counts
 * (suspensionPoints).
 */
export function fixturesFromConfiguration(config: Configuration, catalog: Catalog): Fixtures {
  const out: Fixtures = { rails: [], modules: [], cables: [] };
  const H = config.room.height;
  for (const system of config.systems) {
    const y = moduleHeight(system, config.room, catalog);
    // A surface-mounted rail touches the ceiling: never draw it above the ceiling plane.
    const railY = Math.min(y + MODULE_HEIGHT + RAIL_HEIGHT / 2, H - RAIL_HEIGHT / 2);
    const rails = railPlacements(system, catalog);
    for (const r of rails) out.rails.push({ start: [r.start[0], railY, r.start[1]], end: [r.end[0], railY, r.end[1]] });
    if (system.mounting !== 'surface') {
      for (const p of suspensionPoints(system, catalog)) out.cables.push({ top: [p.plan[0], H, p.plan[1]], bottom: [p.plan[0], railY + RAIL_HEIGHT / 2, p.plan[1]] });
    }
    const dimming = new Map(system.rails.flatMap((r) => r.modules).map((m) => [m.id, m.dimming]));
    for (const m of modulePlacements(system, catalog)) {
      out.modules.push({ id: m.moduleId, centre: [m.centre[0], y, m.centre[1]], heading: m.heading, length: m.length, on: (dimming.get(m.moduleId) ?? 1) > 0 });
    }
  }
  return out;
}

/** A lighting scene has no rails: each luminaire becomes a small box at its position, turned by its yaw. */
export function fixturesFromScene(scene: LightingScene): Fixtures {
  return {
    rails: [],
    cables: [],
    modules: scene.luminaires.map((l, i) => ({ id: l.id ?? `l${i}`, centre: l.position, heading: l.yaw, length: 0.12, on: (l.dimming ?? 1) > 0 })),
  };
}
