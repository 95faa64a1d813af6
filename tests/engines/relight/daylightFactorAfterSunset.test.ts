/**
 * The daylight factor after sunset (issue 30; docs/daylight.md, "The shopper's daylight" and
 * "Daylight in the relight engine"): DF is defined under the CIE standard overcast sky (CIE S 011),
 * here of DAYLIGHT_FACTOR_SKY_ILLUMINANCE, whatever the time, so the 3D view's DF mode works at 17:00
 * on 21 December in Zurich (the sun down) and gives the same maps and work-plane numbers as at 10:00
 * on 21 June; with the scene's own light after sunset there is no daylight at all: Daylight shows
 * zero everywhere (no NaN), Both the electric light alone. The shopper's version-10 configuration
 * (tests/fixtures/formats/configuration-v10.luxbox.json: an L-shaped room with a slope, a
 * triple-glazed north window, ground ρ 0.25, its luminaires), headless-gl.
 */
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { glazingFrom } from '../../../src/core/daylight/glazing';
import { SURFACE_NAMES } from '../../../src/core/model/lightingScene/lightingScene';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { prepareObjectsCached } from '../../../src/engines/bake/objects/prepareObjectsCached';
import { encloseShapedRoom } from '../../../src/engines/bake/shapedRoom/encloseShapedRoom';
import { createRelightEngine } from '../../../src/engines/relight/createRelightEngine';
import type { LightSources } from '../../../src/engines/relight/daylightGroups';
import type { RelightEngine } from '../../../src/engines/relight/RelightEngine';
import { loadRenderInputAsync } from '../../../src/hosts/node/renderInput';
import { daylightFactorOfView } from '../../../src/ui/viewer/useDaylightFactorView';
import { withHeadlessGL } from '../bake/withHeadlessGL';

const gl = withHeadlessGL();
const SETTINGS = { texelSize: 0.2, maxTextureSize: 64, samples: 16, bounces: 2, samplesPerDraw: 8, blurRadius: 1, seed: 30 };
const FIXTURE = join(__dirname, '../../fixtures/formats/configuration-v10.luxbox.json');
const TMP = mkdtempSync(join(tmpdir(), 'luxbox-df-night-'));

/** The fixture's bake scene with its daylight at another date and time (the configuration's own settings, as the Daylight panel sets them). */
async function sceneAt(date: string, time: string): Promise<BakeScene> {
  const file = JSON.parse(readFileSync(FIXTURE, 'utf8')) as { configuration: { daylight: Record<string, unknown> } };
  file.configuration.daylight = { ...file.configuration.daylight, date, time };
  const path = join(TMP, `${date}-${time.replace(':', '')}.luxbox.json`);
  writeFileSync(path, JSON.stringify(file));
  return (await loadRenderInputAsync(path)).bakeScene;
}

/** Every map the engine shows (walls and the atlas), totals and directs. */
function allMaps(engine: RelightEngine): Float32Array[] {
  const m = engine.maps().maps;
  return [...SURFACE_NAMES.flatMap((n) => [m[n].direct, m[n].total]), ...(m.objects ? [m.objects.direct, m.objects.total] : [])].map((a) => a.slice());
}

function show(engine: RelightEngine, scene: BakeScene, sources: LightSources): Float32Array[] {
  engine.setLightSources(sources);
  engine.setScene(scene);
  engine.finish();
  return allMaps(engine);
}

describe('the daylight factor at any time of day', () => {
  it('after sunset the scene carries its windows in the dark: their glazing and the ground, no sky, no sun', async () => {
    const night = await sceneAt('2026-12-21', '17:00');
    expect(night.daylight).toEqual({ sky: null, sun: null, groundLuminance: 0, glazing: new Map([[1, glazingFrom('triple')]]), groundReflectance: 0.25 });
    const day = await sceneAt('2026-06-21', '10:00');
    expect(day.daylight!.sun).not.toBeNull();
    expect(day.daylight!.groundReflectance).toBe(0.25);
  });

  it('Daylight and Both after sunset: no daylight basis, Daylight all zero, Both the electric light alone; the DF mode: one overcast basis, the same maps as at 10:00 in June', async () => {
    const [night, day] = [await sceneAt('2026-12-21', '17:00'), await sceneAt('2026-06-21', '10:00')];
    const engine = createRelightEngine(gl, SETTINGS);
    try {
      const electric = show(engine, night, 'electric');
      // Daylight alone after sunset: nothing at all, and nothing NaN.
      for (const m of show(engine, night, 'daylight')) for (const v of m) expect(v).toBe(0);
      // Both: the electric light alone, value for value.
      const both = show(engine, night, 'both');
      both.forEach((m, k) => expect(m).toEqual(electric[k]));
      let lit = 0;
      for (const m of electric) for (const v of m) lit = Math.max(lit, v);
      expect(lit).toBeGreaterThan(0);
      expect(engine.counters.daylightBakes).toBe(0);
      const nightDf = show(engine, night, 'daylight-factor');
      expect(engine.counters.daylightBakes).toBe(1);
      let peak = 0;
      for (const m of nightDf) for (const v of m) peak = Math.max(peak, Number.isFinite(v) ? v : Infinity);
      expect(Number.isFinite(peak)).toBe(true);
      // The overcast sky of 10 klx through a 1.2 × 1.2 m triple-glazed window: some hundreds of lux near it.
      expect(peak).toBeGreaterThan(50);
      // Another engine at 10:00 in June, the DF mode: the same overcast basis (the same key: windows, glazing, ground ρ), the same maps.
      const other = createRelightEngine(gl, SETTINGS);
      try {
        const dayDf = show(other, day, 'daylight-factor');
        // The day's own sky and sun bases are baked too (they are the scene's, shown at weight 0), and the overcast one.
        expect(other.counters.daylightBakes).toBe(3);
        let worst = 0;
        dayDf.forEach((m, k) => m.forEach((v, i) => (worst = Math.max(worst, Math.abs(v - nightDf[k][i])))));
        console.log(`DF maps at 17:00 in December vs 10:00 in June: peak ${peak.toFixed(1)} lx (DF ${(peak / 100).toFixed(2)} %), |Δ| ${worst.toExponential(2)}`);
        expect(worst).toBeLessThanOrEqual(1e-6 * peak);
      } finally {
        other.dispose();
      }
      // From the night to the day in the DF mode: the overcast basis stays; only the day's sky and sun are new.
      show(engine, day, 'daylight-factor');
      expect(engine.counters.daylightBakes).toBe(3);
    } finally {
      engine.dispose();
    }
  });

  it("the view's work-plane DF after sunset equals the one at 10:00 in June", async () => {
    const values = [];
    for (const [date, time] of [
      ['2026-12-21', '17:00'],
      ['2026-06-21', '10:00'],
    ]) {
      const scene = await sceneAt(date, time);
      const engine = createRelightEngine(gl, SETTINGS);
      try {
        show(engine, scene, 'daylight-factor');
        const prepared = prepareObjectsCached(encloseShapedRoom(scene).objects ?? [], { texelSize: engine.settings.texelSize, maxAtlasSize: engine.settings.maxTextureSize });
        values.push(daylightFactorOfView(scene, engine.maps(), prepared));
      } finally {
        engine.dispose();
      }
    }
    const [night, day] = values;
    console.log(`work-plane DF after sunset: mean ${night?.mean.toFixed(3)} %, min ${night?.min.toFixed(3)} % over ${night?.points} points; at 10:00 in June mean ${day?.mean.toFixed(3)} %`);
    expect(night).not.toBeNull();
    expect(night!.points).toBeGreaterThan(10);
    expect(night!.mean).toBeGreaterThan(0);
    expect(night!.mean).toBeCloseTo(day!.mean, 9);
    expect(night!.min).toBeCloseTo(day!.min, 9);
    expect(night!.shareAbove2).toBe(day!.shareAbove2);
  });
});
