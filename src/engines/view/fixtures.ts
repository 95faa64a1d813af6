import { aimedOrientation } from '../../core/model/modules/aim';
import { findBeam, findModuleType, type Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import { modulePlacements, railPlacements, systemElementTree, type PlanRect } from '../../core/model/rails/geometry';
import type { LightingScene, Rgb, Vec3 } from '../../core/model/lightingScene/lightingScene';
import { moduleHeight, suspensionPoints } from '../../core/model/rails/suspensionPoints';
import type { Photometry } from '../../core/photometry/types';
import type { BakeLuminaire } from '../bake/bakeScene';
import { modelHeight } from './luminaires/luminaireDimensions';
import { hemisphereFlux } from './luminaires/hemisphereFlux';
import { kindOfLuminaire, kindOfModuleType, type LuminaireKind } from './luminaires/luminaireKind';
import type { L3dBody } from './luminaires/l3dBody';
import { modelBodyKey } from './luminaires/modelBodyKey';

/**
 * A module's light as the view's glow needs it: its photometry (the baker's: the face's luminance
 * toward the eye comes from it, luminaires/viewLuminance.ts), its opening, its flux per hemisphere
 * (lm, full power; what tells a lighting scene's luminaire's kind), its weight now (dimming × colour).
 */
export interface ModuleLight {
  photometry: Photometry;
  opening: Photometry['luminousOpening'];
  flux: { down: number; up: number };
  weight: Rgb;
}

/** One drawn module (docs/viewer.md, "Luminaires"). */
export interface FixtureModule {
  id: string;
  /** The photometric centre (world, metres). */
  centre: Vec3;
  /** Degrees: the rail's heading (C0 direction, counterclockwise from above). */
  heading: number;
  /** Length of rail it occupies (m). */
  length: number;
  on: boolean;
  kind: LuminaireKind;
  /** The luminaire's orientation in degrees, exactly the lighting scene's (world = Ry(yaw)·Rx(pitch)·Ry(roll)·local). */
  orientation: { yaw: number; pitch: number; roll: number };
  /** Height of the rail's underside (or, for a lighting scene's hung luminaire, the ceiling) above the photometric centre (m); 0: none. */
  mount: number;
  /** A lighting scene's luminaire standing on the floor: its photometric centre's height above it (m). */
  stand?: number;
  /** Null: its photometry is not known (nothing glows). */
  light: ModuleLight | null;
  /** The real body of its type's L3D geometry (catalog `model`), when loaded: drawn instead of the kind's model (luminaires/l3dBody.ts). */
  body?: L3dBody;
}

/** What the 3D view draws of the hardware, at true positions (metres, world frame). */
export interface Fixtures {
  /** A rail's axis at the height of the profile's centre. */
  rails: { start: Vec3; end: Vec3 }[];
  /** The rail profile's width (m): the catalog's `rail.width`. */
  railWidth: number;
  /** Connector nodes (corner, T, X, straight couplers) as plan rectangles, at the rails' height. */
  connectors: { rect: PlanRect; y: number }[];
  modules: FixtureModule[];
  /** Suspension cables, ceiling to the rail's top (none for a ceiling-surface system: its clips sit on the rail's top). */
  cables: { top: Vec3; bottom: Vec3 }[];
}

/** Rail profile cross-section (m): the catalog's width, a typical 35 mm height (48 V track profiles). */
export const RAIL_HEIGHT = 0.035;

/** The module's light from its bake luminaire (null: none). */
export function moduleLight(l: BakeLuminaire | undefined): ModuleLight | null {
  if (!l) return null;
  const d = Math.max(0, l.dimming ?? 1);
  const c = l.color ?? [1, 1, 1];
  return { photometry: l.photometry, opening: l.photometry.luminousOpening, flux: hemisphereFlux(l.photometry), weight: [d * c[0], d * c[1], d * c[2]] };
}

/**
 * Rails, connectors, modules and suspension cables of a configuration, from the model's own
 * geometry: modules at the photometric centres the baker uses (moduleHeight: ceiling − suspension,
 * or − the surface mount's drop), turned as the lighting scene turns them (aimedOrientation), cables
 * at the derived fixing points the bill of materials counts (suspensionPoints). A system's rail
 * hangs above its tallest module (modelHeight), since the suspension is measured to the
 * photometric centre (catalog `suspension`), never above the ceiling. `lights` (module id → its
 * resolved luminaire) gives the openings and the glow; `bodies` (modelBodyKey: a catalog `model`
 * path, with its `modelEmitter` → its loaded L3D body) the real bodies of the types that have one.
 */
export function fixturesFromConfiguration(config: Configuration, catalog: Catalog, lights: ReadonlyMap<string, BakeLuminaire> = new Map(), bodies: ReadonlyMap<string, L3dBody> = new Map()): Fixtures {
  const out: Fixtures = { rails: [], railWidth: catalog.rail.width, connectors: [], modules: [], cables: [] };
  const H = config.room.height;
  for (const system of config.systems) {
    const y = moduleHeight(system, config.room, catalog);
    const byId = new Map(system.rails.flatMap((r) => r.modules).map((m) => [m.id, m]));
    const placed = modulePlacements(system, catalog).map((p) => {
      const m = byId.get(p.moduleId)!;
      const type = findModuleType(catalog, m.type);
      const light = moduleLight(lights.get(m.id));
      const kind = kindOfModuleType(type);
      const key = modelBodyKey(type);
      const body = key ? bodies.get(key) : undefined;
      // An L3D body's own top (its track adapter) is what the rail must clear; a stem joins any gap.
      return { p, m, type, light, kind, body, height: body ? body.top : modelHeight({ kind, opening: light?.opening ?? null, length: p.length }) };
    });
    // The rail's underside above the tallest module, and the profile under the ceiling.
    const drop = Math.max(0.03, ...placed.map((q) => q.height));
    const railY = Math.min(y + drop + RAIL_HEIGHT / 2, H - RAIL_HEIGHT / 2);
    const mount = railY - RAIL_HEIGHT / 2 - y;
    for (const r of railPlacements(system, catalog)) out.rails.push({ start: [r.start[0], railY, r.start[1]], end: [r.end[0], railY, r.end[1]] });
    const tree = systemElementTree(system, catalog);
    tree.elements.forEach((rects, e) => {
      if (tree.kinds[e]?.kind === 'node') for (const rect of rects) out.connectors.push({ rect, y: railY });
    });
    if (system.mounting !== 'surface') {
      for (const p of suspensionPoints(system, catalog)) out.cables.push({ top: [p.plan[0], H, p.plan[1]], bottom: [p.plan[0], railY + RAIL_HEIGHT / 2, p.plan[1]] });
    }
    for (const { p, m, type, light, kind, body } of placed) {
      const orientation = aimedOrientation(p.heading, findBeam(type, m.beam).roll, m.aim);
      out.modules.push({ id: m.id, centre: [p.centre[0], y, p.centre[1]], heading: p.heading, length: p.length, on: m.on !== false && m.dimming > 0, kind, orientation, mount, light, ...(body ? { body } : {}) });
    }
  }
  return out;
}

/**
 * A lighting scene has no rails: each luminaire is drawn as its kind (from its photometry) at its
 * position, turned as it is; one in the upper half of the room hangs from the ceiling (its stem
 * reaches it), one in the lower half stands on the floor.
 */
export function fixturesFromScene(scene: LightingScene, luminaires: readonly BakeLuminaire[] = []): Fixtures {
  const H = scene.room.height;
  return {
    rails: [],
    railWidth: 0,
    connectors: [],
    cables: [],
    modules: scene.luminaires.map((l, i) => {
      const light = moduleLight(luminaires[i]);
      const kind = light ? kindOfLuminaire(light.opening, light.flux, l.pitch) : 'downlight';
      const standing = l.position[1] < H / 2;
      return {
        id: l.id ?? `l${i}`,
        centre: l.position,
        heading: l.yaw,
        length: 0.12,
        on: (l.dimming ?? 1) > 0,
        kind,
        orientation: { yaw: l.yaw, pitch: l.pitch, roll: l.roll },
        mount: standing ? 0 : Math.max(0, H - l.position[1]),
        ...(standing ? { stand: l.position[1] } : {}),
        light,
      };
    }),
  };
}
