/**
 * Bounded, deterministic fuzz of every format the product reads (issue 18):
 * the real fixtures, every stored regression input, then a fixed number of
 * seeded mutants per target (about 40 s in all on a 2-core machine). Fails on
 * any crash, non-finite value or dropped field accepted, accepted-invalid
 * value, multi-line or over-200-character message, or input slower than 1 s.
 * The long campaign is `npm run fuzz` (docs/scene-format.md).
 */
import { describe, expect, it } from 'vitest';
import { allTargets, formatTable, fuzz, isFailure, replay, type Tally } from './fuzzEngine';

/** Mutants per target: ~5-8 s each here (photometry has its own, longer campaign in tests/core/photometry/fuzz.test.ts). */
const BUDGET: Record<string, number> = { scene: 1500, 'scene-files': 1500, configuration: 1500, 'share-link': 1800, catalog: 800, photometry: 200, gldf: 250, l3d: 400 };
const SEED = 18;

const targets = await allTargets();

function failures(t: Tally): string[] {
  return t.failures.filter((f) => isFailure(f.result)).map((f) => `${f.seed}: ${f.result.verdict}${f.result.slow ? ` (${Math.round(f.result.ms)} ms)` : ''}: ${f.result.detail} [${f.applied.join(', ')}]`);
}

describe('fuzz: formats under hostile input', () => {
  it('has the four format targets', () => {
    expect(targets.map((t) => t.name)).toEqual(expect.arrayContaining(['scene', 'configuration', 'share-link', 'catalog', 'gldf', 'l3d']));
  });

  for (const target of targets) {
    it(`${target.name}: fixtures and every stored regression input`, () => {
      const tally = replay(target);
      expect(failures(tally)).toEqual([]);
      expect(tally.counts['accepted-valid']).toBeGreaterThanOrEqual(1); // the real fixtures still load
    });

    it(`${target.name}: ${BUDGET[target.name] ?? 500} seeded mutants`, () => {
      const tally = fuzz(target, BUDGET[target.name] ?? 500, SEED);
      console.log(formatTable([tally]));
      expect(failures(tally)).toEqual([]);
      expect(tally.counts['refused-one-line']).toBeGreaterThan(0);
    });
  }
});
