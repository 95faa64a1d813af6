import { describe, expect, it } from 'vitest';
import { MAX_HALF_ANGLE_DEG, beamFootprint } from '../../../src/ui/planner/beamFootprint';

describe('beamFootprint', () => {
  it('a 60° downlight 2.4 m above the floor lights a circle of radius 2.4·tan 30° = 1.3856 m', () => {
    const f = beamFootprint({ center: { x: 1, z: 2 }, axisDeg: 0, length: 0, height: 2.4, beamAlongDeg: 60, beamAcrossDeg: 60 });
    expect(f.rx).toBeCloseTo(1.385641, 5);
    expect(f.ry).toBeCloseTo(1.385641, 5);
    expect(f.center).toEqual({ x: 1, z: 2 });
  });

  it('a linear module adds half its length along the rail only', () => {
    const f = beamFootprint({ center: { x: 0, z: 0 }, axisDeg: 90, length: 1.2, height: 2, beamAlongDeg: 90, beamAcrossDeg: 90 });
    expect(f.rx).toBeCloseTo(0.6 + 2, 9);
    expect(f.ry).toBeCloseTo(2, 9);
    expect(f.rotationDeg).toBe(90);
  });

  it('a tilted beam shifts across the rail; the edge rays land at h·tan(t∓β/2)', () => {
    // Rail along +x, tilt 30° towards +z, beam 20°: edges at 2·tan 20° and 2·tan 40°.
    const f = beamFootprint({ center: { x: 0, z: 0 }, axisDeg: 0, length: 0, height: 2, beamAlongDeg: 20, beamAcrossDeg: 20, tiltDeg: 30 });
    const near = 2 * Math.tan((20 * Math.PI) / 180);
    const far = 2 * Math.tan((40 * Math.PI) / 180);
    expect(f.center.z - f.ry).toBeCloseTo(near, 9);
    expect(f.center.z + f.ry).toBeCloseTo(far, 9);
    expect(f.center.x).toBeCloseTo(0, 12);
  });

  it('caps flat rays so a 180° beam stays finite', () => {
    const f = beamFootprint({ center: { x: 0, z: 0 }, axisDeg: 0, length: 0, height: 2, beamAlongDeg: 180, beamAcrossDeg: 180 });
    const cap = 2 * Math.tan((MAX_HALF_ANGLE_DEG * Math.PI) / 180);
    expect(f.rx).toBeCloseTo(cap, 9);
    expect(Number.isFinite(f.ry)).toBe(true);
  });

  it('never returns NaN for junk input', () => {
    const f = beamFootprint({ center: { x: 0, z: 0 }, axisDeg: Number.NaN, length: -1, height: Number.POSITIVE_INFINITY, beamAlongDeg: Number.NaN, beamAcrossDeg: -5 });
    for (const v of [f.rx, f.ry, f.center.x, f.center.z, f.rotationDeg]) expect(Number.isFinite(v)).toBe(true);
  });
});
