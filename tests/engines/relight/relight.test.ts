import { describe, expect, it } from 'vitest';
import { LUMINANCE_WEIGHTS } from '../../../src/engines/bake/bakedMaps';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { createBaker } from '../../../src/engines/bake/createBaker';
import type { Rgb } from '../../../src/core/model/lightingScene/lightingScene';
import { createRelightEngine } from '../../../src/engines/relight/createRelightEngine';
import { groupLuminaires, groupWeight } from '../../../src/engines/relight/luminaireGroups';
import { loadIes, spot as spotPhotometry, uniformRoom } from '../bake/bakeTestKit';
import { boxMesh } from '../bake/objects/objectFixtures';
import type { BakeObject } from '../../../src/engines/bake/bakeScene';
import { compareWithBake } from './relightTestKit';
import { withHeadlessGL } from '../bake/withHeadlessGL';

const gl = withHeadlessGL();
// Coarse but real: a 3 × 2.6 × 3.4 m grey room, two real photometric files, 2 bounces.
const SETTINGS = { texelSize: 0.1, maxTextureSize: 64, samples: 16, bounces: 2, samplesPerDraw: 8, blurRadius: 2, seed: 7 };
const spot = loadIes('bega_84693_narrow_spot.ies');
const down = loadIes('bega_50975_downlight_lm1995_crlf.ies');
const room = uniformRoom(3, 2.6, 3.4, 0.5);
const OBJECT_SETTINGS = { texelSize: 0.15, bounces: 1 };
const synthSpot = spotPhotometry(800, 30, 10, 2);
const synthWide = spotPhotometry(600, 60, 15, 2);
const table: BakeObject = { id: 'table', mesh: boxMesh(0.8, 0.7, 0.6, 0.6), position: [1.6, 0, 1.8], yaw: 20, scale: 1 };
const lum = (photometry = spot, x = 1, z = 1, dimming = 1, color: Rgb = [1, 1, 1]) => ({ photometry, position: [x, 2.4, z] as [number, number, number], yaw: 30, pitch: 0, roll: 0, dimming, color });

describe('luminaire groups', () => {
  it('puts luminaires with identical photometry, position and orientation in one group, anything else apart', () => {
    const a = lum(spot, 1, 1, 0.5, [1, 0.9, 0.8]);
    const b = lum(spot, 1, 1, 0.25, [1, 1, 1]); // same geometry as a, other settings
    const c = lum(spot, 1.0002, 1); // moved 0.2 mm
    const d = lum(down, 1, 1); // other photometry
    const e = { ...lum(spot, 1, 1), yaw: 31 }; // turned
    const groups = groupLuminaires([a, b, c, d, e]);
    expect(groups.map((g) => g.members)).toEqual([[0, 1], [2], [3], [4]]);
    // Members share geometry, so their maps add: the group weight is Σ dimming·colour.
    expect(groupWeight(groups[0], [a, b, c, d, e])).toEqual([0.75, 0.7, 0.65]);
    expect(groups[0].basis[0].dimming).toBe(1);
    expect(groups[0].basis[0].color).toEqual([1, 1, 1]);
  });
});

describe('relighting = weighted direct bases + one shared indirect solve', () => {
  // The shared solve is fed Σ w·direct_g, which equals the full bake's direct maps to float
  // rounding (direct light is linear), and then runs the very passes of the full bake with the
  // same seed: the same bright patches, the same samples, the same tail. So relit and full bake
  // differ only by that rounding carried through the (linear) gather: measured 6.5e-8 of the
  // peak for all three cases (llvmpipe); the bound 1e-5 is the direct maps' own bound, far above
  // float rounding and far below Monte Carlo noise (16 samples: percent level), so a solve that
  // read other direct maps, other samples or another tail would fail it. Objects use coarser
  // texels and one bounce: their passes are slow on software GL.
  for (const [label, extra, objects] of [
    ['pure Monte Carlo', { brightPatches: 0 }, false],
    ['default bright patches', {}, false],
    ['with objects', {}, true],
  ] as const)
    it(`matches a full bake of the dimmed, coloured scene (${label}): direct to 1e-5, total to 1e-5 of the peak`, () => {
      const settings = { ...SETTINGS, ...extra, ...(objects ? OBJECT_SETTINGS : {}) };
      const engine = createRelightEngine(gl, settings);
      const weights: [number, Rgb][] = [
        [0.3, [1, 0.8, 0.6]],
        [0.9, [0.7, 0.9, 1]],
      ];
      const scene: BakeScene = {
        room,
        // With objects, synthetic point-source spots: a real file's luminous opening splits into
        // many point sources, each traced against the objects per sub-sample (slow on software GL).
        luminaires: objects ? [lum(synthSpot, 1, 1, ...weights[0]), lum(synthWide, 2.1, 2.5, ...weights[1])] : [lum(spot, 1, 1, ...weights[0]), lum(down, 2.1, 2.5, ...weights[1])],
        ...(objects ? { objects: [table] } : {}),
      };
      engine.setScene(scene);
      engine.finish();
      expect(engine.counters.indirectSolves).toBe(1);
      const lit = engine.maps();
      const reference = createBaker(gl).bake(scene, settings).maps;
      const d = compareWithBake(lit, reference);
      expect(d.peak).toBeGreaterThan(100);
      if (objects) expect(d.objectTexels).toBeGreaterThan(20);
      expect(d.direct / d.peak).toBeLessThan(1e-5);
      expect(d.total / d.peak).toBeLessThan(1e-5);
      engine.dispose();
    });

  it('dimming and colour changes bake no group and re-solve once; a moved luminaire bakes only its group; a room change bakes all', () => {
    // Pure Monte Carlo without the tail: the solve is then a linear operator of its direct maps
    // (same seed, same samples), so partial scenes add up to the full one to float rounding.
    const engine = createRelightEngine(gl, { ...SETTINGS, brightPatches: 0, tail: false });
    const base = [lum(spot, 1, 1), lum(down, 2.1, 2.5), lum(spot, 2, 1)];
    expect(engine.setScene({ room, luminaires: base })).toEqual({ bake: 3, reused: 0 });
    engine.finish();
    expect(engine.counters.groupBakes).toBe(3);
    expect(engine.counters.indirectSolves).toBe(1);
    const floorLux = (kind: 'direct' | 'total') => {
      const f = engine.maps().maps.floor[kind];
      let s = 0;
      for (let i = 0; i < f.length; i += 3) s += LUMINANCE_WEIGHTS[0] * f[i] + LUMINANCE_WEIGHTS[1] * f[i + 1] + LUMINANCE_WEIGHTS[2] * f[i + 2];
      return s / (f.length / 3);
    };
    const full = floorLux('total');

    // Dim the downlight to 0 (off): no group bake; the direct part is exact at once, the indirect waits for one re-solve.
    const off = [base[0], { ...base[1], dimming: 0 }, base[2]];
    expect(engine.setScene({ room, luminaires: off })).toEqual({ bake: 0, reused: 3 });
    expect(engine.progress).toMatchObject({ lit: true, exact: false, done: false });
    engine.finish();
    expect(engine.progress).toMatchObject({ exact: true, done: true });
    expect(engine.counters.indirectSolves).toBe(2);
    const withoutDown = floorLux('total');
    engine.setScene({ room, luminaires: [{ ...base[0], dimming: 0 }, base[1], { ...base[2], dimming: 0 }] });
    engine.finish();
    const downOnly = floorLux('total');
    expect(Math.abs(withoutDown + downOnly - full)).toBeLessThan(1e-5 * full);
    expect(engine.counters.groupBakes).toBe(3);
    expect(engine.counters.relightsOnly).toBe(2);
    expect(engine.counters.indirectSolves).toBe(3);

    // Back to weights already solved at: the kept solution (the solution cache) is exact at once, nothing to solve.
    engine.setScene({ room, luminaires: base });
    expect(engine.progress).toMatchObject({ done: true, exact: true });
    engine.finish();
    expect(engine.counters.indirectSolves).toBe(3);
    expect(floorLux('total')).toBeCloseTo(full, 6);

    // Move one spot: only its group is baked, and the indirect light is solved once more.
    const moved = [base[0], base[1], lum(spot, 2.2, 1)];
    expect(engine.setScene({ room, luminaires: moved })).toEqual({ bake: 1, reused: 2 });
    expect(engine.progress).toMatchObject({ lit: false, groupsDone: 2, groups: 3 });
    engine.finish();
    expect(engine.counters.groupBakes).toBe(4);
    expect(engine.counters.indirectSolves).toBe(4);

    // Another room: every group again.
    expect(engine.setScene({ room: uniformRoom(3.2, 2.6, 3.4, 0.5), luminaires: moved })).toEqual({ bake: 3, reused: 0 });
    engine.dispose();
  });

  it('a basis issued but not read back is dropped when its module moves: the moved one bakes, nothing stale shows', () => {
    const engine = createRelightEngine(gl, SETTINGS);
    engine.setScene({ room, luminaires: [lum(spot, 1.5, 1.7)] });
    engine.step(8); // issues the first basis
    engine.setScene({ room, luminaires: [lum(spot, 0.9, 1.7)] });
    engine.finish();
    expect(engine.counters.groupBakes).toBe(2);
    const fresh = createRelightEngine(gl, SETTINGS);
    fresh.setScene({ room, luminaires: [lum(spot, 0.9, 1.7)] });
    fresh.finish();
    const floor = (e: typeof engine) => e.maps().maps.floor.direct;
    expect(Array.from(floor(engine))).toEqual(Array.from(floor(fresh)));
    engine.dispose();
    fresh.dispose();
  });

  it('shows light before the indirect work is done, and refines progressively', () => {
    const engine = createRelightEngine(gl, SETTINGS);
    engine.setScene({ room, luminaires: [lum(spot, 1.5, 1.7)] });
    // The direct-only basis takes two calls: the first issues its passes (no read-back, so a
    // browser's slicer can fence before reading), the second reads the maps back.
    let p = engine.step(8);
    expect(p.lit).toBe(false);
    expect(engine.counters.groupBakes).toBe(1);
    p = engine.step(8);
    expect(p.lit).toBe(true);
    expect(p.done).toBe(false);
    const ceilingEarly = engine.maps().maps.ceiling.total.reduce((a, b) => a + b, 0);
    const fractions = [p.fraction];
    while (!p.done) fractions.push((p = engine.step(8)).fraction);
    const ceilingFinal = engine.maps().maps.ceiling.total.reduce((a, b) => a + b, 0);
    // A downward spot lights the ceiling only by interreflection: nothing direct, something after the bounces.
    expect(ceilingEarly).toBe(0);
    expect(ceilingFinal).toBeGreaterThan(0);
    expect(fractions.every((f, i) => i === 0 || f >= fractions[i - 1])).toBe(true);
    expect(fractions[fractions.length - 1]).toBe(1);
    engine.dispose();
  });
});
