/**
 * Glazing of a window: its normal-incidence visible transmittance τ_n (presets for clear single,
 * double and triple glazing, or a number), how that falls off at oblique incidence, and the frame.
 *
 * Angular dependence: clear uncoated glass of refractive index n = 1.526, N panes, absorption
 * neglected, with the multiple reflections between the surfaces summed (Fresnel's equations;
 * Duffie & Beckman, Solar Engineering of Thermal Processes, 4th ed. 2013, eqs. 5.1.1–5.1.8):
 *
 *   r⊥ = sin²(θ₂ − θ₁) / sin²(θ₂ + θ₁),   r∥ = tan²(θ₂ − θ₁) / tan²(θ₂ + θ₁),   sin θ₂ = sin θ₁ / n
 *   τ_N(θ₁) = ½ [ (1 − r∥) / (1 + (2N − 1) r∥) + (1 − r⊥) / (1 + (2N − 1) r⊥) ]
 *
 * and the glazing's transmittance τ(θ) = τ_n · τ_N(θ) / τ_N(0): the shape of clear glass scaled to
 * the given normal value (absorption and coatings change τ_n far more than the shape). An open
 * window (τ_n = 1, no panes) transmits everything at every angle. A number other than a preset
 * takes the single pane's shape.
 *
 * Frame: a fraction of the opening's area that is opaque (0 … < 1, default 0: the opening is all
 * glass); it scales the transmitted light uniformly, i.e. the frame is smeared over the opening
 * rather than drawn (its shadow lines are not modelled).
 */

export const GLASS_REFRACTIVE_INDEX = 1.526;

export const GLAZING_PRESETS = {
  single: { normalTransmittance: 0.85, panes: 1 },
  double: { normalTransmittance: 0.75, panes: 2 },
  triple: { normalTransmittance: 0.6, panes: 3 },
} as const;

export type GlazingPreset = keyof typeof GLAZING_PRESETS;

export interface Glazing {
  /** Visible transmittance at normal incidence, 0 … 1 (1 with panes 0: an open hole). */
  normalTransmittance: number;
  /** Panes of clear glass that give the angular shape; 0 = no glass. */
  panes: 0 | 1 | 2 | 3;
  /** Opaque share of the opening (frame and bars), 0 … < 1. */
  frameFraction: number;
}

export const OPEN_OPENING: Glazing = { normalTransmittance: 1, panes: 0, frameFraction: 0 };

/** Glazing from a preset name or a normal-incidence number (1 = open), with an optional frame fraction. */
export function glazingFrom(value: GlazingPreset | number, frameFraction = 0): Glazing {
  if (typeof value === 'string') return { ...GLAZING_PRESETS[value], frameFraction };
  if (value === 1) return { ...OPEN_OPENING, frameFraction };
  return { normalTransmittance: value, panes: 1, frameFraction };
}

/** Fresnel transmittance of N clear panes (no absorption) at incidence cos θ₁ (Duffie & Beckman 5.1.8). */
export function clearGlassTransmittance(cosIncidence: number, panes: number, n = GLASS_REFRACTIVE_INDEX): number {
  const c = Math.min(1, Math.abs(cosIncidence));
  const k = 2 * panes - 1;
  if (c >= 1 - 1e-12) {
    const r = ((n - 1) / (n + 1)) ** 2;
    return (1 - r) / (1 + k * r);
  }
  if (c <= 0) return 0;
  const t1 = Math.acos(c);
  const t2 = Math.asin(Math.sin(t1) / n);
  const rPerp = Math.sin(t2 - t1) ** 2 / Math.sin(t2 + t1) ** 2;
  const rPar = Math.tan(t2 - t1) ** 2 / Math.tan(t2 + t1) ** 2;
  return 0.5 * ((1 - rPar) / (1 + k * rPar) + (1 - rPerp) / (1 + k * rPerp));
}

/** τ at incidence cos θ (to the window's normal), frame included. */
export function glazingTransmittance(g: Glazing, cosIncidence: number): number {
  const open = 1 - g.frameFraction;
  if (g.panes === 0) return g.normalTransmittance * open;
  return (g.normalTransmittance * open * clearGlassTransmittance(cosIncidence, g.panes)) / clearGlassTransmittance(1, g.panes);
}

/**
 * Hemispherical-diffuse transmittance of the glazing for a uniform radiance from one side:
 * τ_d = 2 ∫₀¹ τ(μ) μ dμ (composite Simpson on 2000 intervals): what a uniform sky through an
 * unobstructed window sees on average.
 */
export function diffuseTransmittance(g: Glazing): number {
  const n = 2000;
  let sum = 0;
  for (let i = 0; i <= n; i++) {
    const mu = i / n;
    const w = i === 0 || i === n ? 1 : i % 2 === 1 ? 4 : 2;
    sum += w * glazingTransmittance(g, mu) * mu;
  }
  return (2 * sum) / (3 * n);
}
