/**
 * The model's memoised derived data (perCatalog.ts and the caches built on it: system element trees,
 * a system's own problems and footprint, a preset's planned feeds and probe facts, module colours)
 * give exactly what a fresh computation gives. "Fresh" means on a structured clone of the state,
 * whose objects no cache has seen, or through the uncached reference the cache replaced (the
 * placement search as it was before: every candidate instantiated and checked with systemProblems).
 * States come from seeded random walks over the actions that change systems, performed whether
 * enabled or not, so invalid states (the refused branch of the always-valid test) are covered too.
 */
import { describe, expect, it } from 'vitest';
import { bindAction } from '../../../../src/core/model/actions/actionDefinitions';
import { type Catalog } from '../../../../src/core/model/catalogSchema/catalogSchema';
import { type PresetSpec } from '../../../../src/core/model/catalogSchema/presetSchema';
import { createConfiguration, type Configuration } from '../../../../src/core/model/configuration/configuration';
import { plannedFeeds } from '../../../../src/core/model/power/feedLoads';
import { systemBounds, systemElementTree } from '../../../../src/core/model/rails/geometry';
import { moduleLightColour } from '../../../../src/core/model/modules/moduleFilter';
import { perCatalog } from '../../../../src/core/model/catalogSchema/perCatalog';
import { findPresetPlacement, instantiatePreset, type Placement } from '../../../../src/core/model/actions/presets';
import { validate } from '../../../../src/core/model/validation/validate';
import { systemProblems } from '../../../../src/core/model/validation/systemProblems';
import { moduleColour } from '../../../../src/core/colour/moduleColour';
import { createRng, type Rng } from '../../../fuzz/mutate';
import { catalog } from '../helpers';

/** One random step: an action on the state's systems, rails and modules, or a new room size. */
function randomStep(s: Configuration, rng: Rng): [string, unknown] {
  const systems = s.systems.map((x) => x.id);
  const rails = s.systems.flatMap((x) => x.rails.map((r) => r.id));
  const modules = s.systems.flatMap((x) => x.rails.flatMap((r) => r.modules.map((m) => m.id)));
  const pick = <T>(xs: readonly T[], fallback: T): T => (xs.length ? rng.pick(xs) : fallback);
  const preset = rng.pick(catalog.presets).id;
  const { width: W, depth: D } = s.room;
  switch (rng.int(12)) {
    case 0:
      return ['setRoom', { width: 1 + rng.next() * 9, depth: 1 + rng.next() * 9, height: 2.2 + rng.next() * 2 }];
    case 1:
    case 2:
      return ['placePreset', { presetId: preset }];
    case 3:
      return ['placePreset', { presetId: preset, x: rng.next() * W, z: rng.next() * D, rotation: 90 * rng.int(4) }];
    case 4:
      return ['moveSystem', { systemId: pick(systems, 'none'), x: rng.next() * W, z: rng.next() * D }];
    case 5:
      return ['rotateSystem', { systemId: pick(systems, 'none'), by: rng.pick([90, -90, 45, 180]) }];
    case 6:
      return ['addRail', { systemId: pick(systems, 'none'), connector: rng.pick(catalog.connectors).id, turn: rng.pick([0, 90, -90, 45]), length: 0.5 + 0.5 * rng.int(5) }];
    case 7:
      return ['setRailLength', { railId: pick(rails, 'none'), length: 0.5 + 0.25 * rng.int(12) }];
    case 8:
      return ['addModule', { railId: pick(rails, 'none'), type: rng.pick(catalog.moduleTypes).id }];
    case 9:
      return ['removeRail', { railId: pick(rails, 'none') }];
    case 10:
      return ['setSuspension', { systemId: pick(systems, 'none'), suspension: rng.next() * 2.5 }];
    default:
      return ['removeModule', { moduleId: pick(modules, 'none') }];
  }
}

/** `count` states from seeded walks: each the state after one more step, enabled or not (refused results kept when perform returns one). */
function randomStates(seed: number, count: number): Configuration[] {
  const rng = createRng(seed);
  const out: Configuration[] = [];
  let s = createConfiguration({ width: 3 + rng.next() * 7, depth: 3 + rng.next() * 7, height: 2.6 + rng.next() });
  while (out.length < count) {
    const [name, params] = randomStep(s, rng);
    const action = bindAction(name, params, catalog);
    let next: Configuration;
    try {
      next = action.perform(s);
    } catch {
      continue;
    }
    out.push(next);
    // Walk on from valid states mostly; now and then start over in a new room.
    if (action.isEnabled(s) === true) s = next;
    if (rng.chance(0.03)) s = createConfiguration({ width: 2 + rng.next() * 8, depth: 2 + rng.next() * 8, height: 2.4 + rng.next() * 2 });
  }
  return out;
}

/** The placement search before its caches: every candidate instantiated and checked in full. */
function referencePlacement(config: Configuration, preset: PresetSpec, cat: Catalog, suspension: number): Placement | null {
  const { width, depth } = config.room;
  const step = Math.max(width, depth) / 40;
  const range = (a: number, b: number): number[] => {
    if (a > b + 1e-12) return [];
    if (b - a < 1e-12) return [a];
    const n = Math.ceil((b - a) / step);
    return Array.from({ length: n + 1 }, (_, i) => a + ((b - a) * i) / n);
  };
  // A clone: no cache has seen its systems (the first candidates fill the caches for it, as the search did before).
  const fresh = structuredClone(config);
  for (const rotation of [0, 90]) {
    const probe = instantiatePreset(fresh, preset, cat, { x: 0, z: 0, rotation }, suspension);
    const index = probe.systems.length - 1;
    const b = systemBounds(structuredClone(probe.systems[index]), cat);
    const hx = (b.maxX - b.minX) / 2;
    const hz = (b.maxZ - b.minZ) / 2;
    const centres = range(hx, width - hx).flatMap((x) => range(hz, depth - hz).map((z) => [x, z] as const));
    centres.sort((a, b2) => Math.hypot(a[0] - width / 2, a[1] - depth / 2) - Math.hypot(b2[0] - width / 2, b2[1] - depth / 2));
    for (const [cx, cz] of centres) {
      const placement = { x: cx - (b.minX + b.maxX) / 2, z: cz - (b.minZ + b.maxZ) / 2, rotation };
      const candidate = instantiatePreset(fresh, preset, cat, placement, suspension);
      if (systemProblems(candidate, index, cat).length === 0) return placement;
    }
  }
  return null;
}

describe('perCatalog', () => {
  it('computes once per object and catalog, again for another catalog, and forgets a throw', () => {
    let calls = 0;
    const f = perCatalog((o: { n: number }, cat: Catalog) => {
      calls++;
      if (o.n < 0) throw new Error('negative');
      return { twice: 2 * o.n, catalog: cat.id };
    });
    const a = { n: 3 };
    const first = f(a, catalog);
    expect(f(a, catalog)).toBe(first);
    expect(calls).toBe(1);
    const other = { ...catalog, id: 'other' };
    expect(f(a, other)).toEqual({ twice: 6, catalog: 'other' });
    expect(calls).toBe(2);
    const bad = { n: -1 };
    expect(() => f(bad, catalog)).toThrow('negative');
    expect(() => f(bad, catalog)).toThrow('negative');
    expect(calls).toBe(4);
  });
});

describe('cached derived data equals a fresh computation', () => {
  const states = randomStates(20261123, 240);

  it('the walks reach many systems, invalid states and full rooms', () => {
    expect(states.filter((s) => s.systems.length >= 2).length).toBeGreaterThan(60);
    expect(states.filter((s) => validate(s, catalog).length > 0).length).toBeGreaterThan(12);
  });

  it('validate() and systemProblems(): asked twice (cache hits) as on a clone (no cache has seen it)', () => {
    for (const s of states) {
      const fresh = validate(structuredClone(s), catalog);
      expect(validate(s, catalog)).toEqual(fresh);
      expect(validate(s, catalog)).toEqual(fresh);
      for (let i = 0; i < s.systems.length; i++) {
        const once = systemProblems(s, i, catalog);
        expect(systemProblems(s, i, catalog)).toEqual(once);
        expect(once).toEqual(systemProblems(structuredClone(s), i, catalog));
      }
    }
  });

  it('a caller changing the problems it got does not change the next answer', () => {
    const s = states.find((x) => x.systems.some((_, i) => systemProblems(x, i, catalog).length > 0))!;
    const i = s.systems.findIndex((_, k) => systemProblems(s, k, catalog).length > 0);
    const got = systemProblems(s, i, catalog);
    const copy = structuredClone(got);
    got.push({ code: 'x', path: 'y', message: 'z' });
    (got[0] as { path: string }).path = 'changed';
    expect(systemProblems(s, i, catalog)).toEqual(copy);
  });

  it('system element trees: the same object twice, equal to a clone’s', () => {
    for (const s of states) {
      for (const sys of s.systems) {
        let tree: ReturnType<typeof systemElementTree>;
        try {
          tree = systemElementTree(sys, catalog);
        } catch {
          continue; // an unsound system (validate() reports it first)
        }
        expect(systemElementTree(sys, catalog)).toBe(tree);
        expect(tree).toEqual(systemElementTree(structuredClone(sys), catalog));
      }
    }
  });

  it('the preset placement search finds what the uncached search finds', () => {
    const rng = createRng(7);
    const rooms = states.filter((_, k) => k % 10 === 0);
    let found = 0;
    let none = 0;
    for (const s of rooms) {
      for (const preset of [rng.pick(catalog.presets), rng.pick(catalog.presets)]) {
        const suspension = Math.min(catalog.suspension.default, s.room.height - catalog.suspension.minHeightAboveFloor);
        const expected = referencePlacement(s, preset, catalog, suspension);
        // Twice: the second search hits the preset's caches.
        expect(findPresetPlacement(s, preset, catalog, suspension)).toEqual(expected);
        expect(findPresetPlacement(s, preset, catalog, suspension)).toEqual(expected);
        if (expected) found++;
        else none++;
      }
    }
    expect(found).toBeGreaterThan(10);
    expect(none).toBeGreaterThan(0);
  });

  it('a placed preset gets the feeds plannedFeeds plans for it, whatever the ids and placement', () => {
    const rng = createRng(11);
    for (const preset of catalog.presets) {
      for (let k = 0; k < 3; k++) {
        const start = { ...createConfiguration({ width: 10, depth: 10, height: 3 }), nextId: 1 + rng.int(500) };
        const placed = instantiatePreset(start, preset, catalog, { x: rng.next() * 5, z: rng.next() * 5, rotation: 90 * rng.int(4) }, 0.5 + rng.next());
        const sys = placed.systems[0];
        const planned = plannedFeeds(structuredClone({ ...sys, feeds: [] }), catalog);
        expect(sys.feeds.map(({ at, driver }) => ({ at, driver }))).toEqual(planned);
      }
    }
  });

  it('module colours: cached as computed, for CCTs across the range and through filters', () => {
    const rng = createRng(3);
    for (let k = 0; k < 60; k++) {
      const cct = rng.chance(0.5) ? rng.pick([2700, 3000, 4000, 5000]) : 1000 + rng.next() * 19000;
      expect(moduleLightColour({ cct, filter: undefined })).toEqual(moduleColour(cct, undefined));
      expect(moduleLightColour({ cct, filter: undefined })).toBe(moduleLightColour({ cct, filter: undefined }));
    }
    for (const f of catalog.filters ?? []) {
      let fresh;
      try {
        fresh = moduleColour(3000, f.id);
      } catch {
        continue; // spectra not loaded in this host: moduleLightColour throws the same way
      }
      expect(moduleLightColour({ cct: 3000, filter: f.id })).toEqual(fresh);
    }
  });
});
