import type { Photometry } from './types';

const DEG = Math.PI / 180;

/**
 * Total luminous flux in lm: Φ = ∫∫ I(γ, C) sin γ dγ dC over the sphere,
 * integrated *exactly* for the interpolant that intensity() uses (bilinear in
 * γ and C), so flux and lookups agree:
 *  - in C, I is linear between planes, so each C interval contributes
 *    ΔC · (I_left + I_right) / 2 (the trapezoid rule is exact);
 *  - in γ, I is linear on [γ0, γ1]; with t = (γ − γ0)/Δγ,
 *    ∫ (1 − t) sin γ dγ = (cos γ0 − cos γ1) − w1 and
 *    ∫ t sin γ dγ = w1 = (sin γ1 − sin γ0)/Δγ − cos γ1.
 * An isotropic source (I constant) gives 2π · Σ (cos γ0 − cos γ1) = 4π I
 * up to rounding.
 */
export function integrateFlux(ph: Photometry): number {
  const v = ph.verticalAngles;
  // Per-row weights: ∫ (hat function of row j) sin γ dγ.
  const weights = new Array<number>(v.length).fill(0);
  for (let j = 0; j + 1 < v.length; j++) {
    const g0 = v[j] * DEG;
    const g1 = v[j + 1] * DEG;
    const dg = g1 - g0;
    // cos γ0 − cos γ1 written without cancellation.
    const whole = 2 * Math.sin((g0 + g1) / 2) * Math.sin(dg / 2);
    // For very narrow cells the closed form cancels badly; Simpson's rule on
    // the smooth integrands is then exact to far below float precision.
    const w1 = dg < 1e-3 ? (dg / 6) * (0 + 4 * 0.5 * Math.sin((g0 + g1) / 2) + Math.sin(g1)) : (Math.sin(g1) - Math.sin(g0)) / dg - Math.cos(g1);
    weights[j] += whole - w1;
    weights[j + 1] += w1;
  }
  const planeFlux = (row: number[]): number => row.reduce((sum, cd, j) => sum + cd * weights[j], 0);
  const h = ph.horizontalAngles;
  if (h.length === 1) return 2 * Math.PI * planeFlux(ph.candela[0]);
  let total = 0;
  for (let i = 0; i + 1 < h.length; i++) {
    const dc = (h[i + 1] - h[i]) * DEG;
    total += (dc * (planeFlux(ph.candela[i]) + planeFlux(ph.candela[i + 1]))) / 2;
  }
  return total;
}
