import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { integrateFlux, intensity } from '../../../src/core/photometry';
import { loadReal, realFiles } from './helpers';

/**
 * Expected integrated/stated lumens per shared file, with the reason for each
 * tolerance (also tabulated in docs/photometry.md).
 *  - 'luminaire' files state the luminaire's own output (absolute photometry
 *    with [_ABSOLUTELUMENS] or "NNN lm" in [LAMP], or EULUMDAT lamp flux ×
 *    LORL): the ratio must be 1; ±1 % allows the manufacturer's rounding of
 *    the stated value and of the candela table (observed ≤ 0.3 %); ±2 % for a
 *    type-B file, which is also resampled onto the type-C grid.
 *  - 'lor' files are relative photometry whose header or companion file states
 *    the light output ratio: integrated = LOR × lamp lumens, ±1 %.
 *  - 'relative' files state only lamp lumens: integrated = LOR × lamp lumens
 *    with an unstated LOR, so the ratio must lie in (0.2, 1] — no real
 *    luminaire emits more than its lamps, and none of these is below 20 %.
 *  - 'none': absolute photometry with no stated value; only the independent
 *    quadrature check below applies.
 */
type Expectation = { kind: 'luminaire'; tol: number } | { kind: 'lor'; lor: number; tol: number } | { kind: 'relative' } | { kind: 'none' };
const EXPECTED: Record<string, Expectation> = {
  'aec_italo_streetlight_full360.ies': { kind: 'none' },
  'ael_asa_roadway_type2_bilateral.ies': { kind: 'relative' },
  'bega_50899_asym_h0_345.ies': { kind: 'luminaire', tol: 0.01 },
  'bega_50975_downlight_lm1995_crlf.ies': { kind: 'luminaire', tol: 0.01 },
  'bega_6340_wall_up_down_long_lines.ies': { kind: 'relative' },
  'bega_84659_flood_h90_270.ies': { kind: 'luminaire', tol: 0.01 },
  'bega_84693_narrow_spot.ies': { kind: 'luminaire', tol: 0.01 },
  'collingwood_gl200_ground_uplight.ies': { kind: 'none' },
  'cooper_shaper_ceiling_one_value_per_line.ies': { kind: 'relative' },
  'efficient_dt106_track_spot_utf8.ies': { kind: 'none' },
  // Header line 7: "light output ratio: 0.5912".
  'erco_double_focus_lm1986_ctrlz.ies': { kind: 'lor', lor: 0.5912, tol: 0.01 },
  'erco_kubus_floor_washlight.ies': { kind: 'relative' },
  'erco_mr16_lm1986_latin1.ies': { kind: 'relative' },
  // Converted from ERCO's LDT, whose LORL is 41.0 %.
  'erco_trion_ceiling_washlight_uplight.ies': { kind: 'lor', lor: 0.41, tol: 0.01 },
  'erco_trion_ceiling_washlight_uplight.ldt': { kind: 'luminaire', tol: 0.01 },
  'hewilliams_bollard_nonuniform_v.ies': { kind: 'relative' },
  'infinity_minican_narrow_leading_space.ies': { kind: 'relative' },
  'interlight_ovni_highbay_latin1_361v.ies': { kind: 'luminaire', tol: 0.01 },
  'ledalite_pendant_direct_indirect_iesna95.ies': { kind: 'relative' },
  'ledvance_floodlight_1200w_sym10_crlf.ldt': { kind: 'luminaire', tol: 0.01 },
  'lithonia_esg_comma_separated_iesna91.ies': { kind: 'relative' },
  'rab_bayled78_highbay_nbsp_latin1.ies': { kind: 'luminaire', tol: 0.01 },
  'rab_boa2_linear_quadrant.ies': { kind: 'luminaire', tol: 0.01 },
  'rab_ffledl_flood_type_b_metres.ies': { kind: 'none' },
  'rab_halvs10_wall_sconce_199v.ies': { kind: 'luminaire', tol: 0.01 },
  'rab_pipxl70_flood_type_b_feet.ies': { kind: 'luminaire', tol: 0.02 },
  'zumtobel_arcos3_spot_isym1.ldt': { kind: 'luminaire', tol: 0.01 },
  'zumtobel_intro_isym0.ldt': { kind: 'luminaire', tol: 0.01 },
  'zumtobel_linetik_s_direct_indirect.ldt': { kind: 'luminaire', tol: 0.01 },
  'zumtobel_sloin_linear_isym4.ldt': { kind: 'luminaire', tol: 0.01 },
};

/** Independent flux: midpoint rule in (cos γ, C) on a 1440 × 720 grid, via intensity(). */
function quadratureFlux(ph: Parameters<typeof intensity>[0]): number {
  const nMu = 1440;
  const nC = ph.horizontalAngles.length === 1 ? 1 : 720;
  let sum = 0;
  for (let i = 0; i < nMu; i++) {
    const mu = -1 + (2 * (i + 0.5)) / nMu; // cos γ, γ from the nadir
    const gamma = (Math.acos(-mu) * 180) / Math.PI;
    for (let k = 0; k < nC; k++) sum += intensity(ph, gamma, ((k + 0.5) * 360) / nC);
  }
  return (sum * (2 / nMu) * (2 * Math.PI)) / nC;
}

describe('shared photometric files', () => {
  const files = realFiles();
  it('covers every shared file with an expectation', () => {
    expect(files.length).toBe(30);
    expect(Object.keys(EXPECTED).sort()).toEqual(files);
  });

  const ratios: string[] = [];
  for (const file of files) {
    it(`${file} parses into a valid expanded grid and its lumens agree`, () => {
      const ph = loadReal(file);
      const v = ph.verticalAngles;
      const h = ph.horizontalAngles;
      expect(v[0]).toBe(0);
      expect(v[v.length - 1]).toBe(180);
      for (let i = 1; i < v.length; i++) expect(v[i]).toBeGreaterThan(v[i - 1]);
      if (h.length > 1) {
        expect(h[0]).toBe(0);
        expect(h[h.length - 1]).toBe(360);
        expect(ph.candela[h.length - 1]).toEqual(ph.candela[0]);
      } else expect(h).toEqual([0]);
      expect(ph.candela.length).toBe(h.length);
      for (const row of ph.candela) {
        expect(row.length).toBe(v.length);
        for (const cd of row) expect(Number.isFinite(cd) && cd >= 0).toBe(true);
      }

      const flux = integrateFlux(ph);
      // The exact integral of the interpolant and an independent midpoint
      // quadrature of the same interpolant agree to 0.2 % (quadrature error).
      expect(Math.abs(quadratureFlux(ph) / flux - 1)).toBeLessThan(0.002);

      const e = EXPECTED[file];
      const ratio = ph.statedLumens ? flux / ph.statedLumens : NaN;
      if (e.kind === 'luminaire') expect(Math.abs(ratio - 1)).toBeLessThanOrEqual(e.tol);
      else if (e.kind === 'lor') expect(Math.abs(ratio / e.lor - 1)).toBeLessThanOrEqual(e.tol);
      else if (e.kind === 'relative') {
        expect(ratio).toBeGreaterThan(0.2);
        expect(ratio).toBeLessThanOrEqual(1);
      } else expect(flux).toBeGreaterThan(0);
      ratios.push(`${file}: ${ratio.toFixed(4)}`);
    });
  }

  it('type-B files: the converted grid keeps the flux of the file’s own (H, V) grid', () => {
    // Independent reference: trapezoid rule in the type-B frame, dΩ = cos H dH dV,
    // on the raw numbers of the file (no conversion involved).
    for (const [file, mirrorH] of [
      ['rab_ffledl_flood_type_b_metres.ies', false],
      ['rab_pipxl70_flood_type_b_feet.ies', true],
    ] as const) {
      const text = readFileSync(`public/ies/${file}`, 'latin1');
      const nums = text
        .slice(text.indexOf('TILT=NONE') + 9)
        .trim()
        .split(/\s+/)
        .map(Number);
      const [, , mult, nV, nH] = nums;
      const ballast = nums[10];
      const vs = nums.slice(13, 13 + nV);
      const hs = nums.slice(13 + nV, 13 + nV + nH);
      const cd = (i: number, j: number): number => nums[13 + nV + nH + i * nV + j] * mult * ballast;
      const r = Math.PI / 180;
      let ref = 0;
      for (let i = 0; i + 1 < nH; i++) {
        for (let j = 0; j + 1 < nV; j++) {
          const avg = (cd(i, j) + cd(i + 1, j) + cd(i, j + 1) + cd(i + 1, j + 1)) / 4;
          ref += avg * (Math.sin(hs[i + 1] * r) - Math.sin(hs[i] * r)) * (vs[j + 1] - vs[j]) * r;
        }
      }
      if (mirrorH) ref *= 2;
      expect(Math.abs(integrateFlux(loadReal(file)) / ref - 1)).toBeLessThan(0.02);
    }
  });
});
