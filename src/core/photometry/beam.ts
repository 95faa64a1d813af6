import { intensity } from './intensity';
import type { Photometry } from './types';

export interface BeamField {
  /** Full angle (degrees) between the 50 % points around the peak of the plane pair. */
  beam: number;
  /** Full angle (degrees) between the 10 % points. */
  field: number;
}

/** Step of the walk along a plane pair; crossings are interpolated linearly between steps. */
const STEP = 0.05;

/**
 * Beam (50 %) and field (10 %) angles in the C0–C180 and C90–C270 plane pairs
 * (IES/CIE definition: the angle between the two directions in the plane where
 * the intensity falls to that fraction of the plane's maximum). Each plane pair
 * is a great circle, parametrised by θ ∈ (−180, 180]: θ ≥ 0 is γ = θ in C0 (or
 * C90), θ < 0 is γ = −θ in C180 (C270). From the peak we walk both ways to the
 * first crossing; an off-axis peak (a wall washer) is handled the same way. If
 * the intensity never falls that low (an isotropic source), the angle is 360.
 */
export function beamAndField(ph: Photometry): { c0: BeamField; c90: BeamField } {
  return { c0: planePair(ph, 0), c90: planePair(ph, 90) };
}

function planePair(ph: Photometry, c: number): BeamField {
  const n = Math.round(360 / STEP);
  const samples = new Float64Array(n);
  let peak = 0;
  let peakIndex = 0;
  for (let k = 0; k < n; k++) {
    // θ = −180 + k·STEP; intensity() reflects negative γ into C + 180.
    samples[k] = intensity(ph, -180 + k * STEP, c);
    if (samples[k] > peak) {
      peak = samples[k];
      peakIndex = k;
    }
  }
  if (peak <= 0) return { beam: 0, field: 0 };
  return { beam: spread(samples, peakIndex, 0.5 * peak), field: spread(samples, peakIndex, 0.1 * peak) };
}

/** Angular distance between the first crossings below `level` on both sides of the peak. */
function spread(samples: Float64Array, peakIndex: number, level: number): number {
  const n = samples.length;
  const at = (k: number): number => samples[((k % n) + n) % n];
  const walk = (dir: 1 | -1): number | null => {
    for (let s = 1; s < n; s++) {
      const a = at(peakIndex + dir * (s - 1));
      const b = at(peakIndex + dir * s);
      if (b < level) return (s - 1 + (a - level) / (a - b)) * STEP;
    }
    return null;
  };
  const right = walk(1);
  const left = walk(-1);
  if (right === null || left === null) return 360;
  return Math.min(360, right + left);
}

/** The largest candela value in the grid and its direction (γ, C in degrees). */
export function peakIntensity(ph: Photometry): { candela: number; gamma: number; c: number } {
  let best = { candela: 0, gamma: 0, c: 0 };
  ph.candela.forEach((row, i) => {
    // The 360 plane repeats the 0 plane; report 0.
    if (i === ph.horizontalAngles.length - 1 && i > 0) return;
    row.forEach((cd, j) => {
      if (cd > best.candela) best = { candela: cd, gamma: ph.verticalAngles[j], c: ph.horizontalAngles[i] };
    });
  });
  return best;
}
