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
