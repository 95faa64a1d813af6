import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import type { Mat3 } from './luminaireRotation';
import { applyMat3 } from './luminaireRotation';
import type { SurfaceLayout } from './surfaceLayout';

/**
 * Can a luminaire light this surface at all? It must sit in front of the
 * surface, and its non-zero band of vertical angles [γmin, γmax] must meet
 * the hemisphere of directions toward the surface. With θ the angle between
 * the luminaire's nadir and the direction toward the wall, that hemisphere
 * holds γ ∈ (θ − 90°, θ + 90°). Conservative (ignores C), so it never drops
 * light; it spares the direct pass e.g. the ceiling above a pure downlight.
 */
export function lampReachesSurface(worldSources: Vec3[], rotation: Mat3, gammaMin: number, gammaMax: number, surface: SurfaceLayout): boolean {
  const n = surface.normalAxisIndex;
  const inFront = worldSources.some((p) => (p[n] - surface.origin[n]) * surface.normal[n] > 1e-9);
  if (!inFront) return false;
  const nadir = applyMat3(rotation, [0, -1, 0]);
  const toward = -surface.normal[n];
  const cosTheta = Math.max(-1, Math.min(1, nadir[n] * toward));
  const theta = (Math.acos(cosTheta) * 180) / Math.PI;
  const margin = 1e-3;
  return gammaMax > theta - 90 - margin && gammaMin < theta + 90 + margin;
}
