import { describe, expect, it } from 'vitest';
import { beamAndField, integrateFlux, peakIntensity, type Photometry } from '../../../src/core/photometry';
import { loadReal } from './helpers';

/** A synthetic rotationally symmetric photometry I(γ) on a 0.1° grid. */
function synthetic(f: (g: number) => number, planes: number[] = [0]): Photometry {
  const verticalAngles = Array.from({ length: 1801 }, (_, i) => i / 10);
  return {
    format: 'IES',
    version: 'LM-63-2002',
    manufacturer: '',
    luminaire: '',
    catalogNumber: '',
    keywords: {},
    photometricType: 'C',
    symmetry: planes.length === 1 ? 'rotational' : 'none',
    verticalAngles,
    horizontalAngles: planes,
    candela: planes.map((c) => verticalAngles.map((g) => f(g) * (planes.length === 1 ? 1 : 1 + 0 * c))),
    statedLumens: null,
    absolute: true,
    inputWatts: null,
    luminousOpening: { width: 0, length: 0, height: 0, shape: 'point' },
    warnings: [],
  };
}

describe('beam and field angles', () => {
  it('cos^10 γ: beam = 2·acos(0.5^0.1), field = 2·acos(0.1^0.1) within 0.05°', () => {
    const ph = synthetic((g) => Math.max(0, Math.cos((g * Math.PI) / 180)) ** 10);
    const expectedBeam = (2 * Math.acos(0.5 ** 0.1) * 180) / Math.PI; // 42.0°
    const expectedField = (2 * Math.acos(0.1 ** 0.1) * 180) / Math.PI; // 75.2°
    const { c0, c90 } = beamAndField(ph);
    for (const p of [c0, c90]) {
      expect(Math.abs(p.beam - expectedBeam)).toBeLessThan(0.05);
      expect(Math.abs(p.field - expectedField)).toBeLessThan(0.05);
    }
    // Flux of cos^m over the lower hemisphere is 2π/(m+1).
    expect(integrateFlux(ph) / ((2 * Math.PI) / 11)).toBeCloseTo(1, 4);
  });

  it('an isotropic source has 360° beam and field; a dark one 0°', () => {
    expect(beamAndField(synthetic(() => 5)).c0).toEqual({ beam: 360, field: 360 });
    expect(beamAndField(synthetic(() => 0)).c90).toEqual({ beam: 0, field: 0 });
  });

  it('an off-axis peak (γ = 60° in C0, a wash distribution) is measured around the peak', () => {
    // Gaussian in θ around +60° on the C0 side: half-max at ±σ√(2 ln 2).
    const sigma = 8;
    const ph = synthetic((g) => Math.exp(-((g - 60) ** 2) / (2 * sigma * sigma)), [0, 180, 360]);
    // Make C180 dark so only the C0 half carries light.
    ph.candela[1] = ph.candela[1].map(() => 0);
    const beam = beamAndField(ph).c0.beam;
    expect(Math.abs(beam - 2 * sigma * Math.sqrt(2 * Math.LN2))).toBeLessThan(0.1);
  });

  it('BEGA 84693 narrow spot: peak 39 295.9 cd at nadir, half maximum at about 5° (SOURCES.md)', () => {
    const ph = loadReal('bega_84693_narrow_spot.ies');
    expect(peakIntensity(ph)).toEqual({ candela: 39295.9, gamma: 0, c: 0 });
    const { c0 } = beamAndField(ph);
    expect(c0.beam).toBeGreaterThan(9.5);
    expect(c0.beam).toBeLessThan(10.5);
  });
});
