import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { parsePhotometry, type Photometry } from '../../../src/core/photometry';
import { createRng } from '../../fuzz/mutate';

export const REAL_DIR = 'public/ies';
export const FIXTURE_DIR = 'tests/fixtures/photometry';

export const realFiles = (): string[] =>
  readdirSync(REAL_DIR)
    .filter((f) => /\.(ies|ldt)$/i.test(f))
    .sort();
export const fixtureFiles = (): string[] =>
  readdirSync(FIXTURE_DIR)
    .filter((f) => /\.(ies|ldt)$/i.test(f))
    .sort();

export function loadReal(name: string): Photometry {
  return parsePhotometry(readFileSync(join(REAL_DIR, name)), name);
}

export function loadFixture(name: string): Photometry {
  return parsePhotometry(readFileSync(join(FIXTURE_DIR, name)), name, {
    resolveTilt: (tilt) => {
      try {
        return readFileSync(join(FIXTURE_DIR, tilt), 'latin1');
      } catch {
        return undefined;
      }
    },
  });
}

/** Deterministic PRNG (mulberry32: the fuzzers' createRng) for the fuzz and sampling tests. */
export function rng(seed: number): () => number {
  return createRng(seed).next;
}
