import { describe, expect, it } from 'vitest';
import { clearGlassTransmittance, diffuseTransmittance, GLAZING_PRESETS, glazingFrom, glazingTransmittance } from '../../../src/core/daylight/glazing';

describe('glazing', () => {
  it('has Fresnel reflection of glass n = 1.526 as Duffie & Beckman example 5.1.1 gives it', () => {
    // Normal incidence: r = ((n − 1)/(n + 1))² = 0.0434; one pane transmits (1 − r)/(1 + r).
    const r = (0.526 / 2.526) ** 2;
    expect(clearGlassTransmittance(1, 1)).toBeCloseTo((1 - r) / (1 + r), 12);
    expect(clearGlassTransmittance(1, 2)).toBeCloseTo((1 - r) / (1 + 3 * r), 12);
    // At 60°: r⊥ = 0.185, r∥ = 0.0014 (the textbook's values), so τ₁ = ½ (0.9972 + 0.6872).
    const rPerp = 0.185;
    const rPar = 0.0014;
    expect(clearGlassTransmittance(0.5, 1)).toBeCloseTo(0.5 * ((1 - rPar) / (1 + rPar) + (1 - rPerp) / (1 + rPerp)), 3);
    expect(clearGlassTransmittance(0, 1)).toBe(0);
  });

  it('scales the clear-glass shape to the presets and keeps an open window at 1', () => {
    for (const [name, preset] of Object.entries(GLAZING_PRESETS)) {
      const g = glazingFrom(name as keyof typeof GLAZING_PRESETS);
      expect(glazingTransmittance(g, 1)).toBeCloseTo(preset.normalTransmittance, 12);
      let last = Infinity;
      for (let c = 1; c >= 0; c -= 0.05) {
        const t = glazingTransmittance(g, c);
        expect(t).toBeLessThanOrEqual(last + 1e-12);
        last = t;
      }
      // Flat to about 40° (within 1.5 %), then falling: the shape of clear glass.
      expect(glazingTransmittance(g, Math.cos((40 * Math.PI) / 180)) / preset.normalTransmittance).toBeGreaterThan(0.985);
      expect(glazingTransmittance(g, Math.cos((80 * Math.PI) / 180)) / preset.normalTransmittance).toBeLessThan(0.75);
    }
    const open = glazingFrom(1);
    expect(glazingTransmittance(open, 0.01)).toBe(1);
    expect(diffuseTransmittance(open)).toBeCloseTo(1, 9);
    expect(glazingTransmittance(glazingFrom(0.5), 1)).toBeCloseTo(0.5, 12);
    expect(glazingTransmittance(glazingFrom('double', 0.2), 1)).toBeCloseTo(0.6, 12);
    // Diffuse transmittance of single glass: about 0.9 of the normal value (Duffie & Beckman: τ at 60° equivalent incidence).
    const d = diffuseTransmittance(glazingFrom('single')) / 0.85;
    expect(d).toBeGreaterThan(0.86);
    expect(d).toBeLessThan(0.94);
    expect(Math.abs(d - glazingTransmittance(glazingFrom('single'), 0.5) / 0.85)).toBeLessThan(0.02);
  });
});
