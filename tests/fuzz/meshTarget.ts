/**
 * Fuzz target `mesh` (issue 32): 3D models through both import paths — the app's
 * (`importMesh` with the picked files and the chosen unit) and the CLI's
 * (`createNodeMeshLoader`, the files written to a folder and read from there, units detected).
 * Importing is asynchronous (three's GLTFLoader), so this target has its own campaign loop; it
 * shares the tally, the table and the regression store with the other targets (fuzzEngine.ts).
 * A run fails on: a throw that is not an InputError, a message that is not one line of at most
 * 200 characters, more than 1 s of CPU time, a non-finite vertex, or an accepted model that addObject takes
 * but that does not save and reopen (saveAndReopen.ts).
 */
import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { InputError } from '../../src/core/inputError';
import { importMesh } from '../../src/engines/meshImport/importMesh';
import type { ImportedMesh, MeshFile } from '../../src/engines/meshImport/importedMesh';
import { createNodeMeshLoader } from '../../src/hosts/node/createNodeMeshLoader';
import { saveAndReopen } from '../engines/meshImport/saveAndReopen';
import { messageProblem } from './checks';
import { emptyTally, isFailure, loadRegressions, MAX_MESSAGE, SLOW_MS, type RunResult, type Tally } from './fuzzEngine';
import type { FuzzSeed } from './fuzzTarget';
import { decodeBundle, encodeBundle, type MeshBundle } from './meshBundle';
import { mutateBundle } from './meshMutators';
import { createRng } from './mutate';

export type MeshPath = 'app' | 'cli';
const MODELS = 'tests/fixtures/models';
const encoder = new TextEncoder();

const fixture = (name: string): MeshFile => ({ name, bytes: new Uint8Array(readFileSync(join(MODELS, name))) });

/** A unit cube of 12 triangles in centimetres with two materials: written here, small, with every OBJ feature the scanner handles. */
function cubeObj(): MeshBundle {
  const v = [
    [0, 0, 0],
    [50, 0, 0],
    [50, 50, 0],
    [0, 50, 0],
    [0, 0, 50],
    [50, 0, 50],
    [50, 50, 50],
    [0, 50, 50],
  ];
  const text = [
    '# luxbox fuzz seed: 50 cm cube, two materials, a continued line, negative indices',
    'mtllib cube.mtl',
    ...v.map(([x, y, z]) => `v ${x} ${y} ${z}`),
    'vn 0 0 1',
    'vt 0 0',
    'usemtl side',
    'f 1 4 3 2',
    'f 5 6 7 8',
    'f 1 2 6 \\',
    '5',
    'usemtl top',
    'f -5 -1 -2 -6',
    'f 2 3 7 6',
    'f 1 5 8 4',
  ].join('\n');
  return {
    units: 'auto',
    files: [
      { name: 'cube.obj', bytes: encoder.encode(text) },
      { name: 'cube.mtl', bytes: encoder.encode('newmtl side\nKd 0.8 0.8 0.8\nnewmtl top\nKd 0.2 0.3 0.4\n') },
    ],
  };
}

/** Seeds: the project's own table fixtures (tests/fixtures/models, written by writeModelFixtures.ts) in every container, and the cube. */
export function meshSeeds(): FuzzSeed[] {
  const bundles: [string, MeshBundle][] = [
    ['table.obj + table.mtl', { units: 'auto', files: [fixture('table.obj'), fixture('table.mtl')] }],
    ['table.gltf (data URI)', { units: 'auto', files: [fixture('table.gltf')] }],
    ['table.glb', { units: 'auto', files: [fixture('table.glb')] }],
    ['table-external.gltf + .bin', { units: 'auto', files: [fixture('table-external.gltf'), fixture('table-external.bin')] }],
    ['cube.obj (cm) + cube.mtl', cubeObj()],
  ];
  return bundles.map(([name, bundle]) => ({ name, bytes: encodeBundle(bundle) }));
}

/** Kinds of refusal for the campaign report, by the message's wording (first match). */
const REFUSAL_KINDS: [string, RegExp][] = [
  ['byte cap', /MB are read|is longer than|continues past/],
  ['count cap', /are read$|instances; at most/],
  ['accessor/view bounds', /accessors\[|bufferViews\[|byteStride|sparse/],
  ['triangle budget', /triangles; the limit is/],
  ['vertex cap', /vertices; simplify/],
  ['stored size', /in a saved configuration/],
  ['extent', /from the model's origin/],
  ['non-finite', /not a finite number/],
  ['index range', /refers to vertex/],
  ['references', /refers to (accessor|node|mesh)/],
  ['OBJ syntax', /line \d+:|no faces/],
  ['no triangles', /no triangles/],
  ['JSON', /JSON|must be an array|must be an object|asset\.version|must be a string/],
  ['GLB container', /GLB|chunk|truncated|wrong length/],
  ['buffers', /buffers\[|data URI|is missing|cannot read/],
  ['node graph', /node|scene|mesh \S+, which/],
  ['extension', /extension/],
  ['files picked', /not a model luxbox reads|no \.obj|no \.gltf/],
];

export function refusalKind(message: string): string {
  return REFUSAL_KINDS.find(([, re]) => re.test(message))?.[0] ?? 'other';
}

/** One input through one path, classified as fuzzEngine's runOne does. */
export async function runMesh(bytes: Uint8Array, path: MeshPath, folder: string): Promise<MeshRunResult> {
  const r = await runMeshTimed(bytes, path, folder);
  // Judged by CPU time: on the shared 2-core machine (load average up to 14) wall time measures the
  // neighbours — 898 ms of wall time for 157 ms of CPU in one CI run. The table's max ms stays wall time.
  return { ...r, slow: r.cpuMs > SLOW_MS };
}

async function runMeshTimed(bytes: Uint8Array, path: MeshPath, folder: string): Promise<MeshRunResult> {
  const bundle = decodeBundle(bytes);
  const cpu0 = process.cpuUsage();
  const cpuMs = (): number => {
    const d = process.cpuUsage(cpu0);
    return (d.user + d.system) / 1000;
  };
  const t0 = performance.now();
  let imported: ImportedMesh;
  try {
    if (path === 'app') imported = await importMesh(bundle.files, { units: bundle.units });
    else {
      // The CLI reads the model and what it refers to from a folder: write the bundle there.
      rmSync(folder, { recursive: true, force: true });
      mkdirSync(folder, { recursive: true });
      // File systems take names of at most 255 bytes: a longer one keeps its last 200 characters.
      const onDisk = (name: string): string => name.replace(/[\\/]/g, '_').slice(-200) || 'model.obj';
      for (const f of bundle.files) writeFileSync(join(folder, onDisk(f.name)), f.bytes);
      const main = bundle.files.find((f) => /\.(gltf|glb)$/i.test(f.name)) ?? bundle.files.find((f) => /\.obj$/i.test(f.name)) ?? bundle.files[0];
      const shown = onDisk(main.name);
      const loader = createNodeMeshLoader(folder);
      await loader.load(shown);
      imported = loader.imported.get(shown)!;
    }
  } catch (error) {
    const ms = performance.now() - t0;
    if (!(error instanceof InputError)) {
      const e = error as Error;
      const where =
        (e?.stack ?? '')
          .split('\n')
          .find((l) => /src\//.test(l))
          ?.trim() ?? '';
      return { verdict: 'crash', ms, cpuMs: cpuMs(), detail: `${e?.name ?? 'throw'}: ${String(e?.message ?? error).slice(0, 120)} ${where}`, slow: false };
    }
    const bad = messageProblem(error.message, MAX_MESSAGE);
    return { verdict: bad ? 'bad-message' : 'refused-one-line', ms, cpuMs: cpuMs(), detail: bad ? `${bad}: ${error.message.slice(0, 160)}` : error.message, slow: false };
  }
  const ms = performance.now() - t0;
  const cpu = cpuMs();
  const { problems } = saveAndReopen(imported);
  if (problems.length === 0) return { verdict: 'accepted-valid', ms, cpuMs: cpu, detail: '', slow: false };
  return { verdict: problems.some((p) => p.startsWith('non-finite')) ? 'non-finite' : 'accepted-invalid', ms, cpuMs: cpu, detail: problems.join('; ').slice(0, 300), slow: false };
}

/** A run with its CPU time too: on a shared, overloaded machine wall time measures the neighbours. */
export interface MeshRunResult extends RunResult {
  cpuMs: number;
}

export interface MeshTally extends Tally {
  refusals: Map<string, number>;
  /** Slowest input by the process's CPU time (user + system), and how many took over 1 s of it. */
  maxCpuMs: number;
  slowCpu: number;
}

function record(t: MeshTally, r: MeshRunResult, bytes: Uint8Array, applied: string[], seed: string, keep: number): void {
  t.inputs++;
  t.maxCpuMs = Math.max(t.maxCpuMs, r.cpuMs);
  if (r.cpuMs > SLOW_MS) t.slowCpu++;
  t.counts[r.verdict]++;
  if (r.slow) t.slow++;
  t.maxMs = Math.max(t.maxMs, r.ms);
  t.totalMs += r.ms;
  if (r.verdict === 'refused-one-line') t.refusals.set(refusalKind(r.detail), (t.refusals.get(refusalKind(r.detail)) ?? 0) + 1);
  if (isFailure(r) && t.failures.length < keep) t.failures.push({ result: r, applied, seed, bytes });
}

/**
 * `count` seeded mutants through one path (the same mutants for both paths at the same seed).
 * `inputs` replaces the mutants by given inputs (the seeds and regressions: `replayMesh`).
 */
export async function fuzzMesh(path: MeshPath, count: number, seed: number, options: { keepFailures?: number; onProgress?: (done: number, tally: MeshTally) => void } = {}): Promise<MeshTally> {
  const tally: MeshTally = { ...emptyTally(`mesh (${path})`), refusals: new Map(), maxCpuMs: 0, slowCpu: 0 };
  const seeds = meshSeeds();
  const rng = createRng(seed ^ 0x6d657368);
  const folder = mkdtempSync(join(tmpdir(), 'luxbox-mesh-fuzz-'));
  try {
    for (let i = 0; i < count; i++) {
      const s = seeds[i % seeds.length];
      const { bundle, applied } = mutateBundle(decodeBundle(s.bytes), rng);
      const bytes = encodeBundle(bundle);
      record(tally, await runMesh(bytes, path, join(folder, 'm')), bytes, applied, s.name, options.keepFailures ?? 50);
      if (options.onProgress && (i + 1) % 1000 === 0) options.onProgress(i + 1, tally);
    }
  } finally {
    rmSync(folder, { recursive: true, force: true });
  }
  return tally;
}

/** The seeds and every stored regression input (tests/fixtures/fuzz-regressions/mesh), once each through `path`. */
export async function replayMesh(path: MeshPath): Promise<MeshTally> {
  const tally: MeshTally = { ...emptyTally(`mesh (${path})`), refusals: new Map(), maxCpuMs: 0, slowCpu: 0 };
  const folder = mkdtempSync(join(tmpdir(), 'luxbox-mesh-fuzz-'));
  try {
    for (const s of [...meshSeeds(), ...loadRegressions('mesh')]) record(tally, await runMesh(s.bytes, path, join(folder, 'm')), s.bytes, ['(replay)'], s.name, Infinity);
  } finally {
    rmSync(folder, { recursive: true, force: true });
  }
  return tally;
}

/** Refusals by kind, most frequent first ("triangle budget 812, accessor/view bounds 640, …"), then the CPU time. */
export function formatRefusals(t: MeshTally): string {
  const kinds = [...t.refusals]
    .sort((a, b) => b[1] - a[1])
    .map(([k, n]) => `${k} ${n}`)
    .join(', ');
  return `${kinds}; CPU time: slowest ${Math.round(t.maxCpuMs)} ms, ${t.slowCpu} over 1 s`;
}
