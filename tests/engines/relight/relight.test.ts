import { describe, expect, it } from 'vitest';
import { LUMINANCE_WEIGHTS } from '../../../src/engines/bake/bakedMaps';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { SURFACE_NAMES, type Rgb } from '../../../src/core/model/lightingScene';
import { createRelightEngine } from '../../../src/engines/relight/createRelightEngine';
import { groupLuminaires, groupWeight } from '../../../src/engines/relight/luminaireGroups';
import { loadIes, uniformRoom } from '../bake/bakeTestKit';
import { withHeadlessGL } from '../bake/withHeadlessGL';

const gl = withHeadlessGL();
// Coarse but real: a 3 × 2.6 × 3.4 m grey room, two real photometric files, 2 bounces.
const SETTINGS = { texelSize: 0.1, maxTextureSize: 64, samples: 16, bounces: 2, samplesPerDraw: 8, blurRadius: 2, seed: 7 };
const spot = loadIes('bega_84693_narrow_spot.ies');
const down = loadIes('bega_50975_downlight_lm1995_crlf.ies');
const room = uniformRoom(3, 2.6, 3.4, 0.5);
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

describe('relighting = weighted sum of basis maps (light is linear)', () => {
  // With a fixed seed the pure Monte Carlo gather (brightPatches 0) is a linear operator of the direct
  // maps: group bakes add up to the full bake but for the tail estimate (2e-4 of the peak). The default
  // bright-patch bounce 1 picks its exactly gathered tiles from each bake's own maps, so groups and the
  // full bake split the light differently: they agree to the Monte Carlo noise of these coarse
  // settings (16 samples), not bit for bit.
  for (const [label, extra, totalTolerance] of [
    ['pure Monte Carlo', { brightPatches: 0 }, 2e-4],
    ['default bright patches', {}, 5e-3],
  ] as const) it(`matches a full bake of the dimmed, coloured scene (${label}): direct to 1e-5, total to ${totalTolerance} of the peak`, () => {
    const settings = { ...SETTINGS, ...extra };
    const engine = createRelightEngine(gl, settings);
    const weights: [number, Rgb][] = [
      [0.3, [1, 0.8, 0.6]],
      [0.9, [0.7, 0.9, 1]],
    ];
    const scene: BakeScene = { room, luminaires: [lum(spot, 1, 1, ...weights[0]), lum(down, 2.1, 2.5, ...weights[1])] };
    engine.setScene(scene);
    engine.finish();
    const lit = engine.maps();
    const reference = createBaker(gl).bake(scene, settings).maps;
    let peak = 0;
    let worstDirect = 0;
    let worstTotal = 0;
    for (const n of SURFACE_NAMES) {
      const ref = reference[n];
      for (let i = 0; i < ref.total.length; i++) peak = Math.max(peak, ref.total[i]);
      for (let i = 0; i < ref.total.length; i++) {
        worstDirect = Math.max(worstDirect, Math.abs(lit.maps[n].direct[i] - ref.direct[i]));
        worstTotal = Math.max(worstTotal, Math.abs(lit.maps[n].total[i] - ref.total[i]));
      }
    }
    expect(peak).toBeGreaterThan(100);
    expect(worstDirect / peak).toBeLessThan(1e-5);
    expect(worstTotal / peak).toBeLessThan(totalTolerance);
    engine.dispose();
  });

  it('dimming and colour changes relight without a bake; a moved luminaire bakes only its group; a room change bakes all', () => {
    const engine = createRelightEngine(gl, SETTINGS);
    const base = [lum(spot, 1, 1), lum(down, 2.1, 2.5), lum(spot, 2, 1)];
    expect(engine.setScene({ room, luminaires: base })).toEqual({ bake: 3, reused: 0 });
    engine.finish();
    expect(engine.counters.groupBakes).toBe(3);
    const floorLux = () => {
      const f = engine.maps().maps.floor.total;
      let s = 0;
      for (let i = 0; i < f.length; i += 3) s += LUMINANCE_WEIGHTS[0] * f[i] + LUMINANCE_WEIGHTS[1] * f[i + 1] + LUMINANCE_WEIGHTS[2] * f[i + 2];
      return s / (f.length / 3);
    };
    const full = floorLux();

    // Dim the downlight to 0 (off): no bake, and the floor loses exactly that group's share.
    const off = [base[0], { ...base[1], dimming: 0 }, base[2]];
    expect(engine.setScene({ room, luminaires: off })).toEqual({ bake: 0, reused: 3 });
    expect(engine.progress.done).toBe(true);
    const withoutDown = floorLux();
    engine.setScene({ room, luminaires: [{ ...base[0], dimming: 0 }, base[1], { ...base[2], dimming: 0 }] });
    const downOnly = floorLux();
    expect(withoutDown + downOnly).toBeCloseTo(full, 3);
    expect(engine.counters.groupBakes).toBe(3);
    expect(engine.counters.relightsOnly).toBe(2);

    // Move one spot: only its group is baked.
    const moved = [base[0], base[1], lum(spot, 2.2, 1)];
    expect(engine.setScene({ room, luminaires: moved })).toEqual({ bake: 1, reused: 2 });
    engine.finish();
    expect(engine.counters.groupBakes).toBe(4);

    // Another room: every group again.
    expect(engine.setScene({ room: uniformRoom(3.2, 2.6, 3.4, 0.5), luminaires: moved })).toEqual({ bake: 3, reused: 0 });
    engine.dispose();
  });

  it('shows light before the indirect work is done, and refines progressively', () => {
    const engine = createRelightEngine(gl, SETTINGS);
    engine.setScene({ room, luminaires: [lum(spot, 1.5, 1.7)] });
    let p = engine.step(8); // first call: the direct-only basis
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
