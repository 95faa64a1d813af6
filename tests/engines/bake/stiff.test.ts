/**
 * Stiff scenes (issue #8): light concentrated in a small, very bright region
 * near a surface — a narrow spot 15 cm from a wall, up-lights a few cm under
 * a ceiling. Default bake settings against the independent CPU reference
 * (src/reference: exact patch-integrated direct light, exact form factors,
 * converged radiosity, final gather), read as `luxbox probe` reads them:
 * direct light exactly at the point, indirect from the maps. Also: texel
 * means of direct light against the exact solid angle, and the near-field
 * option.
 */
import { describe, expect, it } from 'vitest';
import type { LightingScene } from '../../../src/core/model/lightingScene/lightingScene';
import type { Photometry } from '../../../src/core/photometry/types';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { probeScene } from '../../../src/engines/bake/probeMaps';
import { luxOf } from '../../../src/engines/bake/bakedMaps';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { solveBoxReference } from '../../../src/reference/solveBoxReference';
import { sampleReference } from '../../../src/reference/sampleReference';
import { samplePoints } from '../../../src/hosts/bench/runBench';
import { relativeErrors } from '../../../src/hosts/bench/errorStats';
import { allFiniteNonNegative, averageLux, isotropic, loadIes, totalFlux, uniformRoom } from './bakeTestKit';
import { integrateFlux } from '../../../src/core/photometry/flux';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
const baker = createBaker(gl);

function bakeSceneOf(scene: LightingScene, files: Record<string, Photometry>): BakeScene {
  return {
    room: scene.room,
    luminaires: scene.luminaires.map((l) => ({ ...l, photometry: files[l.photometry] })),
    ...(scene.nearField ? { nearField: scene.nearField } : {}),
  };
}

/** Default settings against the reference at comparison points every 0.2 m on all six surfaces. */
function compareWithReference(scene: LightingScene, files: Record<string, Photometry>, patchSize: number) {
  const bakeScene = bakeSceneOf(scene, files);
  const { maps, report } = baker.bake(bakeScene);
  const reference = solveBoxReference(scene, files, { patchSize, openingCell: scene.nearField === 'point' ? 0 : 0.05 });
  const points = samplePoints(scene.room, 0.2);
  const ref = points.map(({ surface, point }) => sampleReference(reference, point, surface));
  const probe = probeScene(
    bakeScene,
    maps,
    {},
    points.map((p) => p.point),
  );
  const total = relativeErrors(
    probe.map((p) => p.total),
    ref.map((r) => r.total),
  );
  const direct = relativeErrors(
    probe.map((p) => p.direct),
    ref.map((r) => r.direct),
    1e-9,
  );
  const meanBake = probe.reduce((s, p) => s + p.total, 0) / probe.length;
  const meanRef = ref.reduce((s, r) => s + r.total, 0) / ref.length;
  return { maps, report, total, direct, meanBake, meanRef };
}

const smallRoom = (reflectance: LightingScene['room']['reflectance']): LightingScene['room'] => ({ width: 2.5, height: 2.4, depth: 2, reflectance });

describe('stiff scenes: default settings against the exact reference', () => {
  it('narrow spot 15 cm from a wall, aimed at it: ≤ 3 % RMS, no point worse than 20 %', () => {
    const scene: LightingScene = {
      version: 1,
      room: smallRoom({ floor: 0.3, ceiling: 0.85, north: 0.8, south: 0.6, west: 0.5, east: 0.7 }),
      luminaires: [{ photometry: 'spot', position: [1.2, 1.3, 0.15], yaw: 0, pitch: 90, roll: 0 }],
    };
    const r = compareWithReference(scene, { spot: loadIes('bega_84693_narrow_spot.ies') }, 0.125);
    console.info(`spot 15 cm from a wall: total RMS ${(100 * r.total.rms).toFixed(2)} %, max ${(100 * r.total.max).toFixed(1)} %, bright patches ${JSON.stringify(r.report.brightPatches)}`);
    expect(allFiniteNonNegative(r.maps)).toBe(true);
    // Direct light at the points is exact (same point sources, float64 on both sides).
    expect(r.direct.max).toBeLessThan(1e-6);
    expect(r.total.rms).toBeLessThan(0.03);
    expect(r.total.max).toBeLessThan(0.2);
    expect(Math.abs(r.meanBake / r.meanRef - 1)).toBeLessThan(0.01);
    expect(r.report.brightPatches?.count ?? 0).toBeGreaterThan(0);
  });

  it('two up-lights 3 and 8 cm under a ρ = 0.95 ceiling: ≤ 3 % RMS, no point worse than 20 %', () => {
    const scene: LightingScene = {
      version: 1,
      room: smallRoom({ floor: 0.3, ceiling: 0.95, north: 0.8, south: 0.8, west: 0.7, east: 0.7 }),
      luminaires: [
        { photometry: 'up', position: [0.8, 2.37, 1], yaw: 0, pitch: 0, roll: 0 },
        { photometry: 'up', position: [1.8, 2.32, 1.1], yaw: 90, pitch: 0, roll: 0 },
      ],
    };
    const r = compareWithReference(scene, { up: loadIes('erco_trion_ceiling_washlight_uplight.ies') }, 0.125);
    console.info(`up-lights under the ceiling: total RMS ${(100 * r.total.rms).toFixed(2)} %, max ${(100 * r.total.max).toFixed(1)} %, bright patches ${JSON.stringify(r.report.brightPatches)}`);
    expect(allFiniteNonNegative(r.maps)).toBe(true);
    expect(r.direct.max).toBeLessThan(1e-6);
    expect(r.total.rms).toBeLessThan(0.03);
    expect(r.total.max).toBeLessThan(0.2);
    expect(Math.abs(r.meanBake / r.meanRef - 1)).toBeLessThan(0.01);
  });
});

/** Solid angle of the rectangle [0,a]×[0,b] seen from height h above its corner (Ω = atan(ab / (h·√(a²+b²+h²)))). */
const cornerSolidAngle = (a: number, b: number, h: number) => Math.sign(a * b) * Math.atan(Math.abs(a * b) / (h * Math.hypot(a, b, h)));

/** Solid angle of [u0,u1]×[v0,v1] from height h above the origin, by inclusion–exclusion of corner rectangles. */
const rectSolidAngle = (u0: number, u1: number, v0: number, v1: number, h: number) => cornerSolidAngle(u1, v1, h) - cornerSolidAngle(u0, v1, h) - cornerSolidAngle(u1, v0, h) + cornerSolidAngle(u0, v0, h);

describe('texel means of direct light', () => {
  it('isotropic source 5 cm from a wall: each texel holds I·Ω/A (the exact mean), not the centre value', () => {
    const I = 1000;
    const h = 0.05;
    const { maps } = baker.bake({ room: uniformRoom(2, 2, 2, 0), luminaires: [{ photometry: isotropic(I), position: [1.03, 1.01, h], yaw: 0, pitch: 0, roll: 0 }] }, { texelSize: 0.1, bounces: 0 });
    const north = maps.north;
    const lux = luxOf(north.direct);
    let worst = 0;
    for (let j = 0; j < north.layout.height; j++) {
      for (let i = 0; i < north.layout.width; i++) {
        // Texel (i, j) covers x ∈ [0.1 i, 0.1 (i+1)], y ∈ [0.1 j, 0.1 (j+1)]; the foot of the source is at (1.03, 1.01).
        const mean = (I * rectSolidAngle(0.1 * i - 1.03, 0.1 * (i + 1) - 1.03, 0.1 * j - 1.01, 0.1 * (j + 1) - 1.01, h)) / 0.01;
        worst = Math.max(worst, Math.abs(lux[j * north.layout.width + i] - mean) / mean);
      }
    }
    console.info(`texel means 5 cm from the source: worst ${(100 * worst).toFixed(3)} %`);
    expect(worst).toBeLessThan(0.01);
    // Σ E·A on the near wall: the solid angle of the whole wall, I·Ω.
    const flux = lux.reduce((s, e) => s + e * 0.01, 0);
    expect(flux / (I * rectSolidAngle(-1.03, 0.97, -1.01, 0.99, h))).toBeCloseTo(1, 2);
  });
});

describe('near field', () => {
  const pendant = loadIes('ledalite_pendant_direct_indirect_iesna95.ies');
  const scene = (nearField?: 'split' | 'point'): LightingScene => ({
    version: nearField ? 2 : 1,
    ...(nearField ? { nearField } : {}),
    room: uniformRoom(3, 2.6, 3, 0.5),
    luminaires: [{ photometry: 'p', position: [1.5, 2.3, 1.5], yaw: 30, pitch: 0, roll: 0 }],
  });

  it("'point' makes one source per luminaire, 'split' (default) a grid; the bake setting overrides the scene", () => {
    const split = baker.bake(bakeSceneOf(scene(), { p: pendant }), { bounces: 0, texelSize: 0.2 }).report;
    const point = baker.bake(bakeSceneOf(scene('point'), { p: pendant }), { bounces: 0, texelSize: 0.2 }).report;
    const overridden = baker.bake(bakeSceneOf(scene('point'), { p: pendant }), { bounces: 0, texelSize: 0.2, nearField: 'split' }).report;
    expect(point.pointSources).toBe(1);
    expect(split.pointSources).toBeGreaterThan(1);
    expect(overridden.pointSources).toBe(split.pointSources);
  });

  it('a tall opening (13 cm cylinder) emits down from its bottom face and up from its top face: flux kept, same as the reference', () => {
    const tall = loadIes('cooper_shaper_ceiling_one_value_per_line.ies');
    const s: LightingScene = { version: 1, room: uniformRoom(3, 2.6, 3, 0), luminaires: [{ photometry: 't', position: [1.5, 2.45, 1.5], yaw: 0, pitch: 0, roll: 0 }] };
    const bakeScene = bakeSceneOf(s, { t: tall });
    const { maps, report } = baker.bake(bakeScene, { texelSize: 0.05, bounces: 0 });
    // 3 cells across the 10.06 cm width (≤ 5 cm each; length 0 → one row), once per face.
    expect(report.pointSources).toBe(6);
    expect(Math.abs(totalFlux(maps, 'direct') / integrateFlux(tall) - 1)).toBeLessThan(0.01);
    const reference = solveBoxReference(s, { t: tall }, { patchSize: 0.5 });
    const points = samplePoints(s.room, 0.3);
    const ref = points.map(({ surface, point }) => sampleReference(reference, point, surface));
    const probe = probeScene(
      bakeScene,
      maps,
      { texelSize: 0.05 },
      points.map((p) => p.point),
    );
    expect(
      relativeErrors(
        probe.map((p) => p.direct),
        ref.map((r) => r.direct),
        1e-9,
      ).max,
    ).toBeLessThan(1e-6);
    // The top face sits 6.7 cm above the centre: the ceiling right above gets I(180°)/(0.15 − 0.067)².
    const above = probeScene(bakeScene, maps, {}, [[1.5, 2.6, 1.5]])[0].direct;
    expect(above / (tall.candela[0][tall.candela[0].length - 1] / (2.6 - 2.45 - 0.067) ** 2)).toBeCloseTo(1, 1);
  });

  it('a tall luminaire 5 cm under the ceiling (top face would be above it): the top face stays 1 cm inside, no flux lost', () => {
    const tall = loadIes('cooper_shaper_ceiling_one_value_per_line.ies');
    const s: LightingScene = { version: 1, room: uniformRoom(3, 2.6, 3, 0), luminaires: [{ photometry: 't', position: [1.5, 2.55, 1.5], yaw: 0, pitch: 0, roll: 0 }] };
    const bakeScene = bakeSceneOf(s, { t: tall });
    const { maps } = baker.bake(bakeScene, { texelSize: 0.05, bounces: 0 });
    expect(Math.abs(totalFlux(maps, 'direct') / integrateFlux(tall) - 1)).toBeLessThan(0.02);
    // Right above: a third of I(180°) from the middle cell 1 cm away (the two outer cells sit 3.4 cm aside):
    // the hot spot of a source 1 cm under the ceiling, not 5 cm (which would give 1/25 of it).
    const above = probeScene(bakeScene, maps, {}, [[1.5, 2.6, 1.5]])[0].direct;
    expect(above / (tall.candela[0][tall.candela[0].length - 1] / 3 / 0.01 ** 2)).toBeGreaterThan(1);
    expect(above / (tall.candela[0][tall.candela[0].length - 1] / 3 / 0.01 ** 2)).toBeLessThan(1.1);
    const reference = solveBoxReference(s, { t: tall }, { patchSize: 0.5 });
    const points = samplePoints(s.room, 0.3);
    const probe = probeScene(
      bakeScene,
      maps,
      {},
      points.map((p) => p.point),
    );
    const ref = points.map(({ surface, point }) => sampleReference(reference, point, surface));
    expect(
      relativeErrors(
        probe.map((p) => p.direct),
        ref.map((r) => r.direct),
        1e-9,
      ).max,
    ).toBeLessThan(1e-6);
  });

  it("'point' equals the reference's unsplit model at every probe point (direct exact, total within 3 % RMS)", () => {
    const s = scene('point');
    const bakeScene = bakeSceneOf(s, { p: pendant });
    const { maps } = baker.bake(bakeScene, { texelSize: 0.05 });
    const reference = solveBoxReference(s, { p: pendant }, { patchSize: 0.25, openingCell: 0 });
    const points = samplePoints(s.room, 0.3);
    const ref = points.map(({ surface, point }) => sampleReference(reference, point, surface));
    const probe = probeScene(
      bakeScene,
      maps,
      { texelSize: 0.05 },
      points.map((p) => p.point),
    );
    expect(
      relativeErrors(
        probe.map((p) => p.direct),
        ref.map((r) => r.direct),
        1e-9,
      ).max,
    ).toBeLessThan(1e-6);
    expect(
      relativeErrors(
        probe.map((p) => p.total),
        ref.map((r) => r.total),
      ).rms,
    ).toBeLessThan(0.03);
    expect(averageLux(maps, 'total')).toBeGreaterThan(0);
  });
});
