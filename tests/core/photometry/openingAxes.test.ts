import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { intensity, parsePhotometry } from '../../../src/core/photometry';

const load = (file: string) => parsePhotometry(readFileSync(`public/ies/${file}`), file);

/**
 * Photometry.luminousOpening keeps EULUMDAT's names: width along C0–C180 (local x), length along
 * C90–C270 (local z). LM-63 calls the side along 0°–180° the length, so IES files swap on reading
 * (parseIes.ts, iesOpeningInLuminaireFrame; docs/photometry.md).
 */
describe('the luminous opening lies the same way as the distribution', () => {
  it("LM-63's own example (Ledalite 251602SN): the 4 ft lamps lie along C0, so the 4.04 ft side is along local x", () => {
    const ph = load('ledalite_pendant_direct_indirect_iesna95.ies');
    expect(ph.keywords.ALGN).toMatch(/0 degree plane parallel to lamps/);
    expect(ph.luminousOpening.width).toBeCloseTo(4.04 * 0.3048, 9);
    expect(ph.luminousOpening.length).toBeCloseTo(0.85 * 0.3048, 9);
    // Across the lamps (C90) the louvred pendant throws its batwing; along them (C0) it cuts off.
    expect(intensity(ph, 30, 90)).toBeGreaterThan(1.5 * intensity(ph, 30, 0));
  });

  it("ERCO's Trion washlight in both formats gives one opening: 138 mm along C0, 155 mm along C90", () => {
    const ies = load('erco_trion_ceiling_washlight_uplight.ies');
    const ldt = load('erco_trion_ceiling_washlight_uplight.ldt');
    for (const ph of [ies, ldt]) {
      expect(ph.luminousOpening.width).toBeCloseTo(0.138, 9);
      expect(ph.luminousOpening.length).toBeCloseTo(0.155, 9);
    }
  });
});
