import type { Photometry } from '../../../core/photometry/types';
import { integrateFlux } from '../../../core/photometry/flux';

/**
 * Luminous flux into the lower (γ < 90°, local −y) and upper hemispheres, lm: integrateFlux (the
 * exact integral of the interpolant the baker samples) of the grid with the rows above 90° set to 0,
 * and the rest. The cell straddling 90° counts to the lower side as far as its lower row carries it.
 */
export function hemisphereFlux(ph: Photometry): { down: number; up: number } {
  const total = integrateFlux(ph);
  const lower = integrateFlux({ ...ph, candela: ph.candela.map((row) => row.map((cd, j) => (ph.verticalAngles[j] <= 90 ? cd : 0))) });
  const down = Math.min(total, Math.max(0, lower));
  return { down, up: Math.max(0, total - down) };
}

/**
 * Mean luminance of a Lambertian-equivalent emitter (cd/m²): L = Φ / (π · A) per face, A the face's
 * area (the luminous opening, docs/viewer.md "Luminaires"). By Lambert's cosine law a uniformly
 * diffuse flat source of luminance L and area A emits Φ = M·A = π·L·A into its hemisphere (the
 * exitance M = π·L of a Lambertian surface; DiLaura, Houser, Mistrick, Steffy, *The Lighting
 * Handbook*, 10th ed., IES 2011), so this is the luminance a diffuse opening of that size needs
 * to send out the measured flux. Zero area or flux gives 0, never NaN.
 */
export function emitterLuminance(flux: { down: number; up: number }, area: number): { down: number; up: number } {
  if (!(area > 0) || !Number.isFinite(area)) return { down: 0, up: 0 };
  const l = (phi: number) => (phi > 0 && Number.isFinite(phi) ? phi / (Math.PI * area) : 0);
  return { down: l(flux.down), up: l(flux.up) };
}
