import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { SURFACE_NAMES, type LightingScene, type SurfaceName, type Vec3 } from '../../core/model/lightingScene/lightingScene';
import { furnitureMesh } from '../../core/model/objects/furniture/furnitureLibrary';
import { parsePhotometry } from '../../core/photometry/parsePhotometry';
import type { Photometry } from '../../core/photometry/types';
import type { BakeObject } from '../../engines/bake/bakeScene';
import { luxOf } from '../../engines/bake/bakedMaps';
import type { Baker } from '../../engines/bake/createBaker';
import { texelCentre } from '../../engines/bake/surfaceLayout';
import { furnishedIlluminanceAt } from '../../reference/furnishedIlluminanceAt';
import { luminanceAt, solveFurnishedReference } from '../../reference/solveFurnishedReference';
import type { BenchQuality } from './benchScenes';
import { relativeErrors } from './errorStats';

/** A furnished benchmark scene (issue #10): a lighting scene, its photometry files, library furniture. */
export interface FurnishedBenchScene {
  name: string;
  description: string;
  scene: LightingScene;
  /** `photometry` key → file under public/ies. */
  files: Record<string, string>;
  objects: BakeObject[];
  /** Wall patch edge of the furnished reference, metres (object patches the same). */
  referencePatch: number;
}

const reflectance = (floor: number, ceiling: number, walls: number): LightingScene['room']['reflectance'] => ({ floor, ceiling, north: walls, south: walls, west: walls, east: walls });
const item = (id: string, type: string, position: Vec3, yaw = 0): BakeObject => ({ id, mesh: furnitureMesh(type), position, yaw, scale: 1 });

export const FURNISHED_SCENES: readonly FurnishedBenchScene[] = [
  {
    name: 'dining-pendant',
    description: 'stiff: 4 × 2.7 × 3.5 m, a direct/indirect pendant (Ledalite) 40 cm above a 1.8 × 0.9 m dining table (library item), two chairs',
    scene: { version: 1, room: { width: 4, height: 2.7, depth: 3.5, reflectance: reflectance(0.3, 0.8, 0.55) }, luminaires: [{ photometry: 'pendant', position: [2, 1.15, 1.75], yaw: 0, pitch: 0, roll: 0 }] },
    files: { pendant: 'ledalite_pendant_direct_indirect_iesna95.ies' },
    objects: [item('table', 'dining-table', [2, 0, 1.75]), item('chair-1', 'chair', [1.5, 0, 1.05]), item('chair-2', 'chair', [2.5, 0, 2.45], 180)],
    referencePatch: 0.3,
  },
  {
    name: 'living-furnished',
    description: '5 × 2.7 × 4 m, three downlights (BEGA 50975), sofa, coffee table and a sideboard 2 cm from the north wall (library items)',
    scene: {
      version: 1,
      room: { width: 5, height: 2.7, depth: 4, reflectance: reflectance(0.3, 0.85, 0.6) },
      luminaires: [
        { photometry: 'down', position: [1.5, 2.65, 2], yaw: 0, pitch: 0, roll: 0 },
        { photometry: 'down', position: [3.5, 2.65, 2], yaw: 0, pitch: 0, roll: 0 },
        { photometry: 'down', position: [2.5, 2.65, 0.8], yaw: 0, pitch: 0, roll: 0 },
      ],
    },
    files: { down: 'bega_50975_downlight_lm1995_crlf.ies' },
    objects: [item('sofa', 'sofa', [2.5, 0, 3.4], 180), item('coffee', 'coffee-table', [2.5, 0, 2.3]), item('sideboard', 'sideboard', [2.5, 0, 0.245])],
    referencePatch: 0.3,
  },
];

/** Furnished rungs: texel centres (texelSupersampling 1) so direct light compares point by point. */
export const FURNISHED_LADDER: readonly BenchQuality[] = [
  { texelSize: 0.1, samples: 64, bounces: 4 },
  { texelSize: 0.05, samples: 64, bounces: 4 },
];

export interface FurnishedBenchRow {
  scene: string;
  quality: BenchQuality;
  bakeMs: number;
  wallPoints: number;
  atlasTexels: number;
  /** RMS of the relative error, walls and object atlas, direct and total. */
  wallsDirect: number;
  wallsTotal: number;
  atlasDirect: number;
  atlasTotal: number;
  /** Σ E·A bake / reference − 1, walls + objects, total light. */
  fluxError: number;
}

export interface FurnishedBenchScenePart {
  scene: FurnishedBenchScene;
  patches: number;
  sweeps: number;
  referenceMs: number;
  rows: FurnishedBenchRow[];
}

/** Bake values and reference values at the same points, direct and total. */
interface Samples {
  d: number[];
  rd: number[];
  t: number[];
  rt: number[];
}

const noSamples = (): Samples => ({ d: [], rd: [], t: [], rt: [] });
type FurnishedReference = ReturnType<typeof solveFurnishedReference>;
type BakedMaps = ReturnType<Baker['bake']>['maps'];

function push(out: Samples, d: number, t: number, r: { direct: number; total: number }) {
  out.d.push(d);
  out.rd.push(r.direct);
  out.t.push(t);
  out.rt.push(r.total);
}

/** The room's six surfaces at texel centres every 0.2 m, against the reference there. */
function wallSamples(maps: BakedMaps, reference: FurnishedReference, texelSize: number): Samples {
  const wall = noSamples();
  const stride = Math.max(1, Math.round(0.2 / texelSize));
  for (const name of SURFACE_NAMES as readonly SurfaceName[]) {
    const m = maps[name];
    const [d, t] = [luxOf(m.direct), luxOf(m.total)];
    for (let j = 0; j < m.layout.height; j += stride) {
      for (let i = 0; i < m.layout.width; i += stride) {
        const k = j * m.layout.width + i;
        push(wall, d[k], t[k], furnishedIlluminanceAt(reference, texelCentre(m.layout, i, j), m.layout.normal));
      }
    }
  }
  return wall;
}

/** Every fully covered atlas texel (about one per 0.1 m), at its G-buffer point and normal, against the reference; and the atlas's Σ E·A. */
function atlasSamples(maps: BakedMaps, reference: FurnishedReference, texelSize: number): { atlas: Samples; flux: number } {
  const atlas = noSamples();
  let flux = 0;
  const o = maps.objects;
  if (!o) return { atlas, flux };
  const [d, t] = [luxOf(o.direct), luxOf(o.total)];
  const { position, normal } = o.atlas;
  const every = Math.max(1, Math.round(0.1 / texelSize) ** 2);
  let covered = 0;
  for (let k = 0; k < d.length; k++) {
    flux += t[k] * position[4 * k + 3] * o.atlas.texelSize ** 2;
    if (position[4 * k + 3] < 0.999 || covered++ % every !== 0) continue;
    push(atlas, d[k], t[k], furnishedIlluminanceAt(reference, [position[4 * k], position[4 * k + 1], position[4 * k + 2]], [normal[4 * k], normal[4 * k + 1], normal[4 * k + 2]]));
  }
  return { atlas, flux };
}

/** Σ E·A of the total light on the room's six surfaces. */
function surfaceFlux(maps: BakedMaps): number {
  let flux = 0;
  for (const name of SURFACE_NAMES as readonly SurfaceName[]) {
    const m = maps[name];
    const a = (m.layout.lengthU / m.layout.width) * (m.layout.lengthV / m.layout.height);
    for (const e of luxOf(m.total)) flux += e * a;
  }
  return flux;
}

/** Σ E·A of the reference's total light over its patches. */
function referenceFlux(reference: FurnishedReference): number {
  let flux = 0;
  reference.patches.forEach((p, i) => {
    flux += p.area * (luminanceAt(reference.directRgb, 3 * i) + luminanceAt(reference.indirectRgb, 3 * i));
  });
  return flux;
}

function rowLine(row: FurnishedBenchRow): string {
  const pct = (e: number) => `${(100 * e).toFixed(2)} %`;
  return `  texel ${row.quality.texelSize} m: bake ${Math.round(row.bakeMs)} ms; RMS walls direct ${pct(row.wallsDirect)} total ${pct(row.wallsTotal)}, objects direct ${pct(row.atlasDirect)} total ${pct(row.atlasTotal)}, flux ${pct(row.fluxError)}`;
}

/** One rung: an untimed warm-up bake, the timed bake, and its errors against the reference. */
function benchRung(baker: Baker, s: FurnishedBenchScene, bakeScene: Parameters<Baker['bake']>[0], reference: FurnishedReference, quality: BenchQuality): { row: FurnishedBenchRow; queryMs: number } {
  const settings = { ...quality, sourceSpacing: 0.05, texelSupersampling: 1 };
  baker.bake(bakeScene, { ...settings, samples: 16, bounces: 1 });
  const started = performance.now();
  const { maps } = baker.bake(bakeScene, settings);
  const bakeMs = performance.now() - started;
  const t1 = performance.now();
  const wall = wallSamples(maps, reference, quality.texelSize);
  const { atlas, flux } = atlasSamples(maps, reference, quality.texelSize);
  const fluxError = (flux + surfaceFlux(maps)) / referenceFlux(reference) - 1;
  const queryMs = performance.now() - t1;
  const peak = Math.max(...wall.rt, ...atlas.rt);
  const rms = (bake: number[], ref: number[]) => relativeErrors(bake, ref, 0.01 * peak).rms;
  const row: FurnishedBenchRow = {
    scene: s.name,
    quality,
    bakeMs,
    wallPoints: wall.d.length,
    atlasTexels: atlas.d.length,
    wallsDirect: rms(wall.d, wall.rd),
    wallsTotal: rms(wall.t, wall.rt),
    atlasDirect: rms(atlas.d, atlas.rd),
    atlasTotal: rms(atlas.t, atlas.rt),
    fluxError,
  };
  return { row, queryMs };
}

/**
 * The furnished rows of `luxbox bench`: each scene baked at each rung (after an untimed
 * warm-up bake) and compared with the furnished CPU reference (src/reference) at wall texel
 * centres (every 0.2 m) and at every fully covered atlas texel (its G-buffer point and normal).
 */
export function runFurnishedBench(baker: Baker, root: string, log: (line: string) => void): FurnishedBenchScenePart[] {
  const parts: FurnishedBenchScenePart[] = [];
  for (const s of FURNISHED_SCENES) {
    const files: Record<string, Photometry> = {};
    for (const [key, file] of Object.entries(s.files)) files[key] = parsePhotometry(readFileSync(join(root, 'public/ies', file)), file);
    const t0 = performance.now();
    const reference = solveFurnishedReference(s.scene, files, s.objects, { patchSize: s.referencePatch, openingCell: 0.05 });
    const solveMs = performance.now() - t0;
    log(`${s.name}: furnished reference ${reference.patches.length} patches, ${reference.sweeps} sweeps, ${Math.round(solveMs)} ms`);
    const bakeScene = { room: s.scene.room, luminaires: s.scene.luminaires.map((l) => ({ ...l, photometry: files[l.photometry] })), objects: s.objects };
    const rows: FurnishedBenchRow[] = [];
    let queryMs = 0;
    for (const quality of FURNISHED_LADDER) {
      const rung = benchRung(baker, s, bakeScene, reference, quality);
      rows.push(rung.row);
      queryMs += rung.queryMs;
      log(rowLine(rung.row));
    }
    parts.push({ scene: s, patches: reference.patches.length, sweeps: reference.sweeps, referenceMs: solveMs + queryMs, rows });
  }
  return parts;
}

/** The furnished rows as markdown (docs/benchmarks.md, "Furnished rooms"). */
export function furnishedTables(parts: readonly FurnishedBenchScenePart[]): string {
  const pct = (e: number): string => `${(100 * e).toFixed(2)} %`;
  const lines: string[] = [];
  lines.push('| scene | reference patches / sweeps | reference time (solve + queries) |');
  lines.push('|---|---|---|');
  for (const p of parts) lines.push(`| ${p.scene.name}: ${p.scene.description} | ${p.patches} / ${p.sweeps} | ${(p.referenceMs / 1000).toFixed(1)} s |`);
  lines.push('');
  lines.push('| scene | texel | samples | bounces | bake time | wall points / atlas texels | walls direct RMS | walls total RMS | objects direct RMS | objects total RMS | flux Σ E·A bake / ref − 1 |');
  lines.push('|---|---|---|---|---|---|---|---|---|---|---|');
  for (const p of parts) {
    for (const r of p.rows) {
      lines.push(
        `| ${r.scene} | ${r.quality.texelSize} m | ${r.quality.samples} | ${r.quality.bounces} | ${Math.round(r.bakeMs)} ms | ${r.wallPoints} / ${r.atlasTexels} | ${pct(r.wallsDirect)} | ${pct(r.wallsTotal)} | ${pct(r.atlasDirect)} | ${pct(r.atlasTotal)} | ${pct(r.fluxError)} |`,
      );
    }
  }
  return lines.join('\n');
}
