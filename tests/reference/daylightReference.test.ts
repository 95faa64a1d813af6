/**
 * The daylight reference (issue 30, "Accuracy"): a uniform sky through an unglazed window is
 * π L × the exact point-to-polygon (view) factor; the CIE overcast sky (and glass) against an
 * independent area integration over the opening; the sun patch's edges and illuminance against
 * geometry; the flux balance entering = absorbed + leaving with reflecting surfaces.
 */
import { describe, expect, it } from 'vitest';
import { glazingFrom, glazingTransmittance, type Glazing } from '../../src/core/daylight/glazing';
import { cieGeneralSky, cieOvercastSky, uniformSky, type Sky } from '../../src/core/daylight/skies';
import { sunDirection } from '../../src/core/daylight/solarPosition';
import type { Vec3 } from '../../src/core/model/lightingScene/lightingScene';
import type { RoomInput } from '../../src/core/room/roomInput';
import { daylightL } from '../../src/hosts/bench/daylightBox';
import { skyThroughWindow, sunThroughWindow } from '../../src/reference/daylightDirect';
import { pointToPolygonFormFactor } from '../../src/reference/pointToPolygonFormFactor';
import { daylightIlluminanceAt, solveDaylightReference, type DaylightReferenceInput } from '../../src/reference/solveDaylightReference';
import { roomFluxes } from '../../src/reference/solveRoomReference';

const relErr = (a: number, b: number) => Math.abs(a - b) / Math.abs(b);
const uniform = (rho: number) => ({ floor: rho, ceiling: rho, walls: rho });
const UP: Vec3 = [0, 1, 0];

// A 5 × 4 m room, 2.8 m high; wall 2 is the south wall z = 4 (from corner (5, 4) to (0, 4)).
// Its window: offset 1.75 m from (5, 4), 1.5 m wide, sill 0.9 m, 1.4 m high: x 1.75 … 3.25, y 0.9 … 2.3.
const OUTLINE: [number, number][] = [
  [0, 0],
  [5, 0],
  [5, 4],
  [0, 4],
];
const WINDOW = { x0: 1.75, x1: 3.25, y0: 0.9, y1: 2.3, z: 4 };
const room = (rho: number | { floor: number; ceiling: number; walls: number }): RoomInput => ({
  outline: OUTLINE,
  height: 2.8,
  openings: [{ wall: 2, offset: 1.75, width: 1.5, sill: 0.9, height: 1.4, kind: 'window' }],
  reflectance: typeof rho === 'number' ? uniform(rho) : rho,
});
const rect = (x0: number, x1: number, y0: number, y1: number): Vec3[] => [
  [x0, y0, WINDOW.z],
  [x1, y0, WINDOW.z],
  [x1, y1, WINDOW.z],
  [x0, y1, WINDOW.z],
];

/** 4-point Gauss–Legendre nodes and weights on [−1, 1]. */
const G4 = [
  [-0.8611363115940526, 0.3478548451374538],
  [-0.3399810435848563, 0.6521451548625461],
  [0.3399810435848563, 0.6521451548625461],
  [0.8611363115940526, 0.3478548451374538],
];

/**
 * E at p (normal n) from luminance L(d) behind the window, transmitted τ(cos θ_w), by the plain
 * area integral E = ∫∫ L τ cos θ_p cos θ_w / r² dx dy over the rectangle, split at p's height,
 * with composite 4-point Gauss–Legendre on 40 × 40 cells: no form factors, no centroids.
 */
function areaIntegral(p: Vec3, n: Vec3, sky: (d: Vec3) => number, ground: number, tau: (c: number) => number, window = WINDOW): number {
  const WINDOW = window;
  const ys = [WINDOW.y0, WINDOW.y1];
  if (p[1] > WINDOW.y0 && p[1] < WINDOW.y1) ys.splice(1, 0, p[1]);
  let e = 0;
  const cells = 40;
  for (let k = 0; k + 1 < ys.length; k++) {
    for (let i = 0; i < cells; i++) {
      for (let j = 0; j < cells; j++) {
        const hx = (WINDOW.x1 - WINDOW.x0) / cells / 2;
        const hy = (ys[k + 1] - ys[k]) / cells / 2;
        for (const [a, wa] of G4) {
          for (const [b, wb] of G4) {
            const q: Vec3 = [WINDOW.x0 + hx * (2 * i + 1 + a), ys[k] + hy * (2 * j + 1 + b), WINDOW.z];
            const d: Vec3 = [q[0] - p[0], q[1] - p[1], q[2] - p[2]];
            const r = Math.hypot(...d);
            const u: Vec3 = [d[0] / r, d[1] / r, d[2] / r];
            const cp = Math.max(0, u[0] * n[0] + u[1] * n[1] + u[2] * n[2]);
            const cw = u[2]; // the window's outward normal is +z
            const l = u[1] > 0 ? sky(u) : ground;
            e += (wa * wb * hx * hy * l * tau(cw) * cp * cw) / (r * r);
          }
        }
      }
    }
  }
  return e;
}

const daylight = (sky: Sky | null, extra: Partial<DaylightReferenceInput> = {}): DaylightReferenceInput => ({ sky, sun: null, groundReflectance: 0.2, ...extra });

describe('daylight reference: sky through a window', () => {
  it('uniform sky, unglazed window, black room: E = π L × the exact form factor on the floor and on walls (≤ 1e-9)', () => {
    const sky = uniformSky(10000);
    // E = π L F with F the view factor (Lambert's contour integral): the whole sky gives π L = 10 000 lx.
    const L = 10000 / Math.PI;
    const r = solveDaylightReference(room(0), daylight(sky, { groundReflectance: 0 }), { patchSize: 1 });
    for (const p of [
      [2.5, 0, 3],
      [0.4, 0, 3.6],
      [4.6, 0, 0.3],
      [2.5, 0, 0.05],
    ] as Vec3[]) {
      const e = daylightIlluminanceAt(r, p, UP).direct;
      expect(relErr(e, Math.PI * L * pointToPolygonFormFactor(p, UP, rect(WINDOW.x0, WINDOW.x1, WINDOW.y0, WINDOW.y1)))).toBeLessThan(1e-9);
    }
    // A point on the east wall at 1.4 m sees sky above its horizon and the ground (ρ 0.2 of 10 klx) below.
    const withGround = solveDaylightReference(room(0), daylight(sky), { patchSize: 1 });
    const Lg = (0.2 * 10000) / Math.PI;
    for (const [p, n] of [
      [
        [5, 1.4, 2],
        [-1, 0, 0],
      ],
      [
        [0, 0.5, 3.5],
        [1, 0, 0],
      ],
      [
        [2.5, 1.2, 0],
        [0, 0, 1],
      ],
      [
        [2.5, 2.8, 3],
        [0, -1, 0],
      ],
    ] as [Vec3, Vec3][]) {
      const cut = Math.min(Math.max(p[1], WINDOW.y0), WINDOW.y1);
      const above = cut < WINDOW.y1 ? pointToPolygonFormFactor(p, n, rect(WINDOW.x0, WINDOW.x1, cut, WINDOW.y1)) : 0;
      const below = cut > WINDOW.y0 ? pointToPolygonFormFactor(p, n, rect(WINDOW.x0, WINDOW.x1, WINDOW.y0, cut)) : 0;
      expect(relErr(daylightIlluminanceAt(withGround, p, n).direct, Math.PI * (L * above + Lg * below))).toBeLessThan(1e-9);
    }
  });

  it('CIE overcast sky through the vertical window: within 2 % of an independent area integration, near and far (measured ≤ 0.09 %)', () => {
    const sky = cieOvercastSky(10000);
    const Lg = (0.2 * 10000) / Math.PI;
    const r = solveDaylightReference(room(0), daylight(sky), { patchSize: 1 });
    const cases: [Vec3, Vec3][] = [
      [[2.5, 0.8, 3.3], UP], // near: 0.7 m from the window, on the work plane
      [[2.5, 0.8, 0.4], UP], // far: 3.6 m away, the window a small bright region
      [[0.3, 0.8, 0.3], UP], // far corner
      [
        [5, 1.6, 3],
        [-1, 0, 0],
      ], // the east wall beside the window: sky and ground
      [
        [2.5, 1.2, 0],
        [0, 0, 1],
      ], // the north wall facing it
    ];
    let worst = 0;
    for (const [p, n] of cases) {
      const expected = areaIntegral(p, n, sky.luminance, Lg, () => 1);
      const err = relErr(daylightIlluminanceAt(r, p, n).direct, expected);
      worst = Math.max(worst, err);
      expect(err, `at ${p}`).toBeLessThan(0.02);
    }
    // Measured: 1e-6 at 0.7 m, 0.08 % at 3.6 m (8 × 8 cells of the window there).
    expect(worst).toBeLessThan(2e-3);
  });

  it('double glazing and a CIE clear sky: the angular transmittance and the sky integrated alike (within 1 %)', () => {
    const glass: Glazing = glazingFrom('double');
    const sky = cieGeneralSky(12, sunDirection(35, 160), 15000);
    const Lg = (0.2 * 15000) / Math.PI;
    const r = solveDaylightReference(room(0), daylight(sky, { glazing: { 0: glass } }), { patchSize: 1 });
    for (const [p, n] of [
      [[2.5, 0.8, 3.3], UP],
      [[1, 0.8, 0.5], UP],
      [
        [5, 1.6, 3],
        [-1, 0, 0],
      ],
    ] as [Vec3, Vec3][]) {
      const expected = areaIntegral(p, n, sky.luminance, Lg, (c) => glazingTransmittance(glass, c));
      expect(relErr(daylightIlluminanceAt(r, p, n).direct, expected), `at ${p}`).toBeLessThan(0.01);
    }
  });
});

describe('daylight reference: the sun', () => {
  const E_N = 80000;
  const s = sunDirection(30, 200) as Vec3;
  const glass = glazingFrom('double');
  const tau = glazingTransmittance(glass, s[2]); // cos θ_w = s·(outward +z)
  /** Where a window corner's ray lands on the floor. */
  const onFloor = (q: Vec3): [number, number] => [q[0] - (q[1] / s[1]) * s[0], q[2] - (q[1] / s[1]) * s[2]];

  it('lands as the window projected along the rays: E_sun·cos θ·τ(θ) inside, nothing outside, edges within 1 mm', () => {
    const r = solveDaylightReference(room(0), daylight(null, { sun: { direction: s, normalIlluminance: E_N }, groundReflectance: 0, glazing: { 0: glass } }), { patchSize: 1 });
    const w = r.daylight.windows[0];
    const sunAt = (x: number, z: number) => sunThroughWindow(r.daylight, w, [x, 0, z], UP);
    const [a, b, c] = [onFloor([WINDOW.x0, WINDOW.y0, 4]), onFloor([WINDOW.x1, WINDOW.y0, 4]), onFloor([WINDOW.x0, WINDOW.y1, 4])];
    // Points of the parallelogram a + λ(b − a) + μ(c − a), λ, μ ∈ [0, 1].
    const at = (l: number, m: number): [number, number] => [a[0] + l * (b[0] - a[0]) + m * (c[0] - a[0]), a[1] + l * (b[1] - a[1]) + m * (c[1] - a[1])];
    const expected = E_N * s[1] * tau;
    expect(relErr(sunAt(...at(0.5, 0.5)), expected)).toBeLessThan(1e-12);
    expect(relErr(sunAt(...at(0.05, 0.95)), expected)).toBeLessThan(1e-12);
    // Across each edge: 1 mm inside lit, 1 mm outside dark (the edges' lengths are 1.5 m and ~2.7 m).
    const eps = [0.001 / 1.5, 0.001 / Math.hypot(c[0] - a[0], c[1] - a[1])];
    for (const [l, m] of [
      [eps[0], 0.5],
      [1 - eps[0], 0.5],
      [0.5, eps[1]],
      [0.5, 1 - eps[1]],
    ])
      expect(sunAt(...at(l, m))).toBeCloseTo(expected, 6);
    for (const [l, m] of [
      [-eps[0], 0.5],
      [1 + eps[0], 0.5],
      [0.5, -eps[1]],
      [0.5, 1 + eps[1]],
    ])
      expect(sunAt(...at(l, m))).toBe(0);
    // The patch means add up to the beam through the window, exactly: E_n τ cos θ_w A.
    const entering = E_N * tau * s[2] * 1.5 * 1.4;
    expect(relErr(r.entering.sun, entering)).toBeLessThan(1e-12);
    let floor = 0;
    r.patches.forEach((p, i) => {
      if (p.kind === 'floor') floor += r.sunDirect[i] * p.area;
    });
    expect(relErr(floor, entering)).toBeLessThan(1e-9);
  });

  it('a low sun reaches the far wall: floor and wall share the beam exactly', () => {
    const low = sunDirection(20, 170) as Vec3;
    const r = solveDaylightReference(room(0), daylight(null, { sun: { direction: low, normalIlluminance: E_N }, groundReflectance: 0 }), { patchSize: 0.5 });
    const byKind = new Map<string, number>();
    r.patches.forEach((p, i) => byKind.set(p.kind, (byKind.get(p.kind) ?? 0) + r.sunDirect[i] * p.area));
    expect(byKind.get('floor')).toBeGreaterThan(0);
    expect(byKind.get('wall')).toBeGreaterThan(0);
    const total = [...byKind.values()].reduce((x, y) => x + y, 0);
    expect(relErr(total, E_N * low[2] * 1.5 * 1.4)).toBeLessThan(1e-9);
  });

  it('in an L, the room itself shadows the sun and hides part of the sky: none behind the inner corner', () => {
    // An L: the window in the south wall of the west wing; the east wing's floor behind the corner stays dark.
    const L: RoomInput = daylightL(uniform(0));
    // A sun from the south-south-west lights the west wing's floor through the window …
    const sun = sunDirection(20, 200) as Vec3;
    const r = solveDaylightReference(L, daylight(null, { sun: { direction: sun, normalIlluminance: E_N }, groundReflectance: 0 }), { patchSize: 0.5 });
    const w = r.daylight.windows[0];
    const q: Vec3 = [1.5, 1.4, 6]; // the window's middle
    const along = (dir: Vec3, t: number): Vec3 => [q[0] - t * dir[0], q[1] - t * dir[1], q[2] - t * dir[2]];
    const lit = along(sun, q[1] / sun[1]);
    expect(lit[0]).toBeLessThan(3); // on the floor of the west wing, in sight of the window
    expect(lit[2]).toBeLessThan(3);
    expect(relErr(sunThroughWindow(r.daylight, w, lit, UP), E_N * sun[1])).toBeLessThan(1e-12);
    // … a low sun from the south-west would reach a point of the east wing through the window's
    // middle, but the ray crosses the wall x = 3 (z 3 … 6) on its way: no sun there.
    const low = sunDirection(10, 230) as Vec3;
    const hidden = along(low, 5.5);
    expect(hidden[0]).toBeGreaterThan(3);
    expect(hidden[2]).toBeLessThan(3);
    expect(hidden[1]).toBeGreaterThan(0);
    const crossing = q[2] - ((3 - q[0]) / -low[0]) * low[2];
    expect(crossing).toBeGreaterThan(3);
    const lowSun = { ...r.daylight, sun: { direction: low, normalIlluminance: E_N } };
    expect(sunThroughWindow(lowSun, w, hidden, UP)).toBe(0);
    // Without the room in the way (a convex room's rule) the same point would be lit: the shadow is the wall's.
    expect(sunThroughWindow({ ...lowSun, sight: { ...lowSun.sight, convex: true } }, w, hidden, UP)).toBeGreaterThan(0);
    // The sky: a point of the east wing sees the window only left of the line through it and the
    // inner corner (3, 3): the independent integral over exactly that part, within 1 %.
    const overcast = cieOvercastSky(10000);
    const skyLit = { ...r.daylight, sky: overcast };
    for (const p of [
      [3.5, 0.8, 0.5],
      [4.2, 0.8, 0.4],
    ] as Vec3[]) {
      const cut = p[0] + ((3 - p[0]) * (6 - p[2])) / (3 - p[2]);
      expect(cut).toBeGreaterThan(0.5);
      expect(cut).toBeLessThan(2.5);
      const expected = areaIntegral(p, UP, overcast.luminance, 0, () => 1, { x0: 0.5, x1: cut, y0: 0.5, y1: 2.3, z: 6 });
      expect(relErr(skyThroughWindow(skyLit, w, p, UP), expected), `at ${p}`).toBeLessThan(0.01);
    }
    // Deep in the east wing the whole window is behind the wall.
    expect(skyThroughWindow(skyLit, w, [5.5, 0.8, 0.5], UP)).toBe(0);
    const entering = r.entering.sun;
    const landed = r.patches.reduce((sum, p, i) => sum + r.sunDirect[i] * p.area, 0);
    // Sampled on 16 × 16 pieces per patch in a non-convex room: within 1 % (measured +0.17 %).
    expect(relErr(landed, entering)).toBeLessThan(0.01);
  });
});

describe('daylight reference: flux balance', () => {
  it('black room: the direct light on all surfaces and openings is what enters (0.5 %; measured 5e-5)', () => {
    const sun = { direction: sunDirection(35, 190) as Vec3, normalIlluminance: 70000 };
    const r = solveDaylightReference(room(0), daylight(cieOvercastSky(12000), { sun, glazing: { 0: glazingFrom('double') } }), { patchSize: 0.5 });
    const f = roomFluxes(r);
    expect(relErr(f.direct + f.escapedDirect, r.entering.total)).toBeLessThan(5e-3);
  });

  it("reflecting room: entering − leaving = absorbed within 0.5 % (measured −0.17 %, the form factors' closure)", () => {
    const sun = { direction: sunDirection(25, 200) as Vec3, normalIlluminance: 60000 };
    const r = solveDaylightReference(room({ floor: 0.3, ceiling: 0.8, walls: 0.5 }), daylight(cieOvercastSky(10000), { sun }), { patchSize: 0.5 });
    const f = roomFluxes(r);
    expect(f.escaped).toBeGreaterThan(0);
    expect(relErr(r.entering.total - f.escaped, f.absorbed)).toBeLessThan(5e-3);
  });
});
