/**
 * Presets (catalog data) turned into placed systems, and the search for a free
 * spot when the user places one without saying where.
 */
import { findBeam, findModuleType, type Catalog } from '../catalogSchema/catalogSchema';
import { type PresetSpec } from '../catalogSchema/presetSchema';
import type { Configuration, LightSystem, ModuleInstance } from '../configuration/configuration';
import { plannedFeeds } from '../power/feedLoads';
import { normaliseDegrees, systemBounds, type PlanBounds } from '../rails/geometry';
import { perCatalog } from '../catalogSchema/perCatalog';
import { systemFitsAt } from '../validation/systemProblems';
import { systemOwnProblems } from '../validation/systemOwnProblems';

export interface Placement {
  readonly x: number;
  readonly z: number;
  readonly rotation: number;
}

/** A module of a type with its defaults (or the given beam / cct). */
export function newModule(catalog: Catalog, id: string, typeId: string, beam?: string, cct?: number): ModuleInstance {
  const type = findModuleType(catalog, typeId);
  const b = findBeam(type, beam ?? type.defaultBeam);
  return { id, type: type.id, beam: b.id, cct: cct ?? type.defaultCct, dimming: 1 };
}

/**
 * The suspension a new system gets: the catalog default, lowered so the
 * modules keep their head room in low rooms; null when no suspension works.
 */
export function defaultSuspension(catalog: Catalog, roomHeight: number): number | null {
  const s = catalog.suspension;
  const highest = Math.min(s.max, roomHeight - s.minHeightAboveFloor);
  if (highest < s.min) return null;
  return Math.min(s.default, Math.floor(highest * 1000) / 1000);
}

/** Appends a system built from the preset at the placement; ids come from the configuration's counter. */
export function instantiatePreset(config: Configuration, preset: PresetSpec, catalog: Catalog, placement: Placement, suspension: number): Configuration {
  let next = config.nextId;
  const id = (p: string) => `${p}${next++}`;
  const system = presetSystem(preset, catalog, placement, suspension, id);
  // One feed at the chain start with the catalog's default driver, or what the preset's load needs (plannedFeeds).
  const feeds = presetFeeds(preset, catalog).map((f) => ({ id: id('f'), ...f }));
  return { ...config, systems: [...config.systems, { ...system, feeds }], nextId: next };
}

function presetSystem(preset: PresetSpec, catalog: Catalog, placement: Placement, suspension: number, id: (prefix: string) => string): LightSystem {
  return {
    id: id('s'),
    presetId: preset.id,
    x: placement.x,
    z: placement.z,
    rotation: normaliseDegrees(placement.rotation),
    suspension,
    rails: preset.rails.map((r) => ({
      id: id('r'),
      length: r.length,
      distribution: r.distribution,
      modules: r.modules.map((m) => newModule(catalog, id('m'), m.type, m.beam, m.cct)),
    })),
    joints: preset.joints.map((j) => ({ ...j })),
    feeds: [],
    mounting: 'suspended',
  };
}

/**
 * plannedFeeds of a preset's system, once per preset and catalog (perCatalog.ts): it reads the
 * chain (rails, joints, the modules' types and beams), never the ids, the placement or the
 * suspension that instantiatePreset fills in, and the placement search instantiates every preset
 * it tries twice.
 */
const presetFeeds = perCatalog((preset: PresetSpec, catalog: Catalog) => {
  let n = 0;
  return plannedFeeds(
    presetSystem(preset, catalog, { x: 0, z: 0, rotation: 0 }, catalog.suspension.default, (p) => `${p}${n++}`),
    catalog,
  );
});

/**
 * A preset's system at the origin with a heading, hung at a suspension in a room of a height: its
 * bounds and whether its own rules hold (validate.ts systemOwnProblems). Neither reads the ids
 * (which follow the configuration's counter) nor anything else of the configuration, so the
 * placement search works them out once per preset, heading, suspension and room height.
 */
interface ProbeFacts {
  readonly bounds: PlanBounds;
  readonly ownRulesHold: boolean;
}
const probeFacts = perCatalog((_preset: PresetSpec) => new Map<string, ProbeFacts>());
/** Distinct headings, suspensions and room heights remembered per preset before starting over. */
const MAX_PROBES = 256;

function factsOf(placed: LightSystem, preset: PresetSpec, catalog: Catalog, roomHeight: number): ProbeFacts {
  const known = probeFacts(preset, catalog);
  const key = `${placed.rotation}|${placed.suspension}|${roomHeight}`;
  let facts = known.get(key);
  if (!facts) {
    facts = { bounds: systemBounds(placed, catalog), ownRulesHold: systemOwnProblems(placed, roomHeight, catalog).length === 0 };
    if (known.size >= MAX_PROBES) known.clear();
    known.set(key, facts);
  }
  return facts;
}

/**
 * A placement for a preset where it fits without clashing: its footprint's
 * centre on a grid over the room (about 40 steps along the longer side),
 * nearest to the room centre first, heading 0° before 90°. Null if none fits.
 */
export function findPresetPlacement(config: Configuration, preset: PresetSpec, catalog: Catalog, suspension: number): Placement | null {
  const known = placementsOf(config, catalog);
  let bySuspension = known.get(preset);
  if (!bySuspension) known.set(preset, (bySuspension = new Map()));
  if (bySuspension.has(suspension)) return bySuspension.get(suspension)!;
  const placement = searchPlacement(config, preset, catalog, suspension);
  bySuspension.set(suspension, placement);
  return placement;
}

/**
 * Search results per configuration object (perCatalog.ts), preset and suspension: the planner asks
 * whether each preset button is enabled on every render of one state, and a refused step leaves
 * the state as it was for the next (the always-valid test: a refused placePreset is asked again).
 */
const placementsOf = perCatalog((_config: Configuration) => new Map<PresetSpec, Map<number, Placement | null>>());

function searchPlacement(config: Configuration, preset: PresetSpec, catalog: Catalog, suspension: number): Placement | null {
  const { width, depth } = config.room;
  const step = Math.max(width, depth) / 40;
  for (const rotation of [0, 90]) {
    const probe = instantiatePreset(config, preset, catalog, { x: 0, z: 0, rotation }, suspension);
    const index = probe.systems.length - 1;
    const placed = probe.systems[index];
    const { bounds: b, ownRulesHold } = factsOf(placed, preset, catalog, config.room.height);
    // The system's own rules do not depend on where it stands (but for a finite x and z): once per heading.
    if (!ownRulesHold) continue;
    const hx = (b.maxX - b.minX) / 2;
    const hz = (b.maxZ - b.minZ) / 2;
    const xs = range(hx, width - hx, step);
    const zs = range(hz, depth - hz, step);
    // Nearest the room centre first (a stable sort, so equal distances keep grid order).
    const centres = xs.flatMap((x) => zs.map((z) => ({ x, z, d: Math.hypot(x - width / 2, z - depth / 2) })));
    centres.sort((a, b2) => a.d - b2.d);
    for (const { x: cx, z: cz } of centres) {
      const placement = { x: cx - (b.minX + b.maxX) / 2, z: cz - (b.minZ + b.maxZ) / 2, rotation };
      if (!Number.isFinite(placement.x) || !Number.isFinite(placement.z)) continue;
      // What instantiatePreset(config, preset, catalog, placement, suspension) gives: the probe moved
      // to x, z (same ids, same keys; its feeds, plannedFeeds, follow the chain, not where it hangs),
      // without planning the feeds again for each of up to 1 600 centres. systemFitsAt is
      // systemProblems(candidate, index, catalog) being empty, the own rules checked above.
      const candidate: Configuration = { ...probe, systems: [...config.systems, { ...placed, x: placement.x, z: placement.z }] };
      if (systemFitsAt(candidate, index, catalog)) return placement;
    }
  }
  return null;
}

/** Evenly spaced values from a to b inclusive, at most `step` apart; empty when a > b. */
function range(a: number, b: number, step: number): number[] {
  if (a > b + 1e-12) return [];
  if (b - a < 1e-12) return [a];
  const n = Math.ceil((b - a) / step);
  return Array.from({ length: n + 1 }, (_, i) => a + ((b - a) * i) / n);
}
