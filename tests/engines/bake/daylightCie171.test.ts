/**
 * CIE 171:2006-style daylight cases (issue 30: "CIE 171:2006 has daylight test cases for box
 * rooms; implement those you can reconstruct"). The report's §5.11 and §5.12 test the sky
 * component (SC, the direct sky light on a horizontal plane as a share of the unobstructed
 * horizontal sky illuminance) through an unglazed and a glazed façade opening under the CIE skies.
 * Their room sizes and tables are not in the literature this project has, so the cases are
 * rebuilt on the same principle with values that need no table: a 4 × 4 × 3 m black room (ground
 * ρ 0, so the SC is all that lights it) with a 2 × 1.5 m opening in its south wall at sill 1 m,
 * the SC on every floor texel against
 * - the uniform sky: the exact form factor of a rectangle perpendicular to the receiving plane
 *   (Lambert; Hopkinson, Petherbridge & Longmore, *Daylighting*, 1966, the BRS sky-component
 *   formula): SC = 100 % · Σ± G(W, H), G = [atan(W/D) − D/√(D²+H²) · atan(W/√(D²+H²))] / (2π),
 *   corners at the foot of the perpendicular;
 * - the CIE standard overcast sky, L = L_z (1 + 2 sin γ)/3, E_h = 7π L_z / 9: the uniform part
 *   above plus 2/3 L_z D ∫ [h³ / (3 a² (a² + h²)^{3/2})] du (a² = u² + D², the height integral in
 *   closed form), the last integral by 16 × 8-point Gauss–Legendre;
 * - every one of the 15 CIE general skies (ISO 15469 / CIE S 011, the sun at 40°, azimuth 200°, in
 *   front of the opening, its beam left out: the SC is the sky's), and double glazing with the
 *   clear-glass angular transmittance (§5.12's glazed opening), by a 2-D composite Gauss–Legendre
 *   integral over the opening (8 × 8 pieces of 8 × 8 points), independent of the baker's
 *   midpoint rule.
 * Bars: the issue's (uniform 1 %, overcast and the other skies 2 %) on every texel more than 0.2 m
 * from the opening's wall.
 */
import { describe, expect, it } from 'vitest';
import { glazingFrom, glazingTransmittance, OPEN_OPENING, type Glazing } from '../../../src/core/daylight/glazing';
import { CIE_GENERAL_SKY_TYPES, cieGeneralSky, cieOvercastSky, uniformSky, type Sky } from '../../../src/core/daylight/skies';
import { sunDirection } from '../../../src/core/daylight/solarPosition';
import type { Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import type { RoomInput } from '../../../src/core/room/roomInput';
import { luxOf } from '../../../src/engines/bake/bakedMaps';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { encloseShapedRoom } from '../../../src/engines/bake/shapedRoom/encloseShapedRoom';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { shapedBakeRoom } from './shapedRoomKit';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
const baker = createBaker(gl);
const E_H = 10_000;
// The opening: south wall z = 4, x from 1 to 3, y from 1 to 2.5 (wall 2 runs from (4, 4) to (0, 4): offset 1 from x = 4).
const OPENING = { x0: 1, x1: 3, y0: 1, y1: 2.5, z: 4 };
const ROOM: RoomInput = {
  outline: [
    [0, 0],
    [4, 0],
    [4, 4],
    [0, 4],
  ],
  height: 3,
  openings: [{ wall: 2, offset: 1, width: 2, sill: 1, height: 1.5, kind: 'window' }],
  reflectance: { floor: 0, ceiling: 0, walls: 0 },
};

// 8-point Gauss–Legendre on [−1, 1] (Abramowitz & Stegun, table 25.4).
const GL_X = [0.1834346424956498, 0.525532409916329, 0.7966664774136267, 0.9602898564975363];
const GL_W = [0.362683783378362, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763];
/** ∫_a^b f by `pieces` × 8-point Gauss–Legendre. */
function integrate(f: (x: number) => number, a: number, b: number, pieces: number): number {
  let sum = 0;
  const h = (b - a) / pieces;
  for (let k = 0; k < pieces; k++) {
    const mid = a + (k + 0.5) * h;
    for (let i = 0; i < 4; i++) sum += GL_W[i] * (f(mid - 0.5 * h * GL_X[i]) + f(mid + 0.5 * h * GL_X[i]));
  }
  return (sum * h) / 2;
}

/** Lambert's G for a rectangle from the foot of the perpendicular: width W (signed), height H above the plane, at distance D. */
const G = (W: number, H: number, D: number): number => (Math.atan(W / D) - (D / Math.hypot(D, H)) * Math.atan(W / Math.hypot(D, H))) / (2 * Math.PI);

/** The opening's extent seen from a floor point: u along the wall from the foot, h above the floor, D to the wall. */
const frame = (p: Vec3) => ({ u0: OPENING.x0 - p[0], u1: OPENING.x1 - p[0], h0: OPENING.y0 - p[1], h1: OPENING.y1 - p[1], D: OPENING.z - p[2] });

/** Exact SC (%) of the uniform sky. */
function uniformSc(p: Vec3): number {
  const { u0, u1, h0, h1, D } = frame(p);
  return 100 * (G(u1, h1, D) - G(u0, h1, D) - G(u1, h0, D) + G(u0, h0, D));
}

/** SC (%) of the CIE overcast sky: its uniform third plus the sin γ part, the height integral in closed form. */
function overcastSc(p: Vec3): number {
  const { u0, u1, h0, h1, D } = frame(p);
  const lz = (9 * E_H) / (7 * Math.PI);
  const heightIntegral = (u: number) => {
    const a2 = u * u + D * D;
    const at = (h: number) => (h * h * h) / (3 * a2 * (a2 + h * h) ** 1.5);
    return at(h1) - at(h0);
  };
  const uniformPart = (lz / 3) * Math.PI * (uniformSc(p) / 100);
  const sinPart = ((2 * lz) / 3) * D * integrate(heightIntegral, u0, u1, 16);
  return (100 * (uniformPart + sinPart)) / E_H;
}

/** SC (%) of any sky through the opening with its glazing: ∫∫ L(d) τ(cos θ_w) h D / r⁴ du dh, 2-D composite Gauss–Legendre. */
function numericSc(sky: Sky, glazing: Glazing, p: Vec3): number {
  const { u0, u1, h0, h1, D } = frame(p);
  const e = integrate(
    (u) =>
      integrate(
        (h) => {
          const r = Math.sqrt(u * u + h * h + D * D);
          // Toward the opening's point (x east, y up, z south): the opening is south of p.
          return sky.luminance([u / r, h / r, D / r]) * glazingTransmittance(glazing, D / r) * ((h * D) / r ** 4);
        },
        h0,
        h1,
        8,
      ),
    u0,
    u1,
    8,
  );
  return (100 * e) / sky.horizontalIlluminance;
}

/** SC (%) of every fully covered floor texel more than 0.2 m from the opening's wall (every `stride`-th), with its point in room coordinates. */
function bakedFloorSc(sky: Sky, glazing: Glazing, stride: number): { p: Vec3; sc: number }[] {
  const scene: BakeScene = { room: shapedBakeRoom(ROOM), luminaires: [], daylight: { sky, sun: null, groundLuminance: 0, glazing: new Map([[0, glazing]]) } };
  const { maps } = baker.bake(scene, { texelSize: 0.1, bounces: 0 });
  const o = maps.objects!;
  const e = luxOf(o.direct);
  const offset = encloseShapedRoom(scene).room.enclosure!.offset;
  const out: { p: Vec3; sc: number }[] = [];
  let n = 0;
  for (let k = 0; k < e.length; k++) {
    // The floor is the room's first surface (object 0); fully covered texels only.
    if (o.atlas.reflectance[4 * k + 3] !== 1 || !(o.atlas.position[4 * k + 3] >= 0.999)) continue;
    const p: Vec3 = [o.atlas.position[4 * k] - offset[0], o.atlas.position[4 * k + 1] - offset[1], o.atlas.position[4 * k + 2] - offset[2]];
    if (OPENING.z - p[2] < 0.2 || n++ % stride !== 0) continue;
    out.push({ p, sc: (100 * e[k]) / sky.horizontalIlluminance });
  }
  return out;
}

function worst(points: { p: Vec3; sc: number }[], expected: (p: Vec3) => number): { max: number; at: Vec3; n: number } {
  let max = 0;
  let at: Vec3 = [0, 0, 0];
  for (const { p, sc } of points) {
    const err = Math.abs(sc / expected(p) - 1);
    if (err > max) [max, at] = [err, p];
  }
  return { max, at, n: points.length };
}

describe('CIE 171:2006-style sky components (§5.11 unglazed, §5.12 glazed façade opening)', () => {
  it('uniform sky, unglazed: every floor texel within 1 % of the exact form factor', () => {
    const w = worst(bakedFloorSc(uniformSky(E_H), OPEN_OPENING, 1), uniformSc);
    console.info(`uniform sky: ${w.n} floor texels, worst ${(100 * w.max).toFixed(3)} % at [${w.at.map((v) => v.toFixed(2)).join(', ')}]; SC at the room's centre ${uniformSc([2, 0, 2]).toFixed(3)} %`);
    expect(w.n).toBeGreaterThan(1000);
    expect(w.max).toBeLessThan(0.01);
  });

  it('CIE overcast sky, unglazed: every floor texel within 2 % of the closed form', () => {
    // The closed form checked against the independent 2-D integral first (two routes to one number).
    for (const p of [
      [2, 0, 2],
      [0.5, 0, 3.5],
      [3.9, 0, 0.1],
    ] as Vec3[])
      expect(overcastSc(p) / numericSc(cieOvercastSky(E_H), OPEN_OPENING, p)).toBeCloseTo(1, 8);
    const w = worst(bakedFloorSc(cieOvercastSky(E_H), OPEN_OPENING, 1), overcastSc);
    console.info(`overcast sky: ${w.n} floor texels, worst ${(100 * w.max).toFixed(3)} %; SC at the room's centre ${overcastSc([2, 0, 2]).toFixed(3)} %`);
    expect(w.max).toBeLessThan(0.02);
  });

  it('the 15 CIE general skies (sun at 40°, azimuth 200°), unglazed and double-glazed: within 2 % of the 2-D integral', () => {
    const sun = sunDirection(40, 200);
    const lines: string[] = [];
    for (const { type } of CIE_GENERAL_SKY_TYPES) {
      const sky = cieGeneralSky(type, sun, E_H);
      for (const glazing of [OPEN_OPENING, glazingFrom('double')]) {
        const w = worst(bakedFloorSc(sky, glazing, 12), (p) => numericSc(sky, glazing, p));
        lines.push(`type ${type} ${glazing === OPEN_OPENING ? 'open' : 'double'}: ${(100 * w.max).toFixed(2)} %`);
        expect(w.n).toBeGreaterThan(80);
        expect(w.max, `sky type ${type}`).toBeLessThan(0.02);
      }
    }
    console.info(`general skies, worst texel: ${lines.join('; ')}`);
  }, 240_000);
});
