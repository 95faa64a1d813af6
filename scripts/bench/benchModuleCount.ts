/**
 * Bake cost against module count (issue #15): the relight engine on headless-gl, default
 * ('balanced' = VIEWER_BAKE_SETTINGS) settings, modules 1, 3, 6, 11, 20 in an empty 8 × 6 × 2.8 m
 * room (moduleCountScene). Each count runs `repeats` times, each on a fresh GL context (a first
 * toggle: programs compile inside the timing); the median is reported.
 * Run alone: xvfb-run -a npx tsx scripts/bench/benchModuleCount.ts [out.json] [repeats] [counts, e.g. 3,20]
 */
import { writeFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import { createHeadlessGL } from '../../src/hosts/node/createHeadlessGL';
import { moduleCountScene } from './moduleCountScene';
import { timeEngineBake, type EngineBakeTiming } from './timeEngineBake';

export const MODULE_COUNTS = [1, 3, 6, 11, 20] as const;

export interface ModuleCountRow {
  modules: number;
  /** Medians over the repeats, ms. */
  litMs: number;
  doneMs: number;
  groupBakes: number;
  runs: EngineBakeTiming[];
}

const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

export function benchModuleCount(repeats = 3, log: (line: string) => void = console.log, counts: readonly number[] = MODULE_COUNTS): ModuleCountRow[] {
  const rows: ModuleCountRow[] = [];
  for (const modules of counts) {
    const runs: EngineBakeTiming[] = [];
    for (let k = 0; k < repeats; k++) {
      const gl = createHeadlessGL();
      try {
        runs.push(timeEngineBake(gl, moduleCountScene(modules)));
      } finally {
        gl.destroy();
      }
    }
    const row = { modules, litMs: median(runs.map((r) => r.litMs)), doneMs: median(runs.map((r) => r.doneMs)), groupBakes: runs[0].groupBakes, runs };
    log(`${modules} modules: lit ${row.litMs.toFixed(0)} ms, done ${row.doneMs.toFixed(0)} ms (runs ${runs.map((r) => `${r.litMs.toFixed(0)}/${r.doneMs.toFixed(0)}`).join(', ')})`);
    rows.push(row);
  }
  return rows;
}

if (import.meta.url === pathToFileURL(process.argv[1]).href) {
  const rows = benchModuleCount(Number(process.argv[3] ?? 3), console.log, process.argv[4] ? process.argv[4].split(',').map(Number) : MODULE_COUNTS);
  if (process.argv[2]) writeFileSync(process.argv[2], JSON.stringify({ date: new Date().toISOString(), rows }, null, 2));
}
