/**
 * The bright patches chosen on the GPU (selectBrightPatchesOnGpu.ts) against the CPU selection
 * (selectBrightPatches.ts) on the same tile sums: the same tiles in the same order (ties included),
 * the same rectangles to float rounding, the same residual mask; bakes of the stiff scenes give
 * the same maps either way; and a bake that outputs no maps reads nothing back.
 */
import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES, type LightingScene, type Rgb } from '../../../src/core/model/lightingScene/lightingScene';
import type { Photometry } from '../../../src/core/photometry/types';
import { brightPatchOptions } from '../../../src/engines/bake/brightPatchOptions';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { createPassCompiler } from '../../../src/engines/bake/createPassCompiler';
import { readRgba, requireFloatTargets, uploadRgb } from '../../../src/engines/bake/floatTarget';
import { patchTable, PATCH_TABLE_WIDTH } from '../../../src/engines/bake/patchTable';
import { readBacks } from '../../../src/engines/bake/readBackCounter';
import { softwareRenderer } from '../../../src/engines/bake/softwareRenderer';
import { drawTileSums, readTileSums, tileSums } from '../../../src/engines/bake/readTileSums';
import { selectBrightPatches } from '../../../src/engines/bake/selectBrightPatches';
import { selectBrightPatchesOnGpu } from '../../../src/engines/bake/selectBrightPatchesOnGpu';
import { surfaceLayouts } from '../../../src/engines/bake/surfaceLayout';
import { createTargetPool } from '../../../src/engines/bake/targetPool';
import type { BakedMaps } from '../../../src/engines/bake/bakedMaps';
import { loadIes } from './bakeTestKit';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();

/** Mulberry32: a seeded uniform generator on [0, 1). */
function seeded(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/**
 * Direct maps of a 2.5 × 2.4 × 2 m room at 0.05 m: a noisy base and hot spots of random size and
 * strength, and the same spot drawn at the same texels of the north and south walls (equal sizes,
 * equal ρ): equal tile sums, a tie that only the surface order breaks.
 */
function selectionCase(seed: number, maxPatches: number) {
  const { linear } = requireFloatTargets(gl);
  const pool = createTargetPool(gl, linear);
  const { compile } = createPassCompiler(gl, { compile: 0 });
  const layouts = surfaceLayouts({ width: 2.5, height: 2.4, depth: 2 }, 0.05, 512);
  const reflectance: Rgb[] = layouts.map((_, i) => (i === 1 ? [0, 0, 0] : ([0.5 + 0.05 * i, 0.6, 0.7 - 0.04 * i] as Rgb)));
  const north = layouts.findIndex((l) => l.name === 'north');
  const south = layouts.findIndex((l) => l.name === 'south');
  reflectance[south] = reflectance[north];
  const random = seeded(seed);
  // Random spots everywhere but on the north and south walls, which get the same two spots.
  const others = layouts.map((l) => l.index).filter((i) => i !== north && i !== south);
  const spots = Array.from({ length: 40 }, () => ({ surface: others[Math.floor(random() * others.length)], u: random(), v: random(), r: 0.5 + 4 * random(), e: 10 ** (3 + 3 * random()) }));
  spots.push({ surface: north, u: 0.3, v: 0.6, r: 2, e: 3e5 }, { surface: north, u: 0.7, v: 0.2, r: 1, e: 8e4 });
  const direct = layouts.map((l) => {
    const rgb = new Float32Array(l.width * l.height * 3);
    for (let j = 0; j < l.height; j++) {
      for (let i = 0; i < l.width; i++) {
        // A base that depends on the texel only: equal on the north and south walls.
        let e = 100 + 2 * ((i * 7 + j * 13) % 10);
        for (const s of spots) {
          const onWall = s.surface === l.index || (s.surface === north && l.index === south);
          if (onWall) e += s.e * Math.exp(-((i - s.u * l.width) ** 2 + (j - s.v * l.height) ** 2) / (2 * s.r * s.r));
        }
        rgb.set([e, 0.9 * e, 0.8 * e], 3 * (j * l.width + i));
      }
    }
    const t = pool.acquire(l.width, l.height, false);
    uploadRgb(gl, t, rgb);
    return t;
  });
  const options = { ...brightPatchOptions({ brightPatches: maxPatches }) };
  const reflecting = layouts.filter((l) => reflectance[l.index].some((r) => r > 0));
  const { sums } = readTileSums(gl, compile(tileSums, 'tiles'), reflecting, reflectance, direct, options.tileSize, pool, () => {});
  const cpu = selectBrightPatches(sums, options);
  const tiles = drawTileSums(gl, compile(tileSums, 'tiles'), reflecting, reflectance, direct, options.tileSize, pool);
  const gpu = selectBrightPatchesOnGpu(gl, tiles, options, compile, pool);
  const table = readRgba(gl, gpu.table);
  const mask = readRgba(gl, gpu.mask);
  const summary = gpu.readSummary(() => {});
  const firstTile = new Map<number, number>();
  let g = 0;
  for (const grid of tiles.grids) {
    firstTile.set(grid.frame.index, g);
    g += grid.tilesU * grid.tilesV;
  }
  const globalIndex = (p: (typeof cpu.patches)[number]) => firstTile.get(p.surface)! + p.tileV * tiles.grids.find((x) => x.frame.index === p.surface)!.tilesU + p.tileU;
  const maskedTiles: number[] = [];
  for (const grid of tiles.grids) {
    for (let iv = 0; iv < grid.tilesV; iv++)
      for (let iu = 0; iu < grid.tilesU; iu++) if (mask[4 * ((iv * mask.length) / 4 / tiles.rowsPerMode + grid.column + iu)] === 1) maskedTiles.push(firstTile.get(grid.frame.index)! + iv * grid.tilesU + iu);
  }
  const result = { cpu, cpuTable: patchTable(cpu.patches), table, summary, rows: gpu.rows, globalIndex, maskedTiles, tieTile: { north, south } };
  gpu.dispose();
  pool.release(tiles.atlas);
  for (const t of direct) pool.release(t);
  pool.dispose();
  return result;
}

describe('bright patches chosen on the GPU', () => {
  for (const [seed, maxPatches] of [
    [1, 64],
    [2, 64],
    [3, 20],
    [4, 5],
  ] as const) {
    it(`seed ${seed}, at most ${maxPatches}: the CPU's tiles in the CPU's order, rectangles within 1e-5, the same mask and summary`, () => {
      const r = selectionCase(seed, maxPatches);
      const n = r.cpu.patches.length;
      expect(n).toBeGreaterThan(0);
      expect(r.summary.count).toBe(n);
      expect(r.summary.peakedness).toBeCloseTo(r.cpu.peakedness, 4);
      expect(Math.abs(r.summary.peakedness / r.cpu.peakedness - 1)).toBeLessThan(1e-5);
      expect(Math.abs(r.summary.residualPeakedness / r.cpu.residualPeakedness - 1)).toBeLessThan(1e-4);
      // Float32 on the GPU against float64 on the CPU: the spread √(m₂/y − μ²) cancels digits.
      let worst = 0;
      const row = (t: Float32Array, k: number, c: number) => Array.from(t.subarray((k * PATCH_TABLE_WIDTH + c) * 4, (k * PATCH_TABLE_WIDTH + c) * 4 + 4));
      r.cpu.patches.forEach((p, k) => {
        expect(row(r.table, k, 0)[3]).toBe(p.surface);
        expect(row(r.table, k, 1)[3]).toBe(r.globalIndex(p));
        for (const c of [0, 1, 2, 3]) {
          const want = row(r.cpuTable, k, c).slice(0, 3);
          const got = row(r.table, k, c).slice(0, 3);
          const scale = Math.max(...want.map(Math.abs));
          for (let i = 0; i < 3; i++) worst = Math.max(worst, Math.abs(got[i] - want[i]) / scale);
        }
      });
      console.info(`seed ${seed}: ${n} patches, rectangles and exitances within ${worst.toExponential(2)} of the CPU's`);
      expect(worst).toBeLessThan(1e-5);
      // The table ends with the sentinel right after the last patch (unless it is full).
      if (n < r.rows) expect(row(r.table, n, 0)[3]).toBe(-1);
      expect(r.maskedTiles.sort((a, b) => a - b)).toEqual(r.cpu.patches.map(r.globalIndex).sort((a, b) => a - b));
    });
  }

  it('ties: the north and south walls carry the same exitance; each tile is taken on the north wall (lower surface index) just before its twin on the south wall, on both sides', () => {
    const r = selectionCase(5, 64);
    const { north, south } = r.tieTile;
    const first = Math.min(north, south);
    const twins = r.cpu.patches.flatMap((p, k) => (p.surface === first ? [{ k, twin: r.cpu.patches.findIndex((q) => q.surface === north + south - first && q.tileU === p.tileU && q.tileV === p.tileV) }] : []));
    expect(twins.length).toBeGreaterThan(1);
    for (const { k, twin } of twins) expect(twin).toBe(k + 1);
    const at = (k: number, c: number) => r.table[(k * PATCH_TABLE_WIDTH + c) * 4 + 3];
    r.cpu.patches.forEach((p, k) => {
      expect(at(k, 0)).toBe(p.surface);
      expect(at(k, 1)).toBe(r.globalIndex(p));
    });
  });
});

const stiffScenes: { name: string; scene: LightingScene; files: Record<string, Photometry> }[] = [
  {
    name: 'narrow spot 15 cm from a wall',
    scene: {
      version: 1,
      room: { width: 2.5, height: 2.4, depth: 2, reflectance: { floor: 0.3, ceiling: 0.85, north: 0.8, south: 0.6, west: 0.5, east: 0.7 } },
      luminaires: [{ photometry: 'spot', position: [1.2, 1.3, 0.15], yaw: 0, pitch: 90, roll: 0 }],
    },
    files: { spot: loadIes('bega_84693_narrow_spot.ies') },
  },
  {
    name: 'two up-lights 3 and 8 cm under a ρ = 0.95 ceiling',
    scene: {
      version: 1,
      room: { width: 2.5, height: 2.4, depth: 2, reflectance: { floor: 0.3, ceiling: 0.95, north: 0.8, south: 0.8, west: 0.7, east: 0.7 } },
      luminaires: [
        { photometry: 'up', position: [0.8, 2.37, 1], yaw: 0, pitch: 0, roll: 0 },
        { photometry: 'up', position: [1.8, 2.32, 1.1], yaw: 90, pitch: 0, roll: 0 },
      ],
    },
    files: { up: loadIes('erco_trion_ceiling_washlight_uplight.ies') },
  },
];

/** Largest |a − b| over a map, relative to the map's peak |a|; and per texel, relative to |a|, over the texels above 1e-3 of the peak. */
function worstRelative(a: BakedMaps, b: BakedMaps): { ofPeak: number; perTexel: number } {
  let worst = 0;
  let perTexel = 0;
  for (const s of SURFACE_NAMES) {
    for (const kind of ['direct', 'indirect', 'total'] as const) {
      const x = a[s][kind];
      const y = b[s][kind];
      let peak = 0;
      let diff = 0;
      for (let i = 0; i < x.length; i++) {
        peak = Math.max(peak, Math.abs(x[i]));
        diff = Math.max(diff, Math.abs(x[i] - y[i]));
      }
      if (peak > 0) worst = Math.max(worst, diff / peak);
      for (let i = 0; i < x.length; i++) if (Math.abs(x[i]) > 1e-3 * peak) perTexel = Math.max(perTexel, Math.abs(x[i] - y[i]) / Math.abs(x[i]));
    }
  }
  return { ofPeak: worst, perTexel };
}

describe('stiff scenes: GPU selection against CPU selection (default settings)', () => {
  const baker = createBaker(gl);
  for (const { name, scene, files } of stiffScenes) {
    it(`${name}: the same patches, maps within 1e-6 of their peak`, () => {
      const bakeScene = { room: scene.room, luminaires: scene.luminaires.map((l) => ({ ...l, photometry: files[l.photometry] })) };
      const cpu = baker.bake(bakeScene, { brightSelection: 'cpu' });
      const gpu = baker.bake(bakeScene, { brightSelection: 'gpu' });
      const worst = worstRelative(cpu.maps, gpu.maps);
      console.info(`${name}: ${gpu.report.brightPatches?.count} patches; maps differ by ${worst.ofPeak.toExponential(2)} of their peak, ${worst.perTexel.toExponential(2)} per texel`);
      expect(gpu.report.brightPatches?.count).toBe(cpu.report.brightPatches?.count);
      expect(gpu.report.brightPatches?.count ?? 0).toBeGreaterThan(0);
      expect(worst.ofPeak).toBeLessThanOrEqual(1e-6);
    });
  }
});

describe('read-backs of a bake that outputs no maps', () => {
  const baker = createBaker(gl);
  const { scene, files } = stiffScenes[0];
  const bakeScene = { room: scene.room, luminaires: scene.luminaires.map((l) => ({ ...l, photometry: files[l.photometry] })) };
  const settings = { texelSize: 0.1, samples: 16, bounces: 2 };

  it('bright patches chosen on the GPU: the context counts 0 read-backs through the whole bake; the report then reads its stats row and the patch summary', () => {
    const before = { ...readBacks(gl) };
    // Forced: unset, this software context selects on the CPU (the test below).
    const job = baker.start(bakeScene, { ...settings, brightSelection: 'gpu' });
    job.run();
    job.finalize();
    expect(readBacks(gl).count - before.count).toBe(0);
    const report = job.report();
    expect(report.brightPatches?.count ?? 0).toBeGreaterThan(0);
    expect(readBacks(gl).count - before.count).toBe(2);
    expect(readBacks(gl).bytes - before.bytes).toBe((settings.bounces + 1) * 16 + 16);
    expect(report.readbacks).toEqual({ count: 2, bytes: (settings.bounces + 1) * 16 + 16 });
    job.dispose();
  });

  it('the twin, chosen on the CPU: the counter sees the tile sums read back during the bake', () => {
    const before = { ...readBacks(gl) };
    const job = baker.start(bakeScene, { ...settings, brightSelection: 'cpu' });
    job.run();
    job.finalize();
    expect(readBacks(gl).count - before.count).toBe(1);
    const report = job.report();
    expect(report.brightPatches?.count ?? 0).toBeGreaterThan(0);
    expect(readBacks(gl).count - before.count).toBe(2);
    expect(report.readbacks.count).toBe(2);
    expect(readBacks(gl).bytes - before.bytes).toBe(report.readbacks.bytes);
    job.dispose();
  });

  it('unset, the selection follows the renderer: this context is llvmpipe (software), so the CPU path and its one read-back of the tile sums', () => {
    expect(softwareRenderer(gl)).toBe(true);
    const before = { ...readBacks(gl) };
    const job = baker.start(bakeScene, settings);
    job.run();
    job.finalize();
    expect(readBacks(gl).count - before.count).toBe(1);
    expect(job.report().brightPatches?.count ?? 0).toBeGreaterThan(0);
    job.dispose();
  });
});
