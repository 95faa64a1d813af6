/**
 * The reference for rooms of any shape (src/reference/solveRoomReference.ts, issue 29) against
 * exact answers: point-source light in a convex pentagon (CIE 171:2006 §5.2), exact shadow behind
 * the inner corner of an L, flux conservation in black rooms (§5.4) and the closed-room identity
 * Σ E·A = Φ/(1 − ρ) for uniform ρ (§5.8) in an L and attic rooms, and an opening that lets out
 * exactly the light the solid angle it subtends says (black room), with Φ = absorbed + escaped
 * when the walls reflect.
 */
import { describe, expect, it } from 'vitest';
import { Matrix4, Vector3 } from 'three';
import type { LightingLuminaire, Vec3 } from '../../src/core/model/lightingScene/lightingScene';
import { intensity } from '../../src/core/photometry/intensity';
import type { RoomInput, RoomOpening } from '../../src/core/room/roomInput';
import { boxRoomInput } from '../../src/core/room/boxRoom';
import { BOX_FACES } from '../../src/reference/boxGeometry';
import { ReferenceInputError } from '../../src/reference/referenceInputError';
import { sampleReference } from '../../src/reference/sampleReference';
import { solveBoxReference } from '../../src/reference/solveBoxReference';
import { roomIlluminanceAt, roomSurfaceIlluminanceAt, roomSurfaceStatistics } from '../../src/reference/roomIlluminanceAt';
import { roomFluxes, solveRoomReference } from '../../src/reference/solveRoomReference';
import { isotropic, realPhotometry } from './photometryFixtures';

const LUMENS = 1000;
const I = LUMENS / (4 * Math.PI);
const files = { iso: isotropic(LUMENS) };
const lamp = (position: Vec3, photometry = 'iso', angles: Partial<LightingLuminaire> = {}): LightingLuminaire => ({ photometry, position, yaw: 0, pitch: 0, roll: 0, ...angles });
const uniform = (rho: number) => ({ floor: rho, ceiling: rho, walls: rho });
const relErr = (a: number, b: number) => Math.abs(a - b) / Math.abs(b);

/** A convex pentagon in plan (positive orientation). */
const PENTAGON: [number, number][] = [
  [0, 0],
  [4, 0],
  [5, 2.5],
  [2, 4.5],
  [-1, 2.5],
];
const L_OUTLINE: [number, number][] = [
  [0, 0],
  [6, 0],
  [6, 3],
  [3.5, 3],
  [3.5, 5],
  [0, 5],
];

const CHIMNEY_OUTLINE: [number, number][] = [
  [0, 0],
  [1.8, 0],
  [1.8, 0.5],
  [3.2, 0.5],
  [3.2, 0],
  [5, 0],
  [5, 4],
  [0, 4],
];

/** Inward unit normal of the wall a → b of a positively oriented outline (the left normal), independent of src/core/room. */
function wallNormal(a: [number, number], b: [number, number]): Vec3 {
  const l = Math.hypot(b[0] - a[0], b[1] - a[1]);
  return [-(b[1] - a[1]) / l, 0, (b[0] - a[0]) / l];
}

describe('room reference: direct light (CIE 171:2006 §5.2)', () => {
  it('a convex pentagon: E = I·cosθ/d² at floor, ceiling and slanted-wall points, exact; Σ E·A = Φ in a black room', () => {
    const room: RoomInput = { outline: PENTAGON, height: 2.8, reflectance: uniform(0) };
    const pos: Vec3 = [2, 2.2, 2];
    const r = solveRoomReference(room, [lamp(pos)], files, { patchSize: 0.5 });
    const points: [Vec3, Vec3][] = [
      [
        [1, 0, 1],
        [0, 1, 0],
      ],
      [
        [-0.5, 0, 2.4],
        [0, 1, 0],
      ],
      [
        [3, 2.8, 3],
        [0, -1, 0],
      ],
      // Midpoints of the slanted walls 1, 2 and 3 at several heights.
      [[4.5, 1, 1.25], wallNormal(PENTAGON[1], PENTAGON[2])],
      [[3.5, 2.5, 3.5], wallNormal(PENTAGON[2], PENTAGON[3])],
      [[0.5, 0.3, 3.5], wallNormal(PENTAGON[3], PENTAGON[4])],
    ];
    for (const [q, n] of points) {
      const d: Vec3 = [pos[0] - q[0], pos[1] - q[1], pos[2] - q[2]];
      const dist = Math.hypot(...d);
      const expected = (I * (d[0] * n[0] + d[1] * n[1] + d[2] * n[2])) / dist / (dist * dist);
      expect(expected).toBeGreaterThan(0);
      const s = roomIlluminanceAt(r, q, n);
      expect(relErr(s.direct, expected)).toBeLessThan(1e-12);
      expect(s.indirect).toBe(0);
    }
    const flux = roomFluxes(r);
    // Patch means by the midpoint rule on ≥ 4 × 4 pieces: measured −4e-6.
    expect(relErr(flux.direct, LUMENS)).toBeLessThan(2e-3);
    expect(flux.escaped).toBe(0);
  });

  it('a real asymmetric IES, tilted and turned, in the pentagon: matches three.js rotations and src/core/photometry lookup', () => {
    const ph = realPhotometry('aec_italo_streetlight_full360.ies');
    const pos: Vec3 = [2.2, 2.6, 1.7];
    const [yaw, pitch, roll] = [35, 20, -50];
    const r = solveRoomReference({ outline: PENTAGON, height: 2.8, reflectance: uniform(0) }, [lamp(pos, 'street', { yaw, pitch, roll, dimming: 0.8 })], { street: ph }, { patchSize: 1, openingCell: 0 });
    const deg = Math.PI / 180;
    const toLocal = new Matrix4()
      .makeRotationY(yaw * deg)
      .multiply(new Matrix4().makeRotationX(pitch * deg))
      .multiply(new Matrix4().makeRotationY(roll * deg))
      .invert();
    const points: [Vec3, Vec3][] = [
      [
        [1, 0, 1],
        [0, 1, 0],
      ],
      [
        [3.5, 0, 3],
        [0, 1, 0],
      ],
      [[4.5, 1, 1.25], wallNormal(PENTAGON[1], PENTAGON[2])],
      [
        [2, 1.5, 0],
        [0, 0, 1],
      ],
    ];
    for (const [q, n] of points) {
      const dir = new Vector3(q[0] - pos[0], q[1] - pos[1], q[2] - pos[2]);
      const dist = dir.length();
      const local = dir.clone().applyMatrix4(toLocal);
      const gamma = Math.acos(-local.y / dist) / deg;
      const c = (((Math.atan2(-local.z, local.x) / deg) % 360) + 360) % 360;
      const cos = -dir.dot(new Vector3(...n)) / dist;
      const expected = (0.8 * intensity(ph, gamma, c) * cos) / (dist * dist);
      expect(expected).toBeGreaterThan(0);
      expect(relErr(roomIlluminanceAt(r, q, n).direct, expected)).toBeLessThan(1e-9);
    }
  });

  it('the inner corner of an L casts a shadow: exactly zero direct light behind it, I·cosθ/d² beside it', () => {
    const pos: Vec3 = [1, 2.2, 4.5];
    const r = solveRoomReference({ outline: L_OUTLINE, height: 2.6, reflectance: uniform(0.5) }, [lamp(pos)], files, { patchSize: 0.5 });
    expect(r.room.convex).toBe(false);
    // From (1, 4.5) to these plan points the line passes x = 3.5 at z > 3: through the notch.
    expect(roomIlluminanceAt(r, [6, 1.2, 2.5], [-1, 0, 0]).direct).toBe(0);
    expect(roomIlluminanceAt(r, [5.5, 0, 2.8], [0, 1, 0]).direct).toBe(0);
    expect(roomIlluminanceAt(r, [4.5, 2.6, 2.9], [0, -1, 0]).direct).toBe(0);
    // ... but they get light by reflection.
    expect(roomIlluminanceAt(r, [5.5, 0, 2.8], [0, 1, 0]).indirect).toBeGreaterThan(1);
    // The floor patch [5.5, 6] × [2.5, 3] lies wholly in the shadow wedge: its mean is exactly 0 too.
    const shadowed = r.patches.findIndex((p) => p.kind === 'floor' && Math.abs(p.centroid[0] - 5.75) < 1e-9 && Math.abs(p.centroid[2] - 2.75) < 1e-9);
    expect(shadowed).toBeGreaterThanOrEqual(0);
    expect(r.directRgb[3 * shadowed]).toBe(0);
    // In sight: (1, 4.5) → (5.5, 0.5) passes x = 3.5 at z ≈ 2.28 < 3.
    const q: Vec3 = [5.5, 0, 0.5];
    const dist = Math.hypot(pos[0] - q[0], pos[1] - q[1], pos[2] - q[2]);
    expect(relErr(roomIlluminanceAt(r, q, [0, 1, 0]).direct, (I * pos[1]) / dist ** 3)).toBeLessThan(1e-12);
  });

  it('a chimney breast shadows the wall beside it: zero direct light there, by surface name', () => {
    const r = solveRoomReference({ outline: CHIMNEY_OUTLINE, height: 2.5, reflectance: uniform(0.5) }, [lamp([0.5, 2, 3.5])], files, { patchSize: 0.5 });
    // Wall 4 is the north wall east of the breast, z = 0, x 3.2..5: from (0.5, 3.5) the line to
    // (4.5, 0) passes x = 3.2 at z ≈ 1.14 > 0.5 (in sight); to (3.4, 0) it passes x = 3.2 at z ≈ 0.24 < 0.5: behind the breast.
    expect(roomSurfaceIlluminanceAt(r, 'wall-4', [3.4, 1, 0]).direct).toBe(0);
    const q: Vec3 = [4.5, 1, 0];
    const dist = Math.hypot(0.5 - q[0], 2 - q[1], 3.5 - q[2]);
    expect(relErr(roomSurfaceIlluminanceAt(r, 'wall-4', q).direct, (I * 3.5) / dist ** 3)).toBeLessThan(1e-12);
    expect(() => roomSurfaceIlluminanceAt(r, 'slope-0', q)).toThrow(/no surface 'slope-0'/);
  });

  it('refuses a lamp outside the room: in the notch of the L, above a slope', () => {
    expect(() => solveRoomReference({ outline: L_OUTLINE, height: 2.6, reflectance: uniform(0.5) }, [lamp([5, 2, 4])], files, { patchSize: 1 })).toThrow(ReferenceInputError);
    const attic: RoomInput = {
      outline: [
        [0, 0],
        [4, 0],
        [4, 6],
        [0, 6],
      ],
      height: 2.6,
      slopes: [{ wall: 0, kneeHeight: 1.2, pitch: 40 }],
      reflectance: uniform(0.5),
    };
    expect(() => solveRoomReference(attic, [lamp([2, 1.6, 0.3])], files, { patchSize: 1 })).toThrow(/luminaires\[0\]\.position: \[2, 1\.6, 0\.3\] lies outside the room/);
  });
});

/** Solid angle of a planar polygon seen from p, by fanning it into triangles (Van Oosterom & Strackee, IEEE Trans. Biomed. Eng. 30(2), 1983). */
function solidAngle(p: Vec3, poly: Vec3[]): number {
  let sum = 0;
  const v = poly.map((q) => [q[0] - p[0], q[1] - p[1], q[2] - p[2]]);
  const len = (a: number[]) => Math.hypot(a[0], a[1], a[2]);
  const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  for (let k = 1; k + 1 < v.length; k++) {
    const [a, b, c] = [v[0], v[k], v[k + 1]];
    const triple = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
    const den = len(a) * len(b) * len(c) + dot(a, b) * len(c) + dot(a, c) * len(b) + dot(b, c) * len(a);
    sum += 2 * Math.atan2(Math.abs(triple), den);
  }
  return sum;
}

describe('room reference: flux balance (CIE 171:2006 §5.4, §5.8)', () => {
  // Σ E·A over a closed room of uniform ρ is Φ/(1 − ρ) exactly when the form factors close
  // (Σ_j F_ij = 1); here they close to the accuracy of point-to-polygon factors from 1, 4 or 16
  // pieces of the receiving patch, so the balance holds to ≈ ρ/(1 − ρ) × the closure error.
  // Measured at 0.5 m patches: L +0.18 % (+0.10 % at 0.25 m), L with a slope +0.16 %, chimney breast ρ 0.6 +0.32 %, gable attic
  // ρ 0.7 +0.48 % (+0.28 % at 0.3 m); direct Σ E·A within 6e-5 of Φ.
  const cases: [string, RoomInput, Vec3, number, number][] = [
    ['an L', { outline: L_OUTLINE, height: 2.6, reflectance: uniform(0.5) }, [1, 2.2, 4.5], 0.5, 5e-3],
    ["an L with a roof slope on wall 0 (the issue's attic)", { outline: L_OUTLINE, height: 2.6, slopes: [{ wall: 0, kneeHeight: 1.2, pitch: 40 }], reflectance: uniform(0.5) }, [1, 2.2, 4.5], 0.5, 5e-3],
    // A 5 × 4 m room with a 1.4 × 0.5 m chimney breast standing out of the north wall at x 1.8..3.2.
    ['a room with a chimney breast', { outline: CHIMNEY_OUTLINE, height: 2.5, reflectance: uniform(0.6) }, [1, 2, 2.5], 0.6, 5e-3],
    [
      'a gable attic with two knee walls',
      {
        outline: [
          [0, 0],
          [4, 0],
          [4, 6],
          [0, 6],
        ],
        height: 2.6,
        slopes: [
          { wall: 0, kneeHeight: 1.2, pitch: 40 },
          { wall: 2, kneeHeight: 1.0, pitch: 50 },
        ],
        reflectance: uniform(0.7),
      },
      [2, 1.8, 3],
      0.7,
      1e-2,
    ],
  ];
  for (const [name, room, pos, rho, tol] of cases) {
    it(`${name}, ρ = ${rho}: Σ E·A = Φ/(1 − ρ) within ${tol * 100} %, and Σ E_dir·A = Φ`, () => {
      const r = solveRoomReference(room, [lamp(pos)], files, { patchSize: 0.5 });
      const flux = roomFluxes(r);
      expect(relErr(flux.direct, LUMENS)).toBeLessThan(1e-3);
      expect(relErr(flux.total, LUMENS / (1 - rho))).toBeLessThan(tol);
      expect(relErr(flux.absorbed, LUMENS)).toBeLessThan(tol);
      expect(flux.escaped).toBe(0);
      // Per-surface statistics add up to the same flux and the floor's area is the outline's.
      const stats = roomSurfaceStatistics(r);
      expect(
        relErr(
          stats.reduce((sum, s) => sum + s.flux, 0),
          flux.total,
        ),
      ).toBeLessThan(1e-12);
      const floor = stats.find((s) => s.id === 'floor')!;
      expect(floor.area).toBeCloseTo(r.surfaces.find((s) => s.id === 'floor')!.area, 9);
      expect(floor.min).toBeLessThanOrEqual(floor.mean);
      expect(floor.max).toBeGreaterThanOrEqual(floor.mean);
    });
  }
});

describe('room reference: openings let light out', () => {
  const window: RoomOpening = { wall: 0, offset: 1, width: 1.2, sill: 0.9, height: 1.1, kind: 'window' };
  const door: RoomOpening = { wall: 3, offset: 0.5, width: 0.9, sill: 0, height: 2, kind: 'door' };
  const room = (rho: number): RoomInput => ({
    outline: [
      [0, 0],
      [4, 0],
      [4, 3],
      [0, 3],
    ],
    height: 2.5,
    openings: [window, door],
    reflectance: uniform(rho),
  });
  const pos: Vec3 = [2, 1.8, 1.5];

  it('black room: the direct light through each opening is I × the solid angle it subtends', () => {
    const r = solveRoomReference(room(0), [lamp(pos)], files, { patchSize: 0.5 });
    // The window: z = 0, x 1..2.2, y 0.9..2; the door: wall 3 runs (0, 3) → (0, 0), so x = 0, z 2.5 → 1.6, y 0..2.
    const windowOmega = solidAngle(pos, [
      [1, 0.9, 0],
      [2.2, 0.9, 0],
      [2.2, 2, 0],
      [1, 2, 0],
    ]);
    const doorOmega = solidAngle(pos, [
      [0, 0, 2.5],
      [0, 0, 1.6],
      [0, 2, 1.6],
      [0, 2, 2.5],
    ]);
    const through = (opening: number) => r.patches.reduce((sum, p, i) => sum + (p.kind === 'opening' && p.opening === opening ? p.area * r.directRgb[3 * i] : 0), 0);
    // Measured: window 0.058 %, door 0.040 % (the midpoint rule on 4 × 4 pieces per patch).
    expect(relErr(through(0), I * windowOmega)).toBeLessThan(1e-3);
    expect(relErr(through(1), I * doorOmega)).toBeLessThan(1e-3);
    const flux = roomFluxes(r);
    // Measured 1e-4: every lumen lands on a surface or leaves through an opening.
    expect(relErr(flux.direct + flux.escaped, LUMENS)).toBeLessThan(1e-3);
  });

  it('reflecting room (ρ 0.6): Φ = absorbed + escaped, and reflections carry more light out than the direct beam', () => {
    const r = solveRoomReference(room(0.6), [lamp(pos)], files, { patchSize: 0.5 });
    const flux = roomFluxes(r);
    // Measured +0.22 % (the form factors' closure, as in the closed rooms above).
    expect(relErr(flux.absorbed + flux.escaped, LUMENS)).toBeLessThan(5e-3);
    expect(flux.escaped).toBeGreaterThan(1.5 * flux.escapedDirect);
    // An opening reflects nothing: no light comes back from it.
    r.patches.forEach((p, i) => {
      if (p.kind === 'opening') expect(r.exitanceRgb[3 * i]).toBe(0);
    });
  });
});

describe('room reference: the rectangle outline agrees with the box reference', () => {
  it('direct exact, indirect within 0.5 % RMS (1.5 % worst) of solveBoxReference at 7 × 7 points per surface', () => {
    // Measured (box reference at 0.2 m patches, this one at 0.25 m): RMS 0.14 %, worst 0.70 %.
    const rho = { floor: 0.3, ceiling: 0.8, north: 0.5, east: 0.6, south: 0.4, west: 0.7 };
    const box = { width: 4, height: 2.6, depth: 3, reflectance: rho };
    const lamps = [lamp([1.2, 2.2, 0.9]), lamp([3.1, 1.5, 2.2])];
    const a = solveBoxReference({ version: 1, room: box, luminaires: lamps }, files, { patchSize: 0.2 });
    const b = solveRoomReference(boxRoomInput(box), lamps, files, { patchSize: 0.25 });
    let worst = 0;
    let sq = 0;
    let count = 0;
    for (const face of BOX_FACES) {
      const extent = [box.width, box.height, box.depth];
      for (let i = 0; i < 7; i++) {
        for (let j = 0; j < 7; j++) {
          const q: Vec3 = [0, 0, 0];
          q[face.axis] = face.side === 0 ? 0 : extent[face.axis];
          q[face.uAxis] = ((i + 0.5) / 7) * extent[face.uAxis];
          q[face.vAxis] = ((j + 0.5) / 7) * extent[face.vAxis];
          const s = sampleReference(a, q, face.name);
          const t = roomIlluminanceAt(b, q, face.normal);
          expect(relErr(t.direct, s.direct)).toBeLessThan(1e-12);
          const e = relErr(t.indirect, s.indirect);
          worst = Math.max(worst, e);
          sq += e * e;
          count++;
        }
      }
    }
    expect(Math.sqrt(sq / count)).toBeLessThan(5e-3);
    expect(worst).toBeLessThan(1.5e-2);
  });
});
