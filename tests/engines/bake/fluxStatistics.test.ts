/**
 * Flux statistics on the GPU (issue 17): the per-bounce flux and
 * flux-weighted reflectance that the ρ → 1 tail needs are reduced on the GPU
 * and never read back between bounces. Checked against the same formula
 * computed on the CPU from maps read back independently, and the read-back
 * count the report states against what the job really did.
 */
import { describe, expect, it } from 'vitest';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { createFloatTarget, requireFloatTargets, uploadRgb } from '../../../src/engines/bake/floatTarget';
import { createFluxStatistics } from '../../../src/engines/bake/fluxStatistics';
import { createDataTexture } from '../../../src/engines/bake/createDataTexture';
import { openRoomRecord, type SurfaceFlux } from '../../../src/engines/bake/fluxRecord';
import { createTargetPool } from '../../../src/engines/bake/targetPool';
import { LUMINANCE_WEIGHTS } from '../../../src/engines/bake/bakedMaps';
import { surfaceLayouts, texelArea } from '../../../src/engines/bake/surfaceLayout';
import { SURFACE_NAMES, type Rgb } from '../../../src/core/model/lightingScene/lightingScene';
import { isotropic, spot } from './bakeTestKit';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
requireFloatTargets(gl);

/** Seeded LCG in [0, 1). */
function random(seed: number): () => number {
  let s = seed >>> 0;
  return () => (s = (Math.imul(s, 1664525) + 1013904223) >>> 0) / 2 ** 32;
}

describe('GPU flux reduction', () => {
  it('matches the CPU sum on odd-sized maps with a hot spot over 7 decades (float64 reference, 1e-5 relative)', () => {
    // Sizes that are not powers of 4, down to 1×1 and 1×n, so partial blocks are exercised.
    const room = { width: 3.3, height: 0.05, depth: 1.7 };
    const layouts = surfaceLayouts(room, 0.05, 512);
    const rho: Rgb[] = [
      [0.2, 0.3, 0.4],
      [0.8, 0.8, 0.8],
      [0.5, 0.1, 0.9],
      [0.95, 0.95, 0.95],
      [0, 0, 0],
      [0.6, 0.5, 0.4],
    ];
    const next = random(7);
    const data = layouts.map((l, s) => {
      const a = new Float32Array(l.width * l.height * 3);
      for (let i = 0; i < a.length; i++) a[i] = next() * 10;
      if (s === 2) a[3 * Math.floor((l.width * l.height) / 2)] = 3e7; // a spot on one texel, red channel
      return a;
    });
    const targets = layouts.map((l, s) => {
      const t = createFloatTarget(gl, l.width, l.height, false);
      uploadRgb(gl, t, data[s]);
      return t;
    });
    let reads = 0;
    const stats = createFluxStatistics(gl, createTargetPool(gl, false), layouts, rho, 3, () => reads++);
    stats.record(0, targets, 1);
    stats.record(2, targets, 0.25);
    expect(reads).toBe(0);
    const [r0, , r2] = stats.read(3);
    expect(reads).toBe(1);

    const flux = [0, 0, 0];
    const reflected = [0, 0, 0];
    layouts.forEach((l, s) => {
      const a = texelArea(l);
      for (let i = 0; i < data[s].length; i++) {
        flux[i % 3] += data[s][i] * a;
        reflected[i % 3] += data[s][i] * a * rho[s][i % 3];
      }
    });
    const fluxY = flux.reduce((sum, f, c) => sum + f * LUMINANCE_WEIGHTS[c], 0);
    expect(Math.abs(r0.fluxY - fluxY) / fluxY).toBeLessThan(1e-5);
    expect(Math.abs(r2.fluxY - fluxY / 4) / fluxY).toBeLessThan(1e-5);
    for (let c = 0; c < 3; c++) {
      const ratio = Math.min(reflected[c] / flux[c], 0.95);
      expect(Math.abs(r0.ratio[c] - ratio)).toBeLessThan(1e-5);
      expect(Math.abs(r2.ratio[c] - ratio)).toBeLessThan(1e-5);
    }
    stats.dispose();
  });
});

describe('GPU flux reduction in a room with openings (issue 30)', () => {
  it('leaves the six sinks out and writes R_k / R_{k−1} of the atlas for k ≥ 1, the reflectance for k = 0: as openRoomRecord in float64, 1e-5', () => {
    const layouts = surfaceLayouts({ width: 0.3, height: 0.2, depth: 0.1 }, 0.1, 512);
    const [width, height, texel] = [37, 23, 0.1];
    const next = random(11);
    const coverage = Array.from({ length: width * height }, () => (next() < 0.1 ? 0 : next() < 0.3 ? next() : 1));
    const rho = Array.from({ length: width * height }, () => [next() * 0.95, next() * 0.95, next() * 0.95]);
    const points = new Float32Array(4 * width * height);
    const reflectance = new Float32Array(4 * width * height);
    coverage.forEach((c, k) => {
      points[4 * k + 3] = c;
      reflectance.set([...rho[k], 1], 4 * k);
    });
    const objects = { width, height, texelSize: texel, points: createDataTexture(gl, points, width, height, 4), reflectance: createDataTexture(gl, reflectance, width, height, 4), maxReflectance: 0.95 };
    const stats = createFluxStatistics(
      gl,
      createTargetPool(gl, false),
      layouts,
      layouts.map((): Rgb => [0, 0, 0]),
      3,
      () => undefined,
      objects,
      true,
    );
    // Three records of different maps; the sinks' maps are bright and must not count.
    const records = [1, 0.125, 0.125].map((scale, index) => {
      const atlas = new Float32Array(3 * width * height).map(() => next() * 10 * (1 - 0.3 * index));
      const sinks = layouts.map((l) => new Float32Array(3 * l.width * l.height).fill(1e4));
      const maps = [...sinks, atlas].map((data, s) => {
        const t = s < layouts.length ? createFloatTarget(gl, layouts[s].width, layouts[s].height, false) : createFloatTarget(gl, width, height, false);
        uploadRgb(gl, t, data);
        return t;
      });
      stats.record(index, maps, scale);
      return coverage.map((c, k): SurfaceFlux => ({ sum: [atlas[3 * k] * c, atlas[3 * k + 1] * c, atlas[3 * k + 2] * c], texelArea: texel * texel * scale, reflectance: rho[k] as Rgb }));
    });
    const gpu = stats.read(3);
    records.forEach((surfaces, k) => {
      const cpu = openRoomRecord(surfaces, k > 0 ? records[k - 1] : null, 0.95);
      expect(Math.abs(gpu[k].fluxY / cpu.fluxY - 1)).toBeLessThan(1e-5);
      for (let c = 0; c < 3; c++) expect(Math.abs(gpu[k].ratio[c] - cpu.ratio[c])).toBeLessThan(1e-5);
    });
    // The series ratio is not the reflectance: the third record's maps are dimmer (0.4 of the first's, 0.7 of the second's at equal scale).
    expect(Math.abs(gpu[2].ratio[1] - 4 / 7)).toBeLessThan(0.05);
    stats.dispose();
  });
});

describe('read-backs of a bake', () => {
  const scene = {
    room: { width: 3, height: 2.5, depth: 4, reflectance: Object.fromEntries(SURFACE_NAMES.map((s) => [s, 0.6])) as Record<(typeof SURFACE_NAMES)[number], number> },
    luminaires: [{ photometry: spot(20000, 8, 4, 1), position: [1.5, 2.4, 2] as [number, number, number], yaw: 0, pitch: 30, roll: 0 }],
  };
  // brightPatches 0: the bright-patch pass (runBrightPatchPass.ts) adds the report's read-back of its
  // summary (or, chosen on the CPU, one of its tile sums before the first bounce); counted separately below.
  const settings = { texelSize: 0.1, samples: 16, bounces: 4, brightPatches: 0 };

  it('none between bounces: a run makes 0 read-backs; the report 1 (stats row); maps 18 (6 surfaces × direct/indirect/total)', () => {
    const job = createBaker(gl).start(scene, settings);
    job.run();
    const layouts = surfaceLayouts(scene.room, settings.texelSize, 512);
    const mapBytes = layouts.reduce((n, l) => n + l.width * l.height * 16, 0) * 3;
    const first = job.report();
    expect(first.readbacks).toEqual({ count: 1, bytes: (settings.bounces + 1) * 16 });
    job.readMaps();
    const second = job.report();
    expect(second.readbacks).toEqual({ count: 1 + 18, bytes: (settings.bounces + 1) * 16 + mapBytes });
    expect(second.bounceFlux).toHaveLength(settings.bounces + 1);
    job.dispose();
  });

  it('the report of a bake states the read-backs it made: bake() = maps + one stats row', () => {
    const { report } = createBaker(gl).bake({ room: scene.room, luminaires: [{ ...scene.luminaires[0], photometry: isotropic(100) }] }, settings);
    expect(report.readbacks.count).toBe(19);
  });

  it("bright patches chosen on the GPU (brightSelection 'gpu', the default on a hardware renderer) add no read-back to the bake; the report reads their summary (one texel) besides its stats row", () => {
    const job = createBaker(gl).start(scene, { ...settings, brightPatches: 64, brightSelection: 'gpu' });
    job.run();
    const report = job.report();
    expect(report.brightPatches?.count ?? 0).toBeGreaterThan(0);
    expect(report.readbacks).toEqual({ count: 1 + 1, bytes: (settings.bounces + 1) * 16 + 16 });
    job.dispose();
  });

  it("chosen on the CPU (brightSelection 'cpu'), the pass adds exactly one read-back (its tile sums, before the first bounce), still none between bounces", () => {
    const job = createBaker(gl).start(scene, { ...settings, brightPatches: 64, brightSelection: 'cpu' });
    job.run();
    // Tile sums + the report's stats row.
    expect(job.report().readbacks.count).toBe(1 + 1);
    job.dispose();
  });
});

describe('render targets kept between bakes', () => {
  it('a second bake of the same room reuses every target and gives the same maps bit for bit; a new room frees the old sizes', () => {
    const room = { width: 2, height: 2.5, depth: 3, reflectance: Object.fromEntries(SURFACE_NAMES.map((s) => [s, 0.7])) as Record<(typeof SURFACE_NAMES)[number], number> };
    const scene = { room, luminaires: [{ photometry: spot(5000, 10, 5, 1), position: [1, 2.45, 0.2] as [number, number, number], yaw: 0, pitch: 60, roll: 0 }] };
    const settings = { texelSize: 0.1, samples: 8, bounces: 2 };
    const baker = createBaker(gl);
    const first = baker.bake(scene, settings).maps;
    const second = baker.bake(scene, settings).maps;
    for (const n of SURFACE_NAMES) {
      for (const kind of ['direct', 'indirect', 'total'] as const) expect(Buffer.from(second[n][kind].buffer).equals(Buffer.from(first[n][kind].buffer))).toBe(true);
    }
    // A different room after a bake with targets still dirty from the first: no light carried over.
    const other = baker.bake({ room: { ...room, width: 2.2 }, luminaires: [] }, settings).maps;
    for (const n of SURFACE_NAMES) expect(other[n].total.every((v) => v === 0)).toBe(true);
    baker.dispose();
  });

  it('the pool hands back a released target cleared, and drops sizes not used by the last job', () => {
    const pool = createTargetPool(gl, false);
    pool.nextJob();
    const a = pool.acquire(4, 3);
    uploadRgb(gl, a, new Float32Array(36).fill(7));
    pool.release(a);
    expect(pool.free).toBe(1);
    pool.nextJob();
    const b = pool.acquire(4, 3);
    expect(b).toBe(a);
    const rgba = new Float32Array(48);
    gl.bindFramebuffer(gl.FRAMEBUFFER, b.framebuffer);
    gl.readPixels(0, 0, 4, 3, gl.RGBA, gl.FLOAT, rgba);
    expect(rgba.every((v) => v === 0)).toBe(true);
    pool.release(b);
    pool.nextJob();
    pool.nextJob();
    expect(pool.free).toBe(0);
    pool.dispose();
  });
});
