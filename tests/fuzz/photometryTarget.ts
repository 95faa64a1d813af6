import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { beamAndField, integrateFlux, intensity, parsePhotometry, PhotometryParseError, photometryWarnings, type Photometry } from '../../src/core/photometry';
import type { FuzzOutcome, FuzzSeed, FuzzTarget } from './fuzzTarget';

/**
 * Fuzz target for the photometry parsers (issue 18): `parsePhotometry`, the
 * entry the CLI, the baker's scene loader, the planner and the viewer all use.
 * Input arrives without a file name, so the format is sniffed from the
 * content exactly as parsePhotometry does for a name without extension.
 *
 * The checks on an accepted model are deliberately independent of the
 * parser's own (documented ranges in docs/photometry.md, "Ranges").
 */

// Resolved from this file, so the runner may start from any directory.
const dir = (relative: string): string => fileURLToPath(new URL(relative, import.meta.url));
const REAL_DIR = dir('../../public/ies');
const FIXTURE_DIR = dir('../fixtures/photometry');
const REGRESSION_DIR = dir('../fixtures/photometry/fuzz-regressions');

export const PHOTOMETRY_RANGES = {
  maxCandela: 1e9,
  minLumens: 1e-3,
  maxLumens: 1e7,
  maxDimensionM: 1000,
  maxMessageLength: 200,
} as const;

const isPhotometric = (f: string): boolean => /\.(ies|ldt)$/i.test(f);

/** The shared real files and the hand-written fixtures (not the refused ones in bad/). */
export function photometrySeeds(): FuzzSeed[] {
  const seeds: FuzzSeed[] = [];
  for (const dir of [REAL_DIR, FIXTURE_DIR]) {
    for (const name of readdirSync(dir).filter(isPhotometric).sort()) {
      seeds.push({ name, bytes: new Uint8Array(readFileSync(join(dir, name))) });
    }
  }
  return seeds;
}

/** Every input that once failed (tests/fixtures/photometry/fuzz-regressions). */
export function photometryRegressions(): FuzzSeed[] {
  return readdirSync(REGRESSION_DIR)
    .filter((f) => !f.endsWith('.md'))
    .sort()
    .map((name) => ({ name, bytes: new Uint8Array(readFileSync(join(REGRESSION_DIR, name))) }));
}

// TILT=<file>: any name resolves to the fixture tilt table, so the path is exercised.
let tiltText: string | undefined;
const resolveTilt = (): string => (tiltText ??= readFileSync(join(FIXTURE_DIR, 'lamp_tilt.tlt'), 'latin1'));

const finite = (x: unknown): x is number => typeof x === 'number' && Number.isFinite(x);

function oneLineProblem(kind: string, text: string): string | null {
  if (text.includes('\n') || text.includes('\r')) return `${kind} spans several lines`;
  if (text.length > PHOTOMETRY_RANGES.maxMessageLength) return `${kind} is ${text.length} characters long`;
  return null;
}

/**
 * What is wrong with an accepted model ([] when it is valid). `deep` adds the
 * beam/field walk (~10 ms; finite by construction once every grid value is).
 */
export function photometryProblems(ph: Photometry, deep = false): string[] {
  const problems: string[] = [];
  const add = (p: string): void => {
    if (problems.length < 10) problems.push(p);
  };
  const { maxCandela, minLumens, maxLumens, maxDimensionM } = PHOTOMETRY_RANGES;
  const v = ph.verticalAngles;
  const h = ph.horizontalAngles;
  if (v.length < 2 || v[0] !== 0 || v[v.length - 1] !== 180) add(`vertical angles span ${v[0]}..${v[v.length - 1]}, not 0..180`);
  for (let i = 1; i < v.length; i++) if (!(v[i] > v[i - 1])) add(`vertical angle ${i} (${v[i]}) does not ascend`);
  if (!(h.length === 1 ? h[0] === 0 : h[0] === 0 && h[h.length - 1] === 360)) add(`horizontal angles span ${h[0]}..${h[h.length - 1]}`);
  for (let i = 1; i < h.length; i++) if (!(h[i] > h[i - 1])) add(`horizontal angle ${i} (${h[i]}) does not ascend`);
  if (ph.candela.length !== h.length) add(`${ph.candela.length} candela planes for ${h.length} horizontal angles`);
  for (const row of ph.candela) {
    if (row.length !== v.length) add(`a candela plane has ${row.length} values for ${v.length} vertical angles`);
    for (const cd of row) if (!(finite(cd) && cd >= 0 && cd <= maxCandela)) add(`candela value ${cd} outside 0..${maxCandela}`);
  }
  const flux = integrateFlux(ph);
  if (!(finite(flux) && flux >= 0 && flux <= maxLumens)) add(`integrated flux ${flux} lm outside 0..${maxLumens}`);
  if (ph.statedLumens !== null && !(finite(ph.statedLumens) && ph.statedLumens >= minLumens && ph.statedLumens <= maxLumens)) {
    add(`stated lumens ${ph.statedLumens} outside ${minLumens}..${maxLumens}`);
  }
  if (ph.candelaScale !== undefined && !(finite(ph.candelaScale) && ph.candelaScale > 0)) add(`candela scale ${ph.candelaScale} is not finite and > 0`);
  if (ph.inputWatts !== null && !(finite(ph.inputWatts) && ph.inputWatts > 0)) add(`input watts ${ph.inputWatts}`);
  const o = ph.luminousOpening;
  for (const [k, x] of [
    ['width', o.width],
    ['length', o.length],
    ['height', o.height],
  ] as const) {
    if (!(finite(x) && x >= 0 && x <= maxDimensionM)) add(`luminous opening ${k} ${x} m outside 0..${maxDimensionM}`);
  }
  if (ph.tilt) {
    const { angles, factors } = ph.tilt;
    if (angles.length !== factors.length || angles.length === 0) add(`TILT table of ${angles.length} angles and ${factors.length} factors`);
    for (const f of factors) if (!(finite(f) && f >= 0)) add(`TILT factor ${f}`);
    for (const a of angles) if (!finite(a)) add(`TILT angle ${a}`);
  }
  for (const w of photometryWarnings(ph)) {
    const p = oneLineProblem('a warning', w);
    if (p) add(p);
  }
  // Lookups and beam figures, as the renderer and `ies info` use them.
  for (const [g, c] of [
    [0, 0],
    [37, 123],
    [90, 271],
    [180, 359.9],
  ]) {
    const i = intensity(ph, g, c);
    if (!(finite(i) && i >= 0 && i <= maxCandela)) add(`intensity(${g}, ${c}) = ${i}`);
  }
  if (deep) {
    const bf = beamAndField(ph);
    for (const x of [bf.c0.beam, bf.c0.field, bf.c90.beam, bf.c90.field]) if (!(finite(x) && x >= 0 && x <= 360)) add(`beam/field angle ${x}`);
  }
  return problems;
}

export const photometryFuzzTarget: FuzzTarget = {
  name: 'photometry',
  seeds: photometrySeeds,
  run(input: Uint8Array): FuzzOutcome {
    let ph: Photometry;
    try {
      ph = parsePhotometry(input, 'input', { resolveTilt });
    } catch (error) {
      if (error instanceof PhotometryParseError) return { kind: 'refused', message: error.message };
      throw error;
    }
    return { kind: 'accepted', problems: photometryProblems(ph) };
  },
};
