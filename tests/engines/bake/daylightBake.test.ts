/**
 * Daylight in the baker (issue 30): the sky, the ground and the sun through the windows of a
 * shaped room (src/engines/bake/daylight), then the existing indirect passes, against the
 * independent daylight reference (src/reference/solveDaylightReference.ts: exact view factors per
 * cell, the sun patch by polygon clipping, radiosity on 0.25 m patches; it shares no code with
 * the baker's daylight). Compared at fully covered atlas texels, 5 cm edge bands left out.
 */
import { describe, expect, it } from 'vitest';
import { glazingFrom, glazingTransmittance, type Glazing } from '../../../src/core/daylight/glazing';
import { cieOvercastSky, groundLuminance, uniformSky, type Sky } from '../../../src/core/daylight/skies';
import { sunDirection } from '../../../src/core/daylight/solarPosition';
import type { Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import type { RoomInput } from '../../../src/core/room/roomInput';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { luxOf } from '../../../src/engines/bake/bakedMaps';
import { createBaker } from '../../../src/engines/bake/createBaker';
import type { BakeDaylight } from '../../../src/engines/bake/daylight/bakeDaylight';
import { encloseShapedRoom } from '../../../src/engines/bake/shapedRoom/encloseShapedRoom';
import { compareDaylightWithReference } from '../../../src/hosts/bench/daylightComparison';
import { relativeErrors } from '../../../src/hosts/bench/shapedRoomComparison';
import { roomFluxes } from '../../../src/reference/solveRoomReference';
import { solveDaylightReference, type DaylightReferenceResult } from '../../../src/reference/solveDaylightReference';
import { shapedBakeRoom } from './shapedRoomKit';
import { withHeadlessGL } from './withHeadlessGL';
import { daylightBox, daylightL } from '../../../src/hosts/bench/daylightBox';

const gl = withHeadlessGL();
const baker = createBaker(gl);
const SETTINGS = { texelSize: 0.1 };
const pct = (x: number) => `${(100 * x).toFixed(2)} %`;

// The reference tests' room: 5 × 4 m, 2.8 m high, a 1.5 × 1.4 m window in the south wall (wall 2) at sill 0.9 m.
const box = (reflectance: RoomInput['reflectance'], transmittance = true): { input: RoomInput; glazing: Map<number, Glazing> } => ({
  input: daylightBox(reflectance),
  glazing: new Map(transmittance ? [[0, glazingFrom('double')]] : []),
});
// An L whose west wing's south wall (wall 4) has a 2 × 1.8 m window; the inner corner hides part of it from the east wing.
const lRoom = (reflectance: RoomInput['reflectance']): { input: RoomInput; glazing: Map<number, Glazing> } => ({
  input: daylightL(reflectance),
  glazing: new Map([[0, glazingFrom('double')]]),
});
const FINISHES = { floor: 0.3, ceiling: 0.8, walls: 0.5 };
const BLACK = { floor: 0, ceiling: 0, walls: 0 };

interface Case {
  input: RoomInput;
  glazing: Map<number, Glazing>;
  sky: Sky | null;
  sun?: { direction: Vec3; normalIlluminance: number };
  groundReflectance?: number;
}

function bakeDaylight(c: Case, settings: Record<string, number> = {}) {
  const sunH = c.sun ? c.sun.normalIlluminance * Math.max(c.sun.direction[1], 0) : 0;
  const daylight: BakeDaylight = { sky: c.sky, sun: c.sun ?? null, groundLuminance: groundLuminance(c.sky?.horizontalIlluminance ?? 0, sunH, c.groundReflectance ?? 0.2), glazing: c.glazing };
  const scene: BakeScene = { room: shapedBakeRoom(c.input), luminaires: [], daylight };
  const t0 = performance.now();
  const { maps, report } = baker.bake(scene, { ...SETTINGS, ...settings });
  return { scene, maps, report, ms: performance.now() - t0 };
}

function reference(c: Case, patchSize = 0.25): DaylightReferenceResult {
  return solveDaylightReference(c.input, { sky: c.sky, sun: c.sun ?? null, groundReflectance: c.groundReflectance ?? 0.2, glazing: Object.fromEntries(c.glazing) }, { patchSize });
}

/** Σ E·A (Y) of a bake's atlas map over the room's surfaces, and Σ (1 − ρ)·E·A (what they absorb). */
function atlasFluxes(maps: ReturnType<typeof bakeDaylight>['maps'], which: 'direct' | 'total'): { flux: number; absorbed: number } {
  const o = maps.objects!;
  const e = luxOf(o[which]);
  const { position, reflectance, texelSize } = o.atlas;
  let flux = 0;
  let absorbed = 0;
  for (let k = 0; k < e.length; k++) {
    const a = position[4 * k + 3] * texelSize * texelSize;
    if (!(a > 0)) continue;
    flux += e[k] * a;
    // Daylight is white; these finishes are grey, so (1 − ρ) E is the same on every channel.
    absorbed += (1 - reflectance[4 * k]) * e[k] * a;
  }
  return { flux, absorbed };
}

function compare(name: string, c: Case, stride: number) {
  const bake = bakeDaylight(c);
  const ref = reference(c);
  const cmp = compareDaylightWithReference(bake.scene, bake.maps, ref, stride);
  const peak = Math.max(...cmp.points.map((p) => p.reference.total));
  const direct = relativeErrors(cmp.points, 'direct', 0.01 * peak);
  const total = relativeErrors(cmp.points, 'total', 0.01 * peak);
  console.info(
    `${name}: bake ${bake.ms.toFixed(0)} ms (daylight direct ${bake.report.daylight?.directMs.toFixed(0)} ms); ${cmp.points.length} points, ${cmp.nearEdge} near an edge; direct RMS ${pct(direct.rms)} max ${pct(direct.max)}; total RMS ${pct(total.rms)} max ${pct(total.max)}`,
  );
  return { bake, ref, cmp, direct, total };
}

describe('daylight in the baker vs the daylight reference', () => {
  it('a uniform sky through an open window into a black box: direct = the exact view-factor sum', () => {
    const c: Case = { ...box(BLACK, false), sky: uniformSky(10_000), groundReflectance: 0 };
    const { direct, cmp } = compare('box, uniform, black', c, 10);
    expect(cmp.points.length).toBeGreaterThan(400);
    expect(direct.rms).toBeLessThan(0.005);
    expect(direct.max).toBeLessThan(0.02);
  });

  it('the box under a CIE overcast sky, double glazing, reflecting finishes: total (daylight factor map) within 3 % RMS', () => {
    const c: Case = { ...box(FINISHES), sky: cieOvercastSky(10_000) };
    const { direct, total, bake } = compare('box, overcast, reflecting', c, 40);
    expect(direct.rms).toBeLessThan(0.01);
    expect(total.rms).toBeLessThan(0.03);
    const maps = bake.maps.objects!;
    for (const m of [maps.direct, maps.indirect, maps.total]) expect(m.every(Number.isFinite)).toBe(true);
  });

  it('the box under a uniform sky, reflecting finishes: total within 3 % RMS', () => {
    const c: Case = { ...box(FINISHES), sky: uniformSky(10_000) };
    expect(compare('box, uniform, reflecting', c, 40).total.rms).toBeLessThan(0.03);
  });

  it('the L under a CIE overcast sky: the inner corner hides part of the window; total within 3 % RMS', () => {
    const c: Case = { ...lRoom(FINISHES), sky: cieOvercastSky(10_000) };
    const { direct, total } = compare('L, overcast, reflecting', c, 40);
    expect(direct.rms).toBeLessThan(0.01);
    expect(total.rms).toBeLessThan(0.03);
  });

  it('the L under a uniform sky: total within 3 % RMS', () => {
    const c: Case = { ...lRoom(FINISHES), sky: uniformSky(10_000) };
    expect(compare('L, uniform, reflecting', c, 40).total.rms).toBeLessThan(0.03);
  });

  it('the sun patch through the window: E_n τ(θ) sin α inside, 0 outside, edges where geometry puts them; its flux = the beam', () => {
    const E_N = 80_000;
    const s = sunDirection(35, 200) as Vec3;
    const c: Case = { ...box(BLACK), sky: null, sun: { direction: s, normalIlluminance: E_N }, groundReflectance: 0 };
    const { maps, report, scene } = bakeDaylight(c, { bounces: 0 });
    const o = maps.objects!;
    const e = luxOf(o.direct);
    const { position, reflectance, texelSize } = o.atlas;
    const offset = encloseShapedRoom(scene).room.enclosure!.offset;
    const cosW = s[2];
    const expected = E_N * glazingTransmittance(glazingFrom('double'), cosW) * s[1];
    // The floor is the room's first surface (object 0). Independent geometry: the ray from p toward the sun crosses z = 4 inside the window.
    let lit = 0;
    let wrong = 0;
    let patchFlux = 0;
    for (let k = 0; k < e.length; k++) {
      if (reflectance[4 * k + 3] !== 1 || !(position[4 * k + 3] > 0)) continue;
      const p = [position[4 * k] - offset[0], position[4 * k + 1] - offset[1], position[4 * k + 2] - offset[2]];
      const t = (4 - p[2]) / s[2];
      const [x, y] = [p[0] + t * s[0], p[1] + t * s[1]];
      const inside = x > 1.75 && x < 3.25 && y > 0.9 && y < 2.3;
      // Distance of the texel from the patch's edge, measured on the window: within one texel the centre may fall either side.
      const margin = Math.min(Math.abs(x - 1.75), Math.abs(x - 3.25), Math.abs(y - 0.9), Math.abs(y - 2.3));
      if (e[k] > 0) lit++;
      // Beyond a texel from the edge: exactly lit or dark; nearer, a texel mean between 0 and the beam.
      if (margin > texelSize) {
        if (inside ? Math.abs(e[k] / expected - 1) > 1e-4 : e[k] !== 0) wrong++;
      } else expect(e[k]).toBeLessThanOrEqual(expected * (1 + 1e-4));
      patchFlux += e[k] * position[4 * k + 3] * texelSize * texelSize;
    }
    const beam = E_N * glazingTransmittance(glazingFrom('double'), cosW) * cosW * 1.5 * 1.4;
    console.info(
      `sun patch: ${lit} floor texels lit, ${wrong} wrong beyond a texel from the edge; floor flux ${patchFlux.toFixed(0)} lm vs beam ${beam.toFixed(0)} lm (${pct(patchFlux / beam - 1)}); report sun flux ${report.daylight?.sunFlux.toFixed(0)}`,
    );
    expect(lit).toBeGreaterThan(100);
    expect(wrong).toBe(0);
    expect(Math.abs(patchFlux / beam - 1)).toBeLessThan(0.005);
  });

  it('flux balance: in a black room the direct daylight on the surfaces = the light entering; with reflecting surfaces the bake absorbs what the reference does', () => {
    const sun = { direction: sunDirection(35, 200) as Vec3, normalIlluminance: 60_000 };
    const black: Case = { ...box(BLACK), sky: cieOvercastSky(10_000), sun };
    const b = bakeDaylight(black);
    const entering = reference(black, 0.5).entering.total;
    const direct = atlasFluxes(b.maps, 'direct').flux;
    const reflecting: Case = { ...box(FINISHES), sky: cieOvercastSky(10_000), sun };
    const r = bakeDaylight(reflecting);
    const ref = reference(reflecting);
    const bakeAbsorbed = atlasFluxes(r.maps, 'total').absorbed;
    const refFluxes = roomFluxes(ref);
    console.info(
      `flux: entering ${entering.toFixed(0)} lm, black-room direct ${direct.toFixed(0)} lm (${pct(direct / entering - 1)}); reflecting: absorbed bake ${bakeAbsorbed.toFixed(0)} vs reference ${refFluxes.absorbed.toFixed(0)} lm (${pct(bakeAbsorbed / refFluxes.absorbed - 1)}), reference leaving ${refFluxes.escaped.toFixed(0)} lm`,
    );
    expect(Math.abs(direct / entering - 1)).toBeLessThan(0.005);
    expect(Math.abs(bakeAbsorbed / refFluxes.absorbed - 1)).toBeLessThan(0.01);
    for (const m of [r.maps.objects!.direct, r.maps.objects!.total]) expect(m.every((v) => Number.isFinite(v) && v >= 0)).toBe(true);
  });

  it('is deterministic: the same scene bakes to the same maps', () => {
    const c: Case = { ...lRoom(FINISHES), sky: cieOvercastSky(10_000), sun: { direction: sunDirection(30, 190) as Vec3, normalIlluminance: 50_000 } };
    const a = bakeDaylight(c, { samples: 16, bounces: 2 }).maps.objects!.total;
    const b = bakeDaylight(c, { samples: 16, bounces: 2 }).maps.objects!.total;
    expect(Buffer.from(a.buffer).equals(Buffer.from(b.buffer))).toBe(true);
  });

  it('a room with windows but no daylight bakes as before: no daylight report, the same maps', () => {
    const c = box(FINISHES);
    const room = shapedBakeRoom(c.input);
    const plain = baker.bake({ room, luminaires: [] }, { ...SETTINGS, samples: 8, bounces: 1 });
    expect(plain.report.daylight).toBeUndefined();
    const dark = baker.bake({ room, luminaires: [], daylight: { sky: null, sun: null, groundLuminance: 0, glazing: c.glazing } }, { ...SETTINGS, samples: 8, bounces: 1 });
    expect(dark.report.daylight).toBeUndefined();
  });
});
