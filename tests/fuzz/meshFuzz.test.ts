/**
 * Bounded, deterministic fuzz of 3D model import (issue 32), both paths: the app's importMesh and
 * the CLI's createNodeMeshLoader. The seeds, every stored regression input
 * (tests/fixtures/fuzz-regressions/mesh), then a fixed number of seeded mutants per path (about
 * 10 s in all on a 2-core machine). Fails on any crash other than InputError, an input taking more than
 * 1 s of CPU time (wall time on the shared machine measures its load), a non-finite vertex, an
 * accepted model that does not save and reopen, or a message that is
 * not one line of at most 200 characters. The long campaign: `npm run fuzz -- --target mesh --count 100000`.
 */
import { describe, expect, it } from 'vitest';
import { formatTable, isFailure } from './fuzzEngine';
import { formatRefusals, fuzzMesh, replayMesh, type MeshTally } from './meshTarget';

const MUTANTS = 400;
const SEED = 32;

function failures(t: MeshTally): string[] {
  return t.failures.filter((f) => isFailure(f.result)).map((f) => `${f.seed}: ${f.result.verdict}${f.result.slow ? ` (${Math.round(f.result.ms)} ms)` : ''}: ${f.result.detail} [${f.applied.join(', ')}]`);
}

describe('fuzz: 3D models under hostile input (app and CLI import paths)', () => {
  for (const path of ['app', 'cli'] as const) {
    it(`${path}: seeds and every stored regression input`, async () => {
      const tally = await replayMesh(path);
      expect(failures(tally)).toEqual([]);
      expect(tally.counts['accepted-valid']).toBeGreaterThanOrEqual(5); // the seeds themselves import, save and reopen
    }, 60_000);

    it(`${path}: ${MUTANTS} seeded mutants`, async () => {
      const tally = await fuzzMesh(path, MUTANTS, SEED);
      console.log(`${formatTable([tally])}\nrefusals: ${formatRefusals(tally)}`);
      expect(failures(tally)).toEqual([]);
      // The mutants reach both outcomes and the limits this target exists for.
      expect(tally.counts['accepted-valid']).toBeGreaterThan(MUTANTS / 10);
      expect(tally.refusals.get('accessor/view bounds') ?? 0).toBeGreaterThan(0);
      expect(tally.refusals.get('count cap') ?? 0).toBeGreaterThan(0);
    }, 120_000);
  }
});
