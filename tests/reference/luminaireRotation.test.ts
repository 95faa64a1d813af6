import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { Euler, Matrix4, Vector3 } from 'three';
import type { Vec3 } from '../../src/core/model/lightingScene/lightingScene';
import { apply, luminaireToWorld, photometricAngles, worldToLuminaire } from '../../src/reference/luminaireRotation';

const close = (a: Vec3, b: Vec3, tol = 1e-12): void => {
  for (let i = 0; i < 3; i++) expect(Math.abs(a[i] - b[i])).toBeLessThan(tol);
};

describe('luminaire frame (docs/scene-format.md "Units and frames")', () => {
  it('all angles zero: nadir along −y, C0 along +x, C90 along −z', () => {
    const m = luminaireToWorld(0, 0, 0);
    close(apply(m, [0, -1, 0]), [0, -1, 0]);
    close(apply(m, [1, 0, 0]), [1, 0, 0]);
  });

  it('Rx(+90°) turns the nadir from −y to −z; Ry(+90°) turns +x to −z (counterclockwise seen from above)', () => {
    close(apply(luminaireToWorld(0, 90, 0), [0, -1, 0]), [0, 0, -1]);
    close(apply(luminaireToWorld(90, 0, 0), [1, 0, 0]), [0, 0, -1]);
    close(apply(luminaireToWorld(0, 0, 90), [1, 0, 0]), [0, 0, -1]);
  });

  it('is world = Ry(yaw)·Rx(pitch)·Ry(roll)·local, as three.js composes it independently', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -360, max: 360, noNaN: true }),
        fc.double({ min: -180, max: 180, noNaN: true }),
        fc.double({ min: -360, max: 360, noNaN: true }),
        fc.tuple(fc.double({ min: -1, max: 1, noNaN: true }), fc.double({ min: -1, max: 1, noNaN: true }), fc.double({ min: -1, max: 1, noNaN: true })),
        (yaw, pitch, roll, v) => {
          const d = Math.PI / 180;
          const m = new Matrix4()
            .makeRotationY(yaw * d)
            .multiply(new Matrix4().makeRotationX(pitch * d))
            .multiply(new Matrix4().makeRotationY(roll * d));
          const expected = new Vector3(...v).applyMatrix4(m);
          const got = apply(luminaireToWorld(yaw, pitch, roll), v);
          const back = apply(worldToLuminaire(yaw, pitch, roll), got);
          // Same composition as Euler order 'YXY' is not offered by three; 'YXZ' with z = 0 then Ry(roll) is a second route.
          const viaEuler = new Vector3(...v).applyMatrix4(new Matrix4().makeRotationY(roll * d)).applyMatrix4(new Matrix4().makeRotationFromEuler(new Euler(pitch * d, yaw * d, 0, 'YXZ')));
          return (
            Math.abs(got[0] - expected.x) + Math.abs(got[1] - expected.y) + Math.abs(got[2] - expected.z) < 1e-12 &&
            Math.abs(viaEuler.x - expected.x) + Math.abs(viaEuler.y - expected.y) + Math.abs(viaEuler.z - expected.z) < 1e-12 &&
            Math.abs(back[0] - v[0]) + Math.abs(back[1] - v[1]) + Math.abs(back[2] - v[2]) < 1e-12
          );
        },
      ),
      { seed: 3, numRuns: 300 },
    );
  });
});

describe('photometric angles of a local direction (IES type C)', () => {
  it('γ from the nadir, C from +x toward −z', () => {
    const cases: [Vec3, number, number][] = [
      [[0, -1, 0], 0, 0],
      [[1, 0, 0], 90, 0],
      [[0, 0, -1], 90, 90],
      [[-1, 0, 0], 90, 180],
      [[0, 0, 1], 90, 270],
      [[1, -1, 0], 45, 0],
      [[0, 1, -1], 135, 90],
    ];
    for (const [v, g, c] of cases) {
      const a = photometricAngles(v);
      expect(a?.gammaDeg).toBeCloseTo(g, 12);
      expect(a?.cDeg).toBeCloseTo(c, 12);
    }
    expect(photometricAngles([0, 0, 0])).toBeNull();
  });
});
