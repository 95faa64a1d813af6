/**
 * Presets (catalog data) turned into placed systems, and the search for a free
 * spot when the user places one without saying where.
 */
import { findBeam, findModuleType, type Catalog, type PresetSpec } from './catalogSchema';
import type { Configuration, LightSystem, ModuleInstance } from './configuration';
import { plannedFeeds } from './feedLoads';
import { normaliseDegrees, systemBounds } from './geometry';
import { systemProblems } from './validate';

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
  const system: LightSystem = {
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
  // One feed at the chain start with the catalog's default driver, or what the preset's load needs (plannedFeeds).
  const feeds = plannedFeeds(system, catalog).map((f) => ({ id: id('f'), ...f }));
  return { ...config, systems: [...config.systems, { ...system, feeds }], nextId: next };
}

/**
 * A placement for a preset where it fits without clashing: its footprint's
 * centre on a grid over the room (about 40 steps along the longer side),
 * nearest to the room centre first, heading 0° before 90°. Null if none fits.
 */
export function findPresetPlacement(config: Configuration, preset: PresetSpec, catalog: Catalog, suspension: number): Placement | null {
  const { width, depth } = config.room;
  const step = Math.max(width, depth) / 40;
  for (const rotation of [0, 90]) {
    const probe = instantiatePreset(config, preset, catalog, { x: 0, z: 0, rotation }, suspension);
    const index = probe.systems.length - 1;
    const b = systemBounds(probe.systems[index], catalog);
    const hx = (b.maxX - b.minX) / 2;
    const hz = (b.maxZ - b.minZ) / 2;
    const xs = range(hx, width - hx, step);
    const zs = range(hz, depth - hz, step);
    const centres = xs.flatMap((x) => zs.map((z) => [x, z] as const));
    centres.sort((a, b2) => Math.hypot(a[0] - width / 2, a[1] - depth / 2) - Math.hypot(b2[0] - width / 2, b2[1] - depth / 2));
    for (const [cx, cz] of centres) {
      const placement = { x: cx - (b.minX + b.maxX) / 2, z: cz - (b.minZ + b.maxZ) / 2, rotation };
      const candidate = instantiatePreset(config, preset, catalog, placement, suspension);
      if (systemProblems(candidate, index, catalog).length === 0) return placement;
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
