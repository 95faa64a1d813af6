/**
 * The relight engine keeps the daylight bases it has baked (issue 30; docs/daylight.md, "Daylight in
 * the relight engine"): a time of day already seen is re-weighted with no daylight basis rebaked
 * (counted by the engine's own `daylightBakes`), the kept bases stay within their byte budget (least
 * recently kept dropped first), and a room or objects change drops them all. Headless-gl, the
 * daylight box with a lamp, the sun from NOAA's position for Zurich on 21 June (summer time).
 */
import { describe, expect, it } from 'vitest';
import { cityNamed } from '../../../src/core/daylight/cities';
import { glazingFrom } from '../../../src/core/daylight/glazing';
import { CIE_CLEAR_SKY_TYPE, cieGeneralSky, cieOvercastSky, groundLuminance } from '../../../src/core/daylight/skies';
import { solarPosition, sunDirection } from '../../../src/core/daylight/solarPosition';
import { daylightAvailability } from '../../../src/core/daylight/daylightAvailability';
import { SURFACE_NAMES, type Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import type { BakeDaylight } from '../../../src/engines/bake/daylight/bakeDaylight';
import { basisBytes, DAYLIGHT_BASIS_CACHE_BYTES } from '../../../src/engines/relight/daylightBasisCache';
import { createRelightEngine, VIEWER_BAKE_SETTINGS } from '../../../src/engines/relight/createRelightEngine';
import type { RelightEngine } from '../../../src/engines/relight/RelightEngine';
import { LOW_MEMORY_RELIGHT_BYTES } from '../../../src/engines/view/createViewRelight';
import { spot } from '../bake/bakeTestKit';
import { shapedBakeRoom } from '../bake/shapedRoomKit';
import { withHeadlessGL } from '../bake/withHeadlessGL';
import { daylightBox } from '../../../src/hosts/bench/daylightBox';

const gl = withHeadlessGL();
const SETTINGS = { texelSize: 0.2, maxTextureSize: 64, samples: 16, bounces: 2, samplesPerDraw: 8, blurRadius: 1, seed: 30 };
const room = shapedBakeRoom(daylightBox());
const glazing = new Map([[0, glazingFrom('double')]]);
const lamp = spot(800, 30, 15, 2);

/** Where the sun stands in Zurich on 21 June at `hours` of the summer-time clock. */
function sunAt(hours: number) {
  const zurich = cityNamed('Zurich')!;
  return solarPosition({ latitude: zurich.latitude, longitude: zurich.longitude, timeZone: 2 }, { year: 2026, month: 6, day: 21, hours });
}

/** The clear sky (CIE type 12) with the sun at that time, the illuminances of the IES model (daylightAvailability.ts), as `luxbox` bakes a scene's sky. */
function clearAt(hours: number): BakeDaylight {
  const p = sunAt(hours);
  const s = sunDirection(p.elevation, p.azimuth) as Vec3;
  const m = daylightAvailability(p.elevation, p.dayOfYear, 'clear');
  return { sky: cieGeneralSky(CIE_CLEAR_SKY_TYPE, s, m.skyHorizontal), sun: { direction: s, normalIlluminance: m.sunNormal }, groundLuminance: groundLuminance(m.skyHorizontal, m.sunHorizontal, 0.2), glazing };
}

/** The overcast sky at that time (its illuminance from the IES model: it changes with the sun's elevation; no sun). */
function overcastAt(hours: number): BakeDaylight {
  const p = sunAt(hours);
  const m = daylightAvailability(p.elevation, p.dayOfYear, 'overcast');
  return { sky: cieOvercastSky(m.skyHorizontal), sun: null, groundLuminance: groundLuminance(m.skyHorizontal, 0, 0.2), glazing };
}

const sceneWith = (daylight: BakeDaylight, r = room): BakeScene => ({ room: r, luminaires: [{ photometry: lamp, position: [2.5, 2.6, 2], yaw: 0, pitch: 0, roll: 0, dimming: 1, color: [1, 1, 1] }], daylight });

/** The total maps (a copy: the engine writes into one buffer). */
const totals = (engine: RelightEngine): Float32Array[] => {
  const m = engine.maps().maps;
  return [...SURFACE_NAMES.map((n) => m[n].total.slice()), ...(m.objects ? [m.objects.total.slice()] : [])];
};

/** Move the engine to `daylight` and finish; the daylight bases baked for it. */
function moveTo(engine: RelightEngine, daylight: BakeDaylight, r = room): number {
  const before = engine.counters.daylightBakes;
  engine.setScene(sceneWith(daylight, r));
  engine.finish();
  return engine.counters.daylightBakes - before;
}

describe('the relight engine keeps the daylight bases it has baked', () => {
  it('a time slider 10:00 → 11:00 → 10:00 rebakes the daylight bases of each new time and none on the way back (clear sky: sky + sun; overcast: sky)', () => {
    for (const [name, at, perTime] of [
      ['clear', clearAt, 2],
      ['overcast', overcastAt, 1],
    ] as const) {
      const engine = createRelightEngine(gl, SETTINGS);
      try {
        const bakes = [moveTo(engine, at(10))];
        const ten = totals(engine);
        const solves = engine.counters.indirectSolves;
        bakes.push(moveTo(engine, at(11)));
        expect(engine.daylightCache.size).toBe(perTime);
        // Back to 10:00: the kept bases and the kept solve of those weights: exact at once, nothing to bake or solve.
        const back = engine.setScene(sceneWith(at(10)));
        expect(back).toEqual({ bake: 0, reused: 1 + perTime, daylightBake: 0 });
        expect(engine.progress.done).toBe(true);
        bakes.push(moveTo(engine, at(10)));
        console.log(`${name} sky, 10:00 → 11:00 → 10:00: daylight bases baked ${bakes.join(' + ')}; kept ${engine.daylightCache.size} (${(engine.daylightCache.bytes / 1024).toFixed(0)} KiB)`);
        expect(bakes).toEqual([perTime, perTime, 0]);
        expect(engine.counters.groupBakes).toBe(1);
        expect(engine.counters.indirectSolves).toBe(solves + 1);
        // The maps at 10:00 again are those of the first 10:00, value for value.
        const again = totals(engine);
        ten.forEach((m, k) => expect(again[k]).toEqual(m));
        // 11:00's bases are the kept ones now.
        expect(engine.daylightCache.size).toBe(perTime);
      } finally {
        engine.dispose();
      }
    }
  });

  it('keeps no more than its byte budget: the least recently kept bases go first and are baked again when their time returns', () => {
    // The bytes of one daylight basis of this room (sky and sun bases have the same maps).
    const probe = createRelightEngine(gl, SETTINGS);
    let basis: number;
    try {
      moveTo(probe, clearAt(10));
      const sizes = probe.relightParts()!.parts.map((p) => basisBytes(p.basis));
      basis = sizes[0];
      expect(new Set(sizes).size).toBe(1);
    } finally {
      probe.dispose();
    }
    // Room for one time of day (two bases) and not two.
    const engine = createRelightEngine(gl, SETTINGS, { daylightCacheBytes: Math.round(2.5 * basis) });
    try {
      expect(moveTo(engine, clearAt(10))).toBe(2);
      expect(moveTo(engine, clearAt(11))).toBe(2);
      expect(engine.daylightCache).toMatchObject({ size: 2, bytes: 2 * basis, evictions: 0 });
      // 10:00 is kept: taken back, 11:00 kept instead.
      expect(moveTo(engine, clearAt(10))).toBe(0);
      // 12:00: 10:00's bases join 11:00's, over the budget: 11:00's (kept first) go.
      expect(moveTo(engine, clearAt(12))).toBe(2);
      expect(engine.daylightCache).toMatchObject({ size: 2, bytes: 2 * basis, evictions: 2 });
      expect(moveTo(engine, clearAt(11))).toBe(2);
      expect(engine.daylightCache.bytes).toBeLessThanOrEqual(engine.daylightCache.budget);
    } finally {
      engine.dispose();
    }
    // A budget smaller than one basis keeps none.
    const none = createRelightEngine(gl, SETTINGS, { daylightCacheBytes: basis - 1 });
    try {
      moveTo(none, clearAt(10));
      moveTo(none, clearAt(11));
      expect(none.daylightCache).toMatchObject({ size: 0, bytes: 0 });
      expect(moveTo(none, clearAt(10))).toBe(2);
    } finally {
      none.dispose();
    }
  });

  it('a room change drops every kept basis: the times seen before are baked again in the new room', () => {
    const engine = createRelightEngine(gl, SETTINGS);
    try {
      moveTo(engine, clearAt(10));
      moveTo(engine, clearAt(11));
      expect(engine.daylightCache.size).toBe(2);
      // Other finishes: another room for the bases (their reflected flux, the bounces).
      const lighter = shapedBakeRoom(daylightBox({ floor: 0.5, ceiling: 0.8, walls: 0.7 }));
      expect(moveTo(engine, clearAt(11), lighter)).toBe(2);
      expect(engine.daylightCache).toMatchObject({ size: 0, bytes: 0 });
      expect(moveTo(engine, clearAt(10), lighter)).toBe(2);
      expect(engine.daylightCache.size).toBe(2);
    } finally {
      engine.dispose();
    }
  });

  it('the default budget is a quarter of the view’s 64 MiB low-memory texture budget, and holds many times of day of the daylight box at the viewer’s 5 cm texels', () => {
    expect(DAYLIGHT_BASIS_CACHE_BYTES).toBe(LOW_MEMORY_RELIGHT_BYTES / 4);
    const engine = createRelightEngine(gl, { ...VIEWER_BAKE_SETTINGS, samples: 8, bounces: 1 });
    try {
      engine.setScene({ room, luminaires: [], daylight: clearAt(10) });
      engine.finish();
      const bytes = engine.relightParts()!.parts.map((p) => basisBytes(p.basis));
      const perTime = bytes.reduce((a, b) => a + b, 0);
      console.log(`daylight box at 5 cm: ${bytes.map((b) => (b / 1024).toFixed(0)).join(' + ')} KiB a time of day; the default budget keeps ${Math.floor(DAYLIGHT_BASIS_CACHE_BYTES / perTime)} times`);
      expect(DAYLIGHT_BASIS_CACHE_BYTES / perTime).toBeGreaterThan(4);
    } finally {
      engine.dispose();
    }
  });
});
