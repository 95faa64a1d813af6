import { describe, expect, it } from 'vitest';
import { railPlacements, systemBounds, modulePlacements, rectsOverlap } from '../../../../src/core/model/rails/geometry';
import { toLightingScene } from '../../../../src/core/model/files/toLightingScene';
import { cctToLinearRgb } from '../../../../src/core/photometry/cct';
import { catalog, only, run, withPreset } from '../helpers';

// Preset 'corner-l': rail 2.0 m (spot, flood, spot, flood; inside-centred), 90° left corner
// (arm 0.05 m), rail 1.5 m (two 0.25 m washers, start). Room 8 × 6 × 3 m, suspension 0.6 m.
describe('plan geometry', () => {
  it('chains rails through a corner (heading 0)', () => {
    const s = only(withPreset('corner-l', 1, 3));
    const [r0, r1] = railPlacements(s, catalog);
    expect(r0.start).toEqual([1, 3]);
    expect(r0.end[0]).toBeCloseTo(3, 12);
    expect(r0.end[1]).toBeCloseTo(3, 12);
    // pivot at x = 3.05; a left turn (counterclockwise from above) heads along −z
    expect(r1.heading).toBe(90);
    expect(r1.start[0]).toBeCloseTo(3.05, 12);
    expect(r1.start[1]).toBeCloseTo(2.95, 12);
    expect(r1.end[1]).toBeCloseTo(1.45, 12);
    const b = systemBounds(s, catalog);
    expect(b.minX).toBeCloseTo(1, 12);
    expect(b.maxX).toBeCloseTo(3.075, 12);
    expect(b.minZ).toBeCloseTo(1.45, 12);
    expect(b.maxZ).toBeCloseTo(3.025, 12);
  });

  it('places modules by distribution', () => {
    const s = only(withPreset('corner-l', 1, 3));
    const p = modulePlacements(s, catalog);
    expect(p.map((m) => m.centre[0]).slice(0, 4)).toEqual([1.25, 1.75, 2.25, 2.75].map((x) => expect.closeTo(x, 12)));
    expect(p[4].centre[0]).toBeCloseTo(3.05, 12);
    expect(p[4].centre[1]).toBeCloseTo(2.825, 12);
    expect(p[5].centre[1]).toBeCloseTo(2.575, 12);
  });

  it('separating-axis overlap: crossing bars overlap, touching ones do not', () => {
    const bar = { centre: [0, 0] as const, axis: [1, 0] as const, halfLength: 1, halfWidth: 0.1 };
    expect(rectsOverlap(bar, { ...bar, axis: [Math.SQRT1_2, Math.SQRT1_2] })).toBe(true);
    expect(rectsOverlap(bar, { ...bar, centre: [0, 0.2] })).toBe(false);
    expect(rectsOverlap(bar, { ...bar, centre: [2.0, 0] })).toBe(false);
    expect(rectsOverlap(bar, { ...bar, centre: [1.99, 0] })).toBe(true);
  });
});

describe('toLightingScene', () => {
  it('one luminaire per module at y = ceiling − suspension, yaw = rail heading, roll from the optic', () => {
    const config = withPreset('corner-l', 1, 3);
    const scene = toLightingScene(config, catalog);
    expect(scene.version).toBe(1);
    expect(scene.room).toMatchObject({ width: 8, depth: 6, height: 3 });
    expect(scene.luminaires).toHaveLength(6);
    const [spot, , , , washer] = scene.luminaires;
    expect(spot.photometry).toBe('ies/bega_84693_narrow_spot.ies');
    expect(spot.position[0]).toBeCloseTo(1.25, 12);
    expect(spot.position[1]).toBeCloseTo(2.4, 12);
    expect(spot.position[2]).toBeCloseTo(3, 12);
    expect([spot.yaw, spot.pitch, spot.roll]).toEqual([0, 0, 0]);
    expect(spot.color).toEqual(cctToLinearRgb(3000));
    expect(spot.dimming).toBe(1);
    expect(washer.photometry).toBe('ies/erco_kubus_floor_washlight.ies');
    expect(washer.position.map((v) => Math.round(v * 1e9) / 1e9)).toEqual([3.05, 2.4, 2.825]);
    expect([washer.yaw, washer.roll]).toEqual([90, 90]);
    expect(washer.id).toBe(only(config).rails[1].modules[0].id);
  });

  it('follows the system rotation (heading 90: first rail along −z)', () => {
    const scene = toLightingScene(withPreset('corner-l', 4, 4, 90), catalog);
    const [spot, , , , washer] = scene.luminaires;
    expect(spot.position[0]).toBeCloseTo(4, 12);
    expect(spot.position[2]).toBeCloseTo(3.75, 12);
    expect(spot.yaw).toBe(90);
    // rail 1 starts at (4 − 0.05, 4 − 2 − 0.05) and heads along −x
    expect(washer.position[0]).toBeCloseTo(3.825, 12);
    expect(washer.position[2]).toBeCloseTo(1.95, 12);
    expect(washer.yaw).toBe(180);
  });

  it('carries CCT, dimming and the photometry base', () => {
    let config = withPreset('single', 1, 1);
    const m = only(config).rails[0].modules[1];
    config = run(config, 'setModuleCct', { moduleId: m.id, cct: 4000 });
    config = run(config, 'setModuleDimming', { moduleId: m.id, dimming: 0.25 });
    const l = toLightingScene(config, catalog, { photometryBase: '../public/' }).luminaires[1];
    expect(l.photometry).toBe('../public/ies/bega_84693_narrow_spot.ies');
    expect(l.color).toEqual(cctToLinearRgb(4000));
    expect(l.dimming).toBe(0.25);
  });
});
