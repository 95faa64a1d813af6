import { readFileSync } from 'node:fs';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { intensity, parsePhotometry, PhotometryParseError } from '../../../src/core/photometry';
import { fixtureFiles, loadFixture, loadReal, realFiles, rng } from './helpers';

describe('intensity is finite and ≥ 0 everywhere (property, seeded)', () => {
  const all = [...fixtureFiles().map((f) => ({ f, ph: loadFixture(f) })), ...realFiles().map((f) => ({ f, ph: loadReal(f) }))];
  it(`holds on all ${all.length} fixtures and shared files`, () => {
    for (const { ph } of all) {
      fc.assert(
        fc.property(fc.double({ min: -1e4, max: 1e4, noNaN: true }), fc.double({ min: -1e4, max: 1e4, noNaN: true }), (g, c) => {
          const v = intensity(ph, g, c);
          return Number.isFinite(v) && v >= 0;
        }),
        { seed: 20240607, numRuns: 200 },
      );
    }
  });
});

/** One random byte-level mutation: flip, insert, delete, duplicate a span, or truncate. */
function mutate(bytes: Uint8Array, next: () => number): Uint8Array {
  const out = Array.from(bytes);
  const edits = 1 + Math.floor(next() * 4);
  for (let e = 0; e < edits; e++) {
    const at = Math.floor(next() * out.length);
    const kind = Math.floor(next() * 6);
    if (kind === 0) out[at] = Math.floor(next() * 256);
    else if (kind === 1) out.splice(at, 0, [0x20, 0x0a, 0x2d, 0x2c, 0x2e, 0x30 + Math.floor(next() * 10), 0x1a, 0x00][Math.floor(next() * 8)]);
    else if (kind === 2) out.splice(at, 1 + Math.floor(next() * 20));
    else if (kind === 3) {
      const len = 1 + Math.floor(next() * 200);
      out.splice(at, 0, ...out.slice(at, at + len));
    } else if (kind === 4) out.length = at;
    else out[at] = [0x39, 0x2d, 0x65, 0x2e, 0x4e][Math.floor(next() * 5)]; // '9' '-' 'e' '.' 'N'
  }
  return Uint8Array.from(out);
}

describe('fuzz: mutated real files only ever throw PhotometryParseError', () => {
  // A subset covering IES 1986/1991/1995/2002, type B, and EULUMDAT; 300 mutations each.
  const subset = [
    'erco_double_focus_lm1986_ctrlz.ies',
    'lithonia_esg_comma_separated_iesna91.ies',
    'bega_84659_flood_h90_270.ies',
    'rab_pipxl70_flood_type_b_feet.ies',
    'zumtobel_sloin_linear_isym4.ldt',
    'ledvance_floodlight_1200w_sym10_crlf.ldt',
  ];
  for (const file of subset) {
    it(file, () => {
      const original = readFileSync(`public/ies/${file}`);
      const next = rng(file.length * 7919);
      let parsed = 0;
      let rejected = 0;
      for (let i = 0; i < 300; i++) {
        const bytes = mutate(original, next);
        try {
          const ph = parsePhotometry(bytes, file);
          parsed++;
          // A successful parse is a valid model.
          for (const row of ph.candela) for (const cd of row) if (!(Number.isFinite(cd) && cd >= 0)) throw new Error(`bad cd ${cd}`);
        } catch (error) {
          if (!(error instanceof PhotometryParseError)) throw error;
          rejected++;
        }
      }
      expect(parsed + rejected).toBe(300);
      // Both outcomes occur: the fuzzer is neither all-fatal nor all-harmless.
      expect(rejected).toBeGreaterThan(0);
    });
  }
});
