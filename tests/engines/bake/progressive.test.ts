/**
 * Progressive refinement and basis baking: stepping a few samples at a time
 * gives the same maps as one run (same sample indices, deterministic seed);
 * maps of luminaire groups add up to the maps of the whole scene.
 */
import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES } from '../../../src/core/model/lightingScene/lightingScene';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { combineMaps, luxOf } from '../../../src/engines/bake/bakedMaps';
import { averageLux, loadIes, uniformRoom } from './bakeTestKit';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
const baker = createBaker(gl);
const down = loadIes('bega_50975_downlight_lm1995_crlf.ies');
const wash = loadIes('erco_kubus_floor_washlight.ies');
const room = { ...uniformRoom(3, 2.5, 3, 0.6), reflectance: { ...uniformRoom(3, 2.5, 3, 0.6).reflectance, east: [0.7, 0.4, 0.2] as [number, number, number] } };
const a = { photometry: down, position: [1, 2.45, 1] as [number, number, number], yaw: 0, pitch: 0, roll: 0 };
const b = { photometry: wash, position: [2.5, 0.5, 2.5] as [number, number, number], yaw: 200, pitch: 50, roll: 0, color: [1, 0.9, 0.7] as [number, number, number] };
const settings = { texelSize: 0.1, samples: 32, bounces: 3, samplesPerDraw: 8 };

describe('progressive bake', () => {
  it('step(5) repeatedly reaches the same maps as run(), and refines monotonically in bounces', () => {
    const whole = baker.bake({ room, luminaires: [a, b] }, settings).maps;
    const job = baker.start({ room, luminaires: [a, b] }, settings);
    const seen: number[] = [];
    let guard = 0;
    while (!job.progress.done && guard++ < 100) {
      const p = job.step(5);
      job.finalize();
      seen.push(p.bounce);
      // Preview maps are usable at every frame.
      expect(luxOf(job.readMaps().floor.total).every((x) => Number.isFinite(x) && x >= 0)).toBe(true);
    }
    expect(job.progress).toMatchObject({ bounce: 3, done: true });
    expect(seen).toEqual([...seen].sort((x, y) => x - y));
    job.finalize();
    const stepped = job.readMaps();
    job.dispose();
    for (const name of SURFACE_NAMES) {
      const x = stepped[name].total;
      const y = whole[name].total;
      for (let i = 0; i < x.length; i++) expect(Math.abs(x[i] - y[i])).toBeLessThanOrEqual(1e-4 * Math.abs(y[i]) + 1e-6);
    }
  });

  it('reports timings, texel counts, samples, bounces and shader sizes', () => {
    const { report } = baker.bake({ room, luminaires: [a, b] }, settings);
    expect(report.totalTexels).toBe(2 * (30 * 25 + 30 * 30 + 30 * 25));
    expect(report.samplesPerTexelPerBounce).toBe(32);
    expect(report.bouncesComputed).toBe(3);
    expect(report.bounceFlux).toHaveLength(4);
    expect(report.shaders.filter((s) => s.pass === 'gather')).toHaveLength(6);
    for (const s of report.shaders) expect(s.bytes).toBeGreaterThan(100);
    for (const t of Object.values(report.timings_ms)) expect(t).toBeGreaterThanOrEqual(0);
  });
});

describe('basis maps per luminaire group (light is linear)', () => {
  it('direct maps of two groups sum exactly to the whole; totals within 2 % on average', () => {
    const whole = baker.bake({ room, luminaires: [a, b] }, settings).maps;
    const onlyA = baker.bake({ room, luminaires: [a] }, settings).maps;
    const onlyB = baker.bake({ room, luminaires: [b] }, settings).maps;
    const sum = combineMaps([
      { maps: onlyA, weight: 1 },
      { maps: onlyB, weight: 1 },
    ]);
    for (const name of SURFACE_NAMES) {
      const x = sum[name].direct;
      const y = whole[name].direct;
      for (let i = 0; i < x.length; i++) expect(Math.abs(x[i] - y[i])).toBeLessThanOrEqual(1e-5 * Math.abs(y[i]) + 1e-6);
    }
    const total = averageLux(whole, 'total');
    expect(Math.abs(averageLux(sum, 'total') - total) / total).toBeLessThan(0.02);
  });

  it('a group weight (dimming, colour) scales that group only', () => {
    const onlyA = baker.bake({ room, luminaires: [a] }, settings).maps;
    const dimmed = baker.bake({ room, luminaires: [{ ...a, dimming: 0.25 }] }, settings).maps;
    const weighted = combineMaps([{ maps: onlyA, weight: 0.25 }]);
    for (const name of SURFACE_NAMES) {
      const x = weighted[name].total;
      const y = dimmed[name].total;
      for (let i = 0; i < x.length; i++) expect(Math.abs(x[i] - y[i])).toBeLessThanOrEqual(1e-4 * Math.abs(y[i]) + 1e-6);
    }
  });
});
