/**
 * Aiming adjustable modules (docs/aiming.md): limits (clamp and snap, refusal for fixed types),
 * aimAt, validate()'s rule, and the orientation the lighting scene gets: the peak-intensity
 * direction of the aimed luminaire, turned with the independent reference rotation
 * (src/reference/luminaireRotation.ts) and looked up with src/reference/candelaAt, hits the aimed point.
 */
import { describe, expect, it } from 'vitest';
import { aimAxis, aimToward, aimedOrientation, clampAim } from '../../../../src/core/model/modules/aim';
import { aimAtPoint, modulePosition } from '../../../../src/core/model/actions/aimActions';
import { parseCatalog, type Catalog } from '../../../../src/core/model/catalogSchema/catalogSchema';
import { toLightingScene } from '../../../../src/core/model/files/toLightingScene';
import { validate } from '../../../../src/core/model/validation/validate';
import { candelaAt } from '../../../../src/reference/candelaAt';
import { apply, luminaireToWorld, photometricAngles, worldToLuminaire } from '../../../../src/reference/luminaireRotation';
import type { Vec3 } from '../../../../src/core/model/lightingScene/lightingScene';
import { loadReal } from '../../photometry/helpers';
import { catalog, enabled, run, withPreset } from '../helpers';
import { bindAction } from '../../../../src/core/model/actions/actionDefinitions';
import type { Configuration } from '../../../../src/core/model/configuration/configuration';

const spot = catalog.moduleTypes.find((t) => t.id === 'spot')!;
const flood = catalog.moduleTypes.find((t) => t.id === 'flood')!;
const DEG = Math.PI / 180;

const angleBetween = (a: Vec3, b: Vec3) => {
  const dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return Math.acos(Math.min(1, Math.max(-1, dot / (Math.hypot(...a) * Math.hypot(...b))))) / DEG;
};

/** The single spot preset (three spots on one rail) turned by `rotation`, in an 8 × 6 × 3 m room. */
function spots(rotation = 0): Configuration {
  return withPreset('single', 2, 3, rotation);
}
const firstModule = (s: Configuration) => s.systems[0].rails[0].modules[0];

describe('aim limits', () => {
  it('clamps tilt to its range and snaps both axes to the stops', () => {
    expect(clampAim({ rotation: 10, tilt: 120 }, spot.adjustable!)).toEqual({ rotation: 10, tilt: 90 });
    expect(clampAim({ rotation: 10, tilt: -5 }, spot.adjustable!)).toEqual({ rotation: 10, tilt: 0 });
    expect(clampAim({ rotation: 12.4, tilt: 17.6 }, flood.adjustable!)).toEqual({ rotation: 10, tilt: 20 });
    expect(clampAim({ rotation: 0, tilt: 61 }, flood.adjustable!)).toEqual({ rotation: 0, tilt: 60 });
  });

  it('wraps rotation and moves it out of the 355–360° gap to the nearer end', () => {
    expect(clampAim({ rotation: -30, tilt: 10 }, spot.adjustable!).rotation).toBe(330);
    expect(clampAim({ rotation: 720 + 45, tilt: 10 }, spot.adjustable!).rotation).toBe(45);
    expect(clampAim({ rotation: 357, tilt: 10 }, spot.adjustable!).rotation).toBe(355);
    expect(clampAim({ rotation: 358, tilt: 10 }, spot.adjustable!).rotation).toBe(0);
    // 358.6 snaps to the 360 stop, which is 0.
    expect(clampAim({ rotation: 358.6, tilt: 10 }, flood.adjustable!).rotation).toBe(0);
  });

  it('setAim clamps instead of refusing; a fixed type is refused with the reason', () => {
    const s = spots();
    const id = firstModule(s).id;
    expect(firstModule(run(s, 'setAim', { moduleId: id, aim: { rotation: 400, tilt: 95 } })).aim).toEqual({ rotation: 40, tilt: 90 });
    const [, m1, m2] = s.systems[0].rails[0].modules.map((m) => m.id);
    const linear = run(run(run(s, 'removeModule', { moduleId: m1 }), 'removeModule', { moduleId: m2 }), 'setModuleType', { moduleId: id, type: 'linear' });
    const e = enabled(linear, 'setAim', { moduleId: id, aim: { rotation: 0, tilt: 10 } });
    expect(e).not.toBe(true);
    expect(e !== true && e.reason).toBe('Linear diffuser is fixed: it cannot be aimed');
    expect(() => enabled(s, 'setAim', { moduleId: id, aim: { rotation: Number.NaN, tilt: 10 } })).toThrow(/aim\.rotation/);
  });

  it('switching type keeps the aim within the new limits, and drops it for a fixed type', () => {
    let s = spots();
    const id = firstModule(s).id;
    s = run(s, 'setAim', { moduleId: id, aim: { rotation: 33, tilt: 80 } });
    expect(firstModule(run(s, 'setModuleType', { moduleId: id, type: 'flood' })).aim).toEqual({ rotation: 35, tilt: 60 });
    const washer = bindAction('setModuleType', { moduleId: id, type: 'washer' }, catalog);
    if (washer.isEnabled(s) === true) expect(firstModule(washer.perform(s)).aim).toBeUndefined();
  });

  it('validate() names an aim out of range, off its stops, or on a fixed type', () => {
    const s = spots();
    const withAim = (type: string, aim: { rotation: number; tilt: number }): Configuration => ({
      ...s,
      systems: [{ ...s.systems[0], rails: [{ ...s.systems[0].rails[0], modules: s.systems[0].rails[0].modules.map((m, i) => (i === 0 ? { ...m, type, beam: catalog.moduleTypes.find((t) => t.id === type)!.defaultBeam, aim } : m)) }] }],
    });
    expect(validate(withAim('spot', { rotation: 355, tilt: 90 }), catalog)).toEqual([]);
    expect(validate(withAim('spot', { rotation: 356, tilt: 10 }), catalog).map((p) => [p.code, p.path])).toEqual([['aim-range', 'systems[0].rails[0].modules[0].aim.rotation']]);
    expect(validate(withAim('spot', { rotation: 10, tilt: 91 }), catalog)[0].message).toBe('tilt must be between 0° and 90° (got 91°)');
    expect(validate(withAim('flood', { rotation: 10, tilt: 12 }), catalog)[0].message).toBe('tilt must be a multiple of 5° (got 12°)');
    expect(validate(withAim('spot', { rotation: 360, tilt: 0 }), catalog)[0].code).toBe('aim-range');
    expect(validate(withAim('washer', { rotation: 0, tilt: 0 }), catalog)[0].code).toBe('aim-fixed');
  });

  it('the catalog schema refuses limits off their stops and stops that do not divide 360', () => {
    const base = JSON.parse(JSON.stringify(catalog)) as Catalog & { moduleTypes: { adjustable?: unknown }[] };
    base.moduleTypes[0].adjustable = { tilt: { min: 0, max: 92, stops: 5 }, rotation: { min: 0, max: 355 } };
    expect(() => parseCatalog(base)).toThrow(/moduleTypes\[0\]\.adjustable\.tilt\.max: must be a multiple of stops 5/);
    base.moduleTypes[0].adjustable = { tilt: { min: 0, max: 90 }, rotation: { min: 0, max: 350, stops: 7 } };
    expect(() => parseCatalog(base)).toThrow(/stops: must divide 360/);
  });
});

describe('aimAt', () => {
  it('points the axis through a reachable floor point exactly', () => {
    for (const heading of [0, 90, 217]) {
      const s = spots(heading);
      const id = firstModule(s).id;
      const target: Vec3 = [5.2, 0, 1.3];
      const next = run(s, 'aimAt', { moduleId: id, point: target });
      const aim = firstModule(next).aim!;
      const from = modulePosition(next, id, catalog);
      const axis = aimAxis(next.systems[0].rotation, aim);
      expect(angleBetween(axis, [target[0] - from[0], target[1] - from[1], target[2] - from[2]])).toBeLessThan(1e-5);
    }
  });

  it('stops at the nearest reachable aim: a point above the module gets the 90° limit, a stepped head the nearest stop', () => {
    const s = spots();
    const id = firstModule(s).id;
    const from = modulePosition(s, id, catalog);
    // 1 m to the module's +x (rail direction, rotation 0) and 0.5 m above: tilt would be 116.6°.
    expect(aimAtPoint(s, id, [from[0] + 1, from[1] + 0.5, from[2]], catalog)).toEqual({ rotation: 0, tilt: 90 });
    // straight below keeps the current rotation
    const turned = run(s, 'setAim', { moduleId: id, aim: { rotation: 120, tilt: 30 } });
    expect(aimAtPoint(turned, id, [from[0], 0, from[2]], catalog)).toEqual({ rotation: 120, tilt: 0 });
    const f = run(s, 'setModuleType', { moduleId: id, type: 'flood' });
    const got = aimAtPoint(f, id, [from[0] + 1, 0, from[2] - 1], catalog);
    const ideal = aimToward(from, [from[0] + 1, 0, from[2] - 1], 0)!;
    expect(ideal.rotation).toBeCloseTo(45, 9);
    expect(got.rotation).toBe(45);
    expect(got.tilt).toBe(5 * Math.round(ideal.tilt / 5));
  });

  it('refuses the module position itself and unknown modules', () => {
    const s = spots();
    const id = firstModule(s).id;
    expect(enabled(s, 'aimAt', { moduleId: id, point: modulePosition(s, id, catalog) })).not.toBe(true);
    expect(enabled(s, 'aimAt', { moduleId: 'm999', point: [1, 0, 1] })).not.toBe(true);
  });
});

describe('aimed orientation in the lighting scene', () => {
  const narrow = loadReal('bega_84693_narrow_spot.ies');

  /** The peak of the photometric grid, as a local direction (γ from local −y, C from +x toward −z). */
  function localPeak(): Vec3 {
    let best = -1;
    let dir: Vec3 = [0, -1, 0];
    for (let g = 0; g <= 90; g += 0.25) {
      for (let c = 0; c < 360; c += 5) {
        const I = candelaAt(narrow, g, c);
        if (I > best) {
          best = I;
          dir = [Math.sin(g * DEG) * Math.cos(c * DEG), -Math.cos(g * DEG), -Math.sin(g * DEG) * Math.sin(c * DEG)];
        }
      }
    }
    return dir;
  }

  it('the peak-intensity direction hits the aimed point within 0.5°, for rails at several headings', () => {
    const peak = localPeak();
    const targets: Vec3[] = [
      [6, 0, 5],
      [0.5, 1.2, 0.4],
      [7.9, 1.5, 2.5],
      [2.2, 0, 3.05],
    ];
    for (const heading of [0, 45, 90, 300]) {
      for (const target of targets) {
        const s = spots(heading);
        const id = firstModule(s).id;
        const next = run(s, 'aimAt', { moduleId: id, point: target });
        const l = toLightingScene(next, catalog).luminaires.find((x) => x.id === id)!;
        const world = apply(luminaireToWorld(l.yaw, l.pitch, l.roll), peak);
        const to: Vec3 = [target[0] - l.position[0], target[1] - l.position[1], target[2] - l.position[2]];
        expect(angleBetween(world, to), `heading ${heading}, target ${target.join(',')}, aim ${JSON.stringify(firstModule(next).aim)}, at ${l.position.join(',')}`).toBeLessThan(0.5);
        // and the reference lookup agrees: the intensity toward the target is the file's peak
        const a = photometricAngles(apply(worldToLuminaire(l.yaw, l.pitch, l.roll), to))!;
        expect(candelaAt(narrow, a.gammaDeg, a.cDeg)).toBeCloseTo(candelaAt(narrow, 0, 0), 6);
      }
    }
  });

  it('untilted, rotation turns C0 about the vertical; tilted, C0 stays across the tilt plane (the head turns, then tilts)', () => {
    for (const [heading, rotation] of [
      [0, 0],
      [30, 100],
      [200, 355],
    ] as const) {
      const flat = aimedOrientation(heading, 0, { rotation, tilt: 0 });
      const c0 = apply(luminaireToWorld(flat.yaw, flat.pitch, flat.roll), [1, 0, 0]);
      const a = (heading + rotation) * DEG;
      expect(angleBetween(c0, [Math.cos(a), 0, -Math.sin(a)])).toBeLessThan(1e-5);
      const tilted = aimedOrientation(heading, 0, { rotation, tilt: 40 });
      const m = luminaireToWorld(tilted.yaw, tilted.pitch, tilted.roll);
      // C0 (local +x) tips with the axis in the vertical plane through the aim direction
      const c0t = apply(m, [1, 0, 0]);
      expect(angleBetween(c0t, [Math.cos(40 * DEG) * Math.cos(a), Math.sin(40 * DEG), -Math.cos(40 * DEG) * Math.sin(a)])).toBeLessThan(1e-5);
      expect(angleBetween(apply(m, [0, -1, 0]), aimAxis(heading, { rotation, tilt: 40 }))).toBeLessThan(1e-5);
    }
  });

  it('an unaimed module keeps yaw = heading, pitch 0 and the catalog roll', () => {
    const s = spots(30);
    const l = toLightingScene(s, catalog).luminaires[0];
    expect([l.yaw, l.pitch, l.roll]).toEqual([30, 0, 0]);
  });
});
