import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { parsePhotometry } from '../../../src/core/photometry';
import { photometryFuzzTarget, photometryRegressions, PHOTOMETRY_RANGES } from '../../fuzz/photometryTarget';
import { rng } from './helpers';
import { mutate } from './mutate';

/**
 * Bounded, seeded fuzz of the photometry parsers in CI (issue 18). Every real
 * file and fixture is mutated MUTATIONS_PER_SEED times; an input fails when it
 * crashes (anything but PhotometryParseError), is accepted with a non-finite
 * or out-of-range value, is refused with a multi-line or overlong message, or
 * takes more than a second. A failing input is written nowhere by this test:
 * copy it into tests/fixtures/photometry/fuzz-regressions/ when fixing it.
 */
const MUTATIONS_PER_SEED = 45;
/** Type A/B seeds are resampled onto a 361 × 361 grid (~50–150 ms a parse): fewer of them. */
const MUTATIONS_PER_TYPE_AB_SEED = 12;
const SLOW_MS = 1000;
const TILT = readFileSync('tests/fixtures/photometry/lamp_tilt.tlt', 'latin1');

interface Failure {
  seed: string;
  index: number;
  what: string;
}

function check(name: string, index: number, input: Uint8Array, failures: Failure[], counts: Record<string, number>): void {
  const t0 = performance.now();
  let outcome;
  try {
    outcome = photometryFuzzTarget.run(input);
  } catch (error) {
    failures.push({ seed: name, index, what: `crash: ${(error as Error)?.stack?.split('\n').slice(0, 2).join(' ') ?? String(error)}` });
    return;
  }
  const ms = performance.now() - t0;
  if (ms > SLOW_MS) {
    // Timed again before failing: a GC pause or a busy shared core is not a hang, a hang repeats.
    const t1 = performance.now();
    photometryFuzzTarget.run(input);
    const again = performance.now() - t1;
    if (again > SLOW_MS) failures.push({ seed: name, index, what: `slow: ${ms.toFixed(0)} ms, then ${again.toFixed(0)} ms, for ${input.length} bytes` });
  }
  if (outcome.kind === 'accepted') {
    counts.accepted++;
    if (outcome.problems.length) failures.push({ seed: name, index, what: `accepted with problems: ${outcome.problems.join('; ')}` });
  } else {
    counts.refused++;
    const m = outcome.message;
    if (m.includes('\n') || m.includes('\r')) failures.push({ seed: name, index, what: `multi-line message: ${JSON.stringify(m.slice(0, 300))}` });
    if (m.length > PHOTOMETRY_RANGES.maxMessageLength) failures.push({ seed: name, index, what: `message of ${m.length} chars: ${m.slice(0, 120)}…` });
    if (!/^input( line \d+)?: \S/.test(m)) failures.push({ seed: name, index, what: `message does not name file/line: ${m.slice(0, 120)}` });
  }
}

describe('photometry fuzz (seeded, bounded)', () => {
  const seeds = photometryFuzzTarget.seeds();

  it(`every seed parses unmutated with no problems (${seeds.length} seeds)`, () => {
    const failures: Failure[] = [];
    const counts = { accepted: 0, refused: 0 };
    seeds.forEach((s) => check(s.name, -1, s.bytes, failures, counts));
    expect(failures).toEqual([]);
    expect(counts.accepted).toBe(seeds.length);
  });

  it(`${MUTATIONS_PER_SEED} mutations of each seed (${MUTATIONS_PER_TYPE_AB_SEED} of type A/B): no crash, hang, non-finite value or bad message`, () => {
    const failures: Failure[] = [];
    const counts = { accepted: 0, refused: 0 };
    let total = 0;
    seeds.forEach((s, k) => {
      const next = rng(0x18 * 1_000_003 + k * 7919);
      const typeC = parsePhotometry(s.bytes, s.name, { resolveTilt: () => TILT }).photometricType === 'C';
      const n = typeC ? MUTATIONS_PER_SEED : MUTATIONS_PER_TYPE_AB_SEED;
      for (let i = 0; i < n; i++) check(s.name, i, mutate(s.bytes, next), failures, counts);
      total += n;
    });
    expect(total).toBeGreaterThan(2000);
    expect(failures.slice(0, 10)).toEqual([]);
    // Both outcomes occur: the mutations are neither all fatal nor all harmless.
    expect(counts.accepted).toBeGreaterThan(seeds.length);
    expect(counts.refused).toBeGreaterThan(seeds.length);
  }, 120_000);

  it('every input that ever failed (fuzz-regressions/) is now refused cleanly or accepted valid, fast', () => {
    const regressions = photometryRegressions();
    expect(regressions.length).toBeGreaterThan(0);
    const failures: Failure[] = [];
    const counts = { accepted: 0, refused: 0 };
    for (const r of regressions) check(r.name, -1, r.bytes, failures, counts);
    expect(failures).toEqual([]);
  });
});
