/**
 * Daylight as bases of the relight engine (issue 30; docs/daylight.md, "Daylight in the relight
 * engine"): the sky and the sun through the window are two groups of their own, their sum with the
 * shared solve is the baker's full daylight bake; a new time of day rebakes only them, a change of
 * the luminaires only the luminaires; the light sources shown are weights.
 */
import { afterAll, describe, expect, it } from 'vitest';
import { glazingFrom } from '../../../src/core/daylight/glazing';
import { DAYLIGHT_FACTOR_SKY_ILLUMINANCE } from '../../../src/core/daylight/daylightFactor';
import { cieGeneralSky, cieOvercastSky, CIE_CLEAR_SKY_TYPE, groundLuminance } from '../../../src/core/daylight/skies';
import { sunDirection } from '../../../src/core/daylight/solarPosition';
import { SURFACE_NAMES, type Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { createBaker } from '../../../src/engines/bake/createBaker';
import type { BakeDaylight } from '../../../src/engines/bake/daylight/bakeDaylight';
import { createGpuRelight } from '../../../src/engines/relight/createGpuRelight';
import { createRelightEngine } from '../../../src/engines/relight/createRelightEngine';
import type { LitMaps } from '../../../src/engines/relight/relightMaps';
import { spot } from '../bake/bakeTestKit';
import { shapedBakeRoom } from '../bake/shapedRoomKit';
import { withHeadlessGL } from '../bake/withHeadlessGL';
import { compareWithBake } from './relightTestKit';
import { daylightBox } from '../../../src/hosts/bench/daylightBox';

const gl = withHeadlessGL();
const SETTINGS = { texelSize: 0.2, maxTextureSize: 64, samples: 16, bounces: 2, samplesPerDraw: 8, blurRadius: 1, seed: 30 };
const baker = createBaker(gl);
afterAll(() => baker.dispose());

// The daylight tests' box: 5 × 4 m, 2.8 m high, a 1.5 × 1.4 m double-glazed window in the south wall at sill 0.9 m.
const room = shapedBakeRoom(daylightBox());
const glazing = new Map([[0, glazingFrom('double')]]);
const lamp = spot(800, 30, 15, 2);

/** A clear sky (CIE type 12) with the sun at `elevation`, azimuth `azimuth` (south-west: it shines in). */
function daylightAt(elevation: number, azimuth: number): BakeDaylight {
  const s = sunDirection(elevation, azimuth) as Vec3;
  const skyH = 12_000;
  const sunN = 60_000;
  return { sky: cieGeneralSky(CIE_CLEAR_SKY_TYPE, s, skyH), sun: { direction: s, normalIlluminance: sunN }, groundLuminance: groundLuminance(skyH, sunN * s[1], 0.2), glazing };
}

const sceneWith = (daylight: BakeDaylight | undefined, lampX = 2.5, dimming = 1): BakeScene => ({
  room,
  luminaires: [{ photometry: lamp, position: [lampX, 2.6, 2], yaw: 0, pitch: 0, roll: 0, dimming, color: [1, 1, 1] }],
  ...(daylight ? { daylight } : {}),
});

/** Peak of |a − b| over every receiver's direct or total map, and the peak of b's. */
function difference(a: LitMaps, b: LitMaps, kind: 'direct' | 'total'): { worst: number; peak: number } {
  let worst = 0;
  let peak = 0;
  const pairs = SURFACE_NAMES.map((n) => [a.maps[n][kind], b.maps[n][kind]] as const);
  if (a.maps.objects && b.maps.objects) pairs.push([a.maps.objects[kind], b.maps.objects[kind]]);
  for (const [x, y] of pairs) {
    for (let i = 0; i < y.length; i++) {
      worst = Math.max(worst, Math.abs(x[i] - y[i]));
      peak = Math.max(peak, Math.abs(y[i]));
    }
  }
  return { worst, peak };
}

/** A copy of the maps (the engine writes into one buffer). */
function copyOf(m: LitMaps): LitMaps {
  const maps = Object.fromEntries(SURFACE_NAMES.map((n) => [n, { direct: m.maps[n].direct.slice(), total: m.maps[n].total.slice() }])) as LitMaps['maps'];
  if (m.maps.objects) maps.objects = { atlas: m.maps.objects.atlas, direct: m.maps.objects.direct.slice(), total: m.maps.objects.total.slice() };
  return { layouts: m.layouts, maps };
}

describe('daylight as relight bases', () => {
  const noon = daylightAt(40, 200);
  const afternoon = daylightAt(25, 240);

  it('the sky and sun bases with the shared solve are the full daylight bake (within 1e-4 of its peak); no luminaire group', () => {
    const engine = createRelightEngine(gl, SETTINGS);
    try {
      const scene: BakeScene = { room, luminaires: [], daylight: noon };
      const result = engine.setScene(scene);
      expect(result).toEqual({ bake: 2, reused: 0, daylightBake: 2 });
      engine.finish();
      expect(engine.counters).toMatchObject({ groupBakes: 0, daylightBakes: 2, indirectSolves: 1 });
      const reference = baker.bake(scene, SETTINGS).maps;
      const { peak, direct, total, objectTexels } = compareWithBake(engine.maps(), reference);
      console.log(`daylight bases vs full bake: peak ${peak.toFixed(1)} lx, |Δ direct| ${direct.toExponential(2)}, |Δ total| ${total.toExponential(2)} lx over ${objectTexels} atlas texels`);
      expect(objectTexels).toBeGreaterThan(100);
      expect(peak).toBeGreaterThan(1000);
      expect(direct).toBeLessThanOrEqual(1e-4 * peak);
      expect(total).toBeLessThanOrEqual(1e-4 * peak);
    } finally {
      engine.dispose();
    }
  });

  it('a new time of day rebakes the two daylight bases and no luminaire group; a change of the luminaires rebakes no daylight basis', () => {
    const engine = createRelightEngine(gl, SETTINGS);
    try {
      expect(engine.setScene(sceneWith(noon))).toEqual({ bake: 3, reused: 0, daylightBake: 2 });
      engine.finish();
      expect(engine.counters).toMatchObject({ groupBakes: 1, daylightBakes: 2 });
      // Another time: the sky (its sun) and the sun's beam change; the lamp stays.
      expect(engine.setScene(sceneWith(afternoon))).toEqual({ bake: 2, reused: 1, daylightBake: 2 });
      engine.finish();
      expect(engine.counters).toMatchObject({ groupBakes: 1, daylightBakes: 4 });
      // The lamp dimmed: a relight only; then moved: one luminaire basis, no daylight.
      expect(engine.setScene(sceneWith(afternoon, 2.5, 0.5))).toEqual({ bake: 0, reused: 3, daylightBake: 0 });
      expect(engine.setScene(sceneWith(afternoon, 1.5, 0.5))).toEqual({ bake: 1, reused: 2, daylightBake: 0 });
      engine.finish();
      expect(engine.counters).toMatchObject({ groupBakes: 2, daylightBakes: 4 });
      // The same scene without daylight: the daylight groups are gone, nothing is baked.
      expect(engine.setScene(sceneWith(undefined, 1.5, 0.5))).toEqual({ bake: 0, reused: 1 });
      // Daylight back: its bases were kept when it left (daylightBasisCache.ts) and come back unbaked, as the lamp's stayed.
      expect(engine.setScene(sceneWith(afternoon, 1.5, 0.5))).toEqual({ bake: 0, reused: 3, daylightBake: 0 });
      engine.finish();
      expect(engine.counters).toMatchObject({ groupBakes: 2, daylightBakes: 4 });
      // The afternoon's maps equal a full bake of the lamp and the afternoon's daylight together.
      const { peak, total } = compareWithBake(engine.maps(), baker.bake(sceneWith(afternoon, 1.5, 0.5), SETTINGS).maps);
      console.log(`afternoon, lamp moved and dimmed: |Δ total| ${total.toExponential(2)} of peak ${peak.toFixed(1)} lx`);
      // The lamp's direct light is baked with its lamps as uniforms and summed per basis: float rounding of a different order.
      expect(total).toBeLessThanOrEqual(1e-4 * peak);
    } finally {
      engine.dispose();
    }
  });

  it('the light sources shown are weights: electric + daylight = both, no basis rebaked, each choice re-solved once', () => {
    const engine = createRelightEngine(gl, SETTINGS);
    try {
      engine.setScene(sceneWith(noon));
      engine.finish();
      const both = copyOf(engine.maps());
      const counts = { ...engine.counters };
      expect(engine.lightSources).toBe('both');
      engine.setLightSources('electric');
      engine.finish();
      const electric = copyOf(engine.maps());
      engine.setLightSources('daylight');
      engine.finish();
      const daylight = copyOf(engine.maps());
      expect(engine.counters).toMatchObject({ groupBakes: counts.groupBakes, daylightBakes: counts.daylightBakes, indirectSolves: counts.indirectSolves + 2 });
      // Back to both: the solve is cached, nothing is solved again.
      engine.setLightSources('both');
      expect(engine.progress.done).toBe(true);
      expect(difference(copyOf(engine.maps()), both, 'total').worst).toBe(0);
      const sum = copyOf(electric);
      for (const n of SURFACE_NAMES) for (const kind of ['direct', 'total'] as const) sum.maps[n][kind].forEach((v, i) => (sum.maps[n][kind][i] = v + daylight.maps[n][kind][i]));
      if (sum.maps.objects && daylight.maps.objects) for (const kind of ['direct', 'total'] as const) sum.maps.objects[kind].forEach((v, i) => (sum.maps.objects![kind][i] = v + daylight.maps.objects![kind][i]));
      const d = difference(sum, both, 'direct');
      const t = difference(sum, both, 'total');
      console.log(`electric + daylight vs both: |Δ direct| ${d.worst.toExponential(2)}, |Δ total| ${t.worst.toExponential(2)} of peak ${t.peak.toFixed(1)} lx`);
      expect(d.worst).toBeLessThanOrEqual(1e-5 * d.peak);
      // Each solve is its own Monte Carlo gather of another direct sum (the same seed): linear up to the blur's and the tail's float order.
      expect(t.worst).toBeLessThanOrEqual(1e-4 * t.peak);
      // Electric alone has no daylight: the window wall's far side stays as the lamp lights it, and daylight alone is brighter than the lamp near the window.
      expect(difference(electric, both, 'direct').worst).toBeGreaterThan(100);
      expect(() => engine.setLightSources('moon' as never)).toThrow(/setLightSources: 'moon' is not one of electric, daylight, both/);
    } finally {
      engine.dispose();
    }
  });

  it("the GPU relight combines the daylight bases like any basis: its maps are the engine's (1e-5 of the peak) at each choice of sources", () => {
    const engine = createRelightEngine(gl, SETTINGS);
    const gpu = createGpuRelight(gl);
    try {
      engine.setScene(sceneWith(noon));
      engine.finish();
      for (const sources of ['daylight', 'both', 'electric'] as const) {
        engine.setLightSources(sources);
        engine.finish();
        const { parts, terms, layouts, atlas } = engine.relightParts()!;
        expect(parts.filter((p) => p.weight.some((w) => w > 0))).toHaveLength(sources === 'both' ? 3 : sources === 'daylight' ? 2 : 1);
        const shown = gpu.relight(parts, terms, layouts, atlas);
        const cpu = engine.maps();
        const read = copyOf(cpu);
        for (const n of SURFACE_NAMES) for (const kind of ['direct', 'total'] as const) read.maps[n][kind] = gpu.read(shown[n][kind]);
        for (const kind of ['direct', 'total'] as const) read.maps.objects![kind] = gpu.read(shown.objects![kind]);
        for (const kind of ['direct', 'total'] as const) {
          const { worst, peak } = difference(read, cpu, kind);
          expect(peak).toBeGreaterThan(100);
          expect(worst).toBeLessThanOrEqual(1e-5 * peak);
        }
      }
    } finally {
      gpu.dispose();
      engine.dispose();
    }
  });

  it("the daylight factor's sources: one overcast basis baked on demand (no other), its maps the full bake under the CIE overcast sky of 10 klx", () => {
    const engine = createRelightEngine(gl, SETTINGS);
    try {
      engine.setScene(sceneWith(noon));
      engine.finish();
      const before = { ...engine.counters };
      engine.setLightSources('daylight-factor');
      engine.finish();
      expect(engine.counters).toMatchObject({ groupBakes: before.groupBakes, daylightBakes: before.daylightBakes + 1 });
      expect(engine.relightParts()!.parts.filter((p) => p.weight.some((w) => w > 0))).toHaveLength(1);
      // The same windows and ground (ρ_g 0.2) under the overcast sky, no lamp, no sun: the report's daylight-factor bake.
      const overcast: BakeDaylight = { sky: cieOvercastSky(DAYLIGHT_FACTOR_SKY_ILLUMINANCE), sun: null, groundLuminance: groundLuminance(DAYLIGHT_FACTOR_SKY_ILLUMINANCE, 0, 0.2), glazing };
      const { peak, direct, total } = compareWithBake(engine.maps(), baker.bake({ room, luminaires: [], daylight: overcast }, SETTINGS).maps);
      console.log(`daylight factor basis vs the overcast bake: |Δ direct| ${direct.toExponential(2)}, |Δ total| ${total.toExponential(2)} of peak ${peak.toFixed(1)} lx (DF ${(peak / 100).toFixed(1)} %)`);
      expect(peak).toBeGreaterThan(100);
      expect(total).toBeLessThanOrEqual(1e-4 * peak);
      // Back to the scene's light: the overcast basis leaves (kept), nothing is baked, the cached solve shows at once.
      engine.setLightSources('both');
      expect(engine.progress.done).toBe(true);
      expect(engine.counters).toMatchObject({ groupBakes: before.groupBakes, daylightBakes: before.daylightBakes + 1 });
      expect(engine.daylightCache.size).toBe(1);
      // The mode again: its kept basis and its cached solve, nothing baked or solved.
      const solves = engine.counters.indirectSolves;
      engine.setLightSources('daylight-factor');
      expect(engine.progress.done).toBe(true);
      engine.finish();
      expect(engine.counters).toMatchObject({ daylightBakes: before.daylightBakes + 1, indirectSolves: solves });
    } finally {
      engine.dispose();
    }
  });
});
