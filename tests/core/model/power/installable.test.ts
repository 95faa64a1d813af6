/**
 * Issue 11, part 1: power feeds and their drivers, derived suspension points, surface
 * mounting, the bill of materials and installation needs that follow from them, scene
 * files from before feeds, and catalogs that state the rules. Every expected number is
 * computed by hand in the comments from the demo catalog: straight connector arm 0.02 m
 * (span 0.02 m), corner arm 0.05 m (span 0.10 m, point at the corner), suspension every
 * 2.0 m at most and at most 0.5 m overhang, surface clips every 1.0 m and 0.25 m, drop 0.07 m.
 */
import { describe, expect, it } from 'vitest';
import data from '../../../../src/core/catalog/default-catalog.json';
import { bindAction } from '../../../../src/core/model/actions/actionDefinitions';
import { billOfMaterials } from '../../../../src/core/model/power/billOfMaterials';
import { parseCatalog } from '../../../../src/core/model/catalogSchema/catalogSchema';
import { chainCoordinates } from '../../../../src/core/model/rails/chainCoordinates';
import { createConfiguration, type Configuration, type LightSystem } from '../../../../src/core/model/configuration/configuration';
import { feedLoads, plannedFeeds } from '../../../../src/core/model/power/feedLoads';
import { installationNeeds } from '../../../../src/core/model/power/installationNeeds';
import { deserializeConfiguration, serializeConfiguration } from '../../../../src/core/model/files/sceneFile';
import { decodeShareString } from '../../../../src/core/model/files/shareLink';
import { suspensionCoordinates, suspensionPoints } from '../../../../src/core/model/rails/suspensionPoints';
import { toLightingScene } from '../../../../src/core/model/files/toLightingScene';
import { validate } from '../../../../src/core/model/validation/validate';
import { catalog, enabled, only, run, withPreset } from '../helpers';

/** A refused action, performed anyway, must yield a state validate() rejects (or throw). */
function expectRefusedAndInvalid(state: Configuration, name: string, params: unknown, reason: string | RegExp, cat = catalog) {
  const a = bindAction(name, params, cat);
  expect(a.isEnabled(state)).toEqual({ ok: false, reason: typeof reason === 'string' ? reason : expect.stringMatching(reason) });
  let next: Configuration;
  try {
    next = a.perform(state);
  } catch {
    return [];
  }
  const problems = validate(next, cat);
  expect(problems.length).toBeGreaterThan(0);
  return problems;
}

/** A one-rail system of the given length, start at (0.5, 1) heading +x, fed at its start. */
function railOf(length: number, room = { width: 8, depth: 6, height: 3 }): Configuration {
  let s = run(createConfiguration(room), 'placePreset', { presetId: 'single', x: 0.5, z: 1 });
  s = run(s, 'setRailLength', { railId: only(s).rails[0].id, length });
  return s;
}

const near = (xs: readonly number[], ys: readonly number[]) => {
  expect(xs.length).toBe(ys.length);
  xs.forEach((x, i) => expect(x).toBeCloseTo(ys[i], 9));
};

describe('suspension points (derived, suspensionPoints.ts)', () => {
  it('one rail of 1, 2.5 and 3 m: two points, inset min(0.5, L/4) from the ends', () => {
    // 1 m: inset 0.25 → 0.25, 0.75 (gap 0.5). 2.5 m: inset 0.5 → 0.5, 2.0 (gap 1.5).
    // 3 m: inset 0.5 → 0.5, 2.5: the gap is exactly 2.0 m, so no third point.
    near(
      suspensionCoordinates(only(railOf(1)), catalog).map((p) => p.s),
      [0.25, 0.75],
    );
    near(
      suspensionCoordinates(only(railOf(2.5)), catalog).map((p) => p.s),
      [0.5, 2.0],
    );
    near(
      suspensionCoordinates(only(railOf(3)), catalog).map((p) => p.s),
      [0.5, 2.5],
    );
    // plan: the rail starts at (0.5, 1) heading +x
    near(
      suspensionPoints(only(railOf(2.5)), catalog).flatMap((p) => [...p.plan]),
      [1.0, 1, 2.5, 1],
    );
  });
  it('two 3 m rails joined straight: a point at the connector and one mid-span each side', () => {
    const s = withPreset('long-line', 1, 1); // 3.0 + 0.02 + 3.0 m
    // ends: 0.5 and 6.02 − 0.5 = 5.52; connector point 3.0 + 0.01 = 3.01;
    // 0.5 → 3.01 is 2.51 m > 2: one interior at 0.5 + 1.255 = 1.755; 3.01 → 5.52 likewise at 4.265
    const pts = suspensionCoordinates(only(s), catalog);
    near(
      pts.map((p) => p.s),
      [0.5, 1.755, 3.01, 4.265, 5.52],
    );
    expect(pts.map((p) => p.joint)).toEqual([null, null, 0, null, null]);
    expect(chainCoordinates(only(s), catalog).length).toBeCloseTo(6.02, 12);
  });
  it('an L corner: the corner point carries the joint, plan positions on both legs', () => {
    const s = withPreset('corner-l', 1, 3); // 2.0 m heading +x, corner (arms 0.05), 1.5 m heading −z
    // s: 0.5 (inset min(0.5, 2/4)); corner 2.0 + 0.05 = 2.05; end 2.1 + 1.5 − min(0.5, 1.5/4) = 3.225
    const pts = suspensionPoints(only(s), catalog);
    near(
      pts.map((p) => p.s),
      [0.5, 2.05, 3.225],
    );
    // plan: (1.5, 3); the corner point (3.05, 3); second leg starts at (3.05, 2.95), 1.125 m along −z → (3.05, 1.825)
    near(
      pts.flatMap((p) => [...p.plan]),
      [1.5, 3, 3.05, 3, 3.05, 1.825],
    );
  });
  it('the snake: five rails, four corners, interior points where a span exceeds 2 m', () => {
    const s = run(createConfiguration({ width: 12, depth: 10, height: 3 }), 'placePreset', { presetId: 'snake' });
    // rails 2.5, 1, 2.5, 1, 2.5 with corners (span 0.1): corner points 2.55, 3.65, 6.25, 7.35; length 9.9
    // spans: 0.5 → 2.55 (2.05: one interior, 1.525), 2.55 → 3.65, 3.65 → 6.25 (2.6: 4.95), 6.25 → 7.35, 7.35 → 9.4 (2.05: 8.375)
    near(
      suspensionCoordinates(only(s), catalog).map((p) => p.s),
      [0.5, 1.525, 2.55, 3.65, 4.95, 6.25, 7.35, 8.375, 9.4],
    );
  });
  it('surface mounting: clips every 1 m at most, 0.25 m from free ends', () => {
    let s = railOf(3);
    s = run(s, 'setMounting', { systemId: only(s).id, mounting: 'surface' });
    // inset min(0.25, 0.75) = 0.25; 0.25 → 2.75 is 2.5 m: ⌈2.5⌉ − 1 = 2 interior → 1.0833…, 1.9166…
    near(
      suspensionCoordinates(only(s), catalog).map((p) => p.s),
      [0.25, 0.25 + 2.5 / 3, 0.25 + 5 / 3, 2.75],
    );
  });
});

describe('power feeds: load per feed, overload refused with the reason', () => {
  it('a new system gets one feed at the start; the default driver when it carries the load, else the smallest that does', () => {
    // three 43 W spots = 129 W > 100.8 W (LPV-100-48, the default) → HLG-150H-48 (153.6 W), the smallest that carries it
    const s = withPreset('single', 1, 1);
    expect(plannedFeeds({ ...only(s), presetId: undefined, feeds: [] }, catalog)).toEqual([{ at: 'start', driver: 'hlg-150h-48' }]);
    // the Single rail preset ships with the driver it names (presets[].driver): HLG-240H-48, room for two more spots
    expect(only(s).feeds).toEqual([{ id: expect.stringMatching(/^f\d+$/), at: 'start', driver: 'hlg-240h-48' }]);
    expect(feedLoads(only(s), catalog).map((l) => [l.load, l.capacity])).toEqual([[129, 240]]);
    // an empty rail keeps the default
    const empty = run(s, 'addRail', { systemId: only(s).id, connector: 'straight', turn: 0, length: 1 });
    expect(plannedFeeds({ ...only(empty), rails: only(empty).rails.map((r) => ({ ...r, modules: [] })), feeds: [] }, catalog)).toEqual([{ at: 'start', driver: 'lpv-100-48' }]);
  });
  it('the snake (386.17 W) needs two feeds: start and end, 240 W each', () => {
    const s = run(createConfiguration({ width: 12, depth: 10, height: 3 }), 'placePreset', { presetId: 'snake' });
    // nearest feed along the 9.9 m chain (midway 4.95 m): rail 1 (43 + 9.39 + 43), the first 1 m rail's flood (50),
    // the middle rail's first spot (43) and its linear, centred exactly at 4.95 m (a tie goes to the start):
    // 197.78 W; the rest 188.39 W; both above 153.6 W, so 240 W drivers
    expect(only(s).feeds.map((f) => [f.at, f.driver])).toEqual([
      ['start', 'hlg-240h-48'],
      ['end', 'hlg-240h-48'],
    ]);
    const loads = feedLoads(only(s), catalog).map((l) => l.load);
    expect(loads).toEqual([197.78, 188.39]);
    expect(loads[0] + loads[1]).toBeCloseTo(386.17, 9);
  });
  it('the Single rail preset has room for two more of its spots; the sixth is refused, naming the driver that would carry it', () => {
    let s = withPreset('single', 1, 1);
    const rail = only(s).rails[0].id;
    s = run(s, 'addModule', { railId: rail, type: 'spot' }); // 172 W
    s = run(s, 'addModule', { railId: rail, type: 'spot' }); // 215 W
    expect(feedLoads(only(s), catalog).map((l) => [l.load, l.capacity])).toEqual([[215, 240]]);
    const problems = expectRefusedAndInvalid(s, 'addModule', { railId: rail, type: 'spot' }, 'the 240 W driver is full: 215 W used; choose the 321.6 W driver in the system options or add a second feed');
    expect(problems[0].message).toBe('Feed 1 carries 258 W, more than its 240 W driver (Mean Well HLG-240H-48)');
    // on the largest driver only a second feed helps: seven spots (301 W) on the 321.6 W HLG-320H-48, an eighth would be 344 W
    s = run(s, 'setFeedDriver', { feedId: only(s).feeds[0].id, driver: 'hlg-320h-48' });
    s = run(s, 'addModule', { railId: rail, type: 'spot' });
    s = run(s, 'addModule', { railId: rail, type: 'spot' });
    expectRefusedAndInvalid(s, 'addModule', { railId: rail, type: 'spot' }, 'the 321.6 W driver is full: 301 W used; add a second feed in the system options');
  });
  it('addModule is refused when the driver is full, with the load before; validate() names the overload', () => {
    // the Single rail preset on the 153.6 W driver (the smallest that carries its 129 W)
    let s = withPreset('single', 1, 1);
    s = run(s, 'setFeedDriver', { feedId: only(s).feeds[0].id, driver: 'hlg-150h-48' });
    const rail = only(s).rails[0].id;
    const problems = expectRefusedAndInvalid(s, 'addModule', { railId: rail, type: 'spot' }, 'the 153.6 W driver is full: 129 W used; choose the 240 W driver in the system options or add a second feed');
    expect(problems[0]).toEqual({ code: 'feed-overload', path: 'systems[0].feeds[0]', message: 'Feed 1 carries 172 W, more than its 153.6 W driver (Mean Well HLG-150H-48)' });
    // the same words from every action that adds load: a heavier beam, a heavier type
    s = run(s, 'setModuleBeam', { moduleId: only(s).rails[0].modules[0].id, beam: 'medium' }); // 28 + 43 + 43 = 114 W
    expectRefusedAndInvalid(s, 'setFeedDriver', { feedId: only(s).feeds[0].id, driver: 'lpv-100-48' }, 'the 100.8 W Mean Well LPV-100-48 cannot carry the 114 W on Feed 1; choose a larger driver or add a feed');
    const light = run(s, 'setModuleBeam', { moduleId: only(s).rails[0].modules[1].id, beam: 'medium' }); // 28 + 28 + 43 = 99 W
    const small = run(light, 'setFeedDriver', { feedId: only(light).feeds[0].id, driver: 'lpv-100-48' });
    expectRefusedAndInvalid(small, 'setModuleBeam', { moduleId: only(small).rails[0].modules[0].id, beam: 'narrow' }, 'the 100.8 W driver is full: 99 W used; choose the 153.6 W driver in the system options or add a second feed');
    expectRefusedAndInvalid(small, 'setModuleType', { moduleId: only(small).rails[0].modules[0].id, type: 'flood' }, /the 100\.8 W driver is full: 99 W used/);
  });
  it('a second feed makes room: modules go to the nearest feed along the chain', () => {
    let s = withPreset('single', 1, 1);
    const id = only(s).id;
    // feeds at 0 and 1.5 m; spots centred at 0.25, 0.75 (a tie: the start), 1.25 → 86 W and 43 W
    s = run(s, 'addFeed', { systemId: id, at: 'end' });
    expect(feedLoads(only(s), catalog).map((l) => l.load)).toEqual([86, 43]);
    expect(only(s).feeds[1].driver).toBe('lpv-100-48');
    // a fourth spot: four cells of 0.375 m, centres 0.1875, 0.5625 | 0.9375, 1.3125 → 86 W and 86 W
    s = run(s, 'addModule', { railId: only(s).rails[0].id, type: 'spot' });
    expect(feedLoads(only(s), catalog).map((l) => l.load)).toEqual([86, 86]);
    expect(validate(s, catalog)).toEqual([]);
  });
  it('feeds: never the last one, one per position, only where the catalog allows', () => {
    let s = withPreset('single', 1, 1);
    const [feed] = only(s).feeds;
    expectRefusedAndInvalid(s, 'removeFeed', { feedId: feed.id }, 'a system keeps at least one power feed');
    expectRefusedAndInvalid(s, 'addFeed', { systemId: only(s).id, at: 'start' }, 'there is already a feed at the chain start');
    expectRefusedAndInvalid(s, 'addFeed', { systemId: only(s).id, at: { joint: 0 } }, 'Feed 2 is at connector 1, but the chain has 0 connectors');
    s = run(s, 'addRail', { systemId: only(s).id, connector: 'straight', turn: 0, length: 1 });
    s = run(s, 'addFeed', { systemId: only(s).id, at: { joint: 0 } });
    // the connector point is at 1.51 m: the spot at 1.25 m is nearer to it (43 W); removing the feed at the
    // start would put all 129 W on its 100.8 W driver
    expect(feedLoads(only(s), catalog).map((l) => l.load)).toEqual([86, 43]);
    expectRefusedAndInvalid(s, 'removeFeed', { feedId: feed.id }, 'the 100.8 W driver is full: 43 W used; choose the 153.6 W driver in the system options or add a second feed');
    s = run(s, 'moveFeed', { feedId: only(s).feeds[1].id, at: 'end' });
    expect(only(s).feeds[1].at).toBe('end');
    // a catalog that feeds only at the ends
    const endsOnly = parseCatalog({ ...structuredClone(data), feed: { ...data.feed, positions: ['ends'] } }, 'ends.json');
    expectRefusedAndInvalid(s, 'moveFeed', { feedId: only(s).feeds[1].id, at: { joint: 0 } }, 'Luxbox demo rail system feeds only at the chain ends, not at connectors', endsOnly);
    expectRefusedAndInvalid(s, 'setFeedDriver', { feedId: feed.id, driver: 'xlg-9000' }, "unknown driver 'xlg-9000' (catalog luxbox-demo-rail)");
  });
  it('removing the last rail moves a feed at its connector to the chain end; two would meet: refused', () => {
    let s = withPreset('single', 1, 1);
    s = run(s, 'addRail', { systemId: only(s).id, connector: 'straight', turn: 0, length: 1 });
    s = run(s, 'addFeed', { systemId: only(s).id, at: { joint: 0 } });
    const removed = run(s, 'removeRail', { railId: only(s).rails[1].id });
    expect(only(removed).feeds.map((f) => f.at)).toEqual(['start', 'end']);
    const both = run(s, 'addFeed', { systemId: only(s).id, at: 'end' });
    expectRefusedAndInvalid(both, 'removeRail', { railId: only(both).rails[1].id }, 'a feed at the last connector and one at the chain end would meet; remove one of them first');
  });
});

describe('mounting: suspended or on the ceiling surface', () => {
  it('surface-mounted modules sit the drop below the ceiling, and head room is checked there', () => {
    let s = withPreset('single', 1, 1); // ceiling 3 m, suspension 0.6 m
    const id = only(s).id;
    expect(toLightingScene(s, catalog).luminaires[0].position[1]).toBeCloseTo(2.4, 12);
    s = run(s, 'setMounting', { systemId: id, mounting: 'surface' });
    expect(toLightingScene(s, catalog).luminaires[0].position[1]).toBeCloseTo(3 - 0.07, 12);
    // the suspension is kept for switching back; a long one is fine on the ceiling, not when hanging
    s = run(s, 'setSuspension', { systemId: id, suspension: 1.5 });
    expectRefusedAndInvalid(s, 'setMounting', { systemId: id, mounting: 'suspended' }, 'modules would hang at 1.5 m, below the minimum 2 m above the floor');
    // a catalog whose surface mount drops 0.3 m, in a 2.2 m room: 1.9 m is below the 2 m head room
    const deep = parseCatalog({ ...structuredClone(data), surfaceMount: { ...data.surfaceMount, drop: 0.3 } }, 'deep.json');
    const low = run(createConfiguration({ width: 4, depth: 4, height: 2.2 }), 'placePreset', { presetId: 'single' }, deep);
    expectRefusedAndInvalid(low, 'setMounting', { systemId: only(low).id, mounting: 'surface' }, 'modules would hang at 1.9 m on the ceiling, below the minimum 2 m above the floor', deep);
  });
});

describe('bill of materials and installation needs', () => {
  it('drivers, feed kits, suspension kits or clips, exact to the cent', () => {
    let s = withPreset('long-line', 1, 1); // 137.56 W → one feed, HLG-150H-48; 5 suspension points (above)
    let bom = billOfMaterials(s, catalog);
    const line = (article: string) => bom.lines.find((l) => l.article === article);
    expect(line('LX-SUSP')).toMatchObject({ count: 5, unitPrice: 18, total: 90 });
    expect(line('LX-FEED')).toMatchObject({ count: 1, total: 65 });
    expect(line('MW-HLG-150H-48')).toMatchObject({ count: 1, unitPrice: 59.9, total: 59.9, kind: 'driver' });
    const before = bom.total;
    // an LPV-60-48 at the end would carry the second rail (linear, flood, linear: 68.78 W): refused
    expectRefusedAndInvalid(s, 'addFeed', { systemId: only(s).id, at: 'end', driver: 'lpv-60-48' }, 'Feed 2 would carry 68.78 W, more than its 60 W driver; add a second feed or choose a larger driver');
    // an LPV-100-48 takes it: +65 + 34.90
    s = run(s, 'addFeed', { systemId: only(s).id, at: 'end', driver: 'lpv-100-48' });
    expect(feedLoads(only(s), catalog).map((l) => l.load)).toEqual([68.78, 68.78]);
    bom = billOfMaterials(s, catalog);
    expect(line('LX-FEED')).toMatchObject({ count: 2, total: 130 });
    expect(line('MW-LPV-100-48')).toMatchObject({ count: 1, unitPrice: 34.9, total: 34.9 });
    expect(Math.round(bom.total * 100)).toBe(Math.round(before * 100) + 9990);
    // on the ceiling: 6.02 m with clips (inset 0.25): 0.25 → 3.01 (2.76 m: 2 interior), 3.01 → 5.77 (2 interior): 7 clips à 6.50
    s = run(s, 'setMounting', { systemId: only(s).id, mounting: 'surface' });
    bom = billOfMaterials(s, catalog);
    expect(line('LX-SUSP')).toBeUndefined();
    expect(line('LX-CLIP')).toMatchObject({ count: 7, unitPrice: 6.5, total: 45.5 });
    expect(Math.round(bom.total * 100)).toBe(Math.round(before * 100) + 9990 - 9000 + 4550);
  });
  it('installationNeeds: feeds with load and capacity, ceiling fixings, total load', () => {
    let s = createConfiguration({ width: 12, depth: 10, height: 3 });
    s = run(s, 'placePreset', { presetId: 'single' });
    s = run(s, 'placePreset', { presetId: 'snake' });
    const needs = installationNeeds(s, catalog);
    expect(needs.systems.map((x) => x.feeds.map((f) => [f.label, f.load, f.capacity, f.driver.article]))).toEqual([
      [['Feed 1', 129, 240, 'MW-HLG-240H-48']],
      [
        ['Feed 1', 197.78, 240, 'MW-HLG-240H-48'],
        ['Feed 2', 188.39, 240, 'MW-HLG-240H-48'],
      ],
    ]);
    // single 1.5 m: 0.375, 1.125 → 2 fixings; snake: 9 (above)
    expect(needs).toMatchObject({ feeds: 3, ceilingFixings: 11, totalLoad: 515.17 });
    expect(needs.systems.map((x) => x.mounting)).toEqual(['suspended', 'suspended']);
  });
});

describe('scene files from before feeds (version 3 and older) still load', () => {
  const v3 = (config: Configuration) => {
    const file = JSON.parse(serializeConfiguration(config, catalog));
    file.version = 3;
    file.configuration.systems = file.configuration.systems.map(({ feeds: _f, mounting: _m, ...rest }: LightSystem) => rest);
    return file;
  };
  it('gets each system a planned feed (ids from nextId) and suspended mounting', () => {
    let s = createConfiguration({ width: 12, depth: 10, height: 3 });
    s = run(s, 'placePreset', { presetId: 'single' });
    s = run(s, 'placePreset', { presetId: 'snake' });
    const file = v3(s);
    const read = deserializeConfiguration(JSON.stringify(file), catalog);
    expect(validate(read, catalog)).toEqual([]);
    expect(read.nextId).toBe(file.configuration.nextId + 3);
    const n = file.configuration.nextId;
    expect(read.systems.map((x) => x.feeds)).toEqual([
      [{ id: `f${n}`, at: 'start', driver: 'hlg-240h-48' }],
      [
        { id: `f${n + 1}`, at: 'start', driver: 'hlg-240h-48' },
        { id: `f${n + 2}`, at: 'end', driver: 'hlg-240h-48' },
      ],
    ]);
    expect(read.systems.map((x) => x.mounting)).toEqual(['suspended', 'suspended']);
    // and as a share link of version 3
    expect(decodeShareString(Buffer.from(JSON.stringify(file)).toString('base64url'), catalog)).toEqual(read);
  });
  it('refuses feeds or mounting in a file that says it is older', () => {
    const file = JSON.parse(serializeConfiguration(withPreset('single', 1, 1), catalog));
    for (const version of [1, 2, 3]) {
      expect(() => deserializeConfiguration(JSON.stringify({ ...file, version }), catalog)).toThrow(`scene file: configuration.systems[0].feeds: needs "version": 4 (this file says version ${version})`);
    }
  });
  it('refuses a version 4 system without feeds, naming the field', () => {
    const file = JSON.parse(serializeConfiguration(withPreset('single', 1, 1), catalog));
    file.configuration.systems[0].feeds = [];
    expect(() => deserializeConfiguration(JSON.stringify(file), catalog)).toThrow('scene file: configuration.systems[0].feeds: system s1 has no power feed');
  });
});

describe('catalog rules for feeds, drivers and mounting name the field', () => {
  const broken = (mutate: (c: typeof data) => void) => {
    const c = structuredClone(data);
    mutate(c);
    return () => parseCatalog(c, 'my.json');
  };
  it('drivers', () => {
    expect(broken((c) => (c.drivers[1].output = '24 V DC'))).toThrow("my.json: drivers[1].output: '24 V DC' does not match feed.output '48 V DC'");
    expect(broken((c) => (c.drivers[0].capacity = -60))).toThrow(/my\.json: drivers\[0\]\.capacity: /);
    expect(broken((c) => (c.drivers[2].id = 'lpv-60-48'))).toThrow("my.json: drivers[2].id: duplicate id 'lpv-60-48'");
    expect(broken((c) => (c.feed.defaultDriver = 'xlg-9000'))).toThrow("my.json: feed.defaultDriver: 'xlg-9000' is not a driver id");
    expect(broken((c) => (c.drivers = []))).toThrow(/my\.json: drivers: /);
  });
  it('feed positions', () => {
    expect(broken((c) => (c.feed.positions = ['joints']))).toThrow("my.json: feed.positions: must include 'ends' (a one-rail system has no joints)");
    expect(broken((c) => (c.feed.positions = ['ends', 'middle']))).toThrow(/my\.json: feed\.positions\[1\]: /);
  });
  it('suspension and surface mount rules', () => {
    expect(broken((c) => (c.suspension.maxOverhang = 2.5))).toThrow('my.json: suspension.maxOverhang: must not exceed maxSpacing');
    expect(broken((c) => (c.surfaceMount.maxOverhang = 1.5))).toThrow('my.json: surfaceMount.maxOverhang: must not exceed spacing');
    expect(broken((c) => (c.surfaceMount.spacing = 0))).toThrow(/my\.json: surfaceMount\.spacing: /);
    expect(broken((c) => delete (c as Partial<typeof data>).surfaceMount)).toThrow(/my\.json: surfaceMount: /);
    // a preset's own driver (presets[].driver) must exist and carry the preset's load (Single rail: 3 × 43 W = 129 W)
    const single = (c: typeof data) => c.presets.find((p) => p.id === 'single') as (typeof data.presets)[number] & { driver?: string };
    expect(broken((c) => (single(c).driver = 'xlg-9000'))).toThrow("my.json: presets[0].driver: 'xlg-9000' is not a driver id");
    expect(broken((c) => (single(c).driver = 'lpv-100-48'))).toThrow("my.json: presets[0].driver: the 100.8 W 'lpv-100-48' cannot carry the preset's 129 W");
  });
  it('the demo drivers are 48 V DC Mean Well units from 60 to 321.6 W, each with its source', () => {
    expect(catalog.drivers.map((d) => [d.id, d.capacity])).toEqual([
      ['lpv-60-48', 60],
      ['lpv-100-48', 100.8],
      ['hlg-150h-48', 153.6],
      ['hlg-240h-48', 240],
      ['hlg-320h-48', 321.6],
    ]);
    // rated power = 48 V × rated current (datasheets): 1.25, 2.1, 3.2, 5, 6.7 A
    expect(catalog.drivers.map((d) => Math.round((d.capacity / 48) * 1000) / 1000)).toEqual([1.25, 2.1, 3.2, 5, 6.7]);
    for (const d of catalog.drivers) expect(d.source).toMatch(/Mean Well .* datasheet/);
  });
});

it('enabled feed actions in a row keep the configuration valid', () => {
  let s = withPreset('single', 1, 1);
  s = run(s, 'addRail', { systemId: only(s).id, connector: 'corner90', turn: -90, length: 1 });
  s = run(s, 'addFeed', { systemId: only(s).id, at: { joint: 0 }, driver: 'lpv-60-48' });
  s = run(s, 'moveFeed', { feedId: only(s).feeds[1].id, at: 'end' });
  expect(enabled(s, 'removeFeed', { feedId: only(s).feeds[1].id })).toBe(true);
  expect(validate(s, catalog)).toEqual([]);
});
