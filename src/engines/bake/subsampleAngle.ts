import type { ProfileLayout } from './profileTable';

/**
 * Largest angle (radians) a direct-pass sub-sample cell may subtend from a
 * luminaire: 0.1 rad for smooth distributions (the midpoint rule on I·cosθ/d²
 * is then good to a fraction of a per cent), a quarter of the profile's feature
 * angle for steep ones (a narrow spot's flank), at least 0.5°.
 */
export function subsampleAngle(profile: ProfileLayout): number {
  const feature = (profile.featureAngle * Math.PI) / 180 / 4;
  return Math.max((0.5 * Math.PI) / 180, Math.min(0.1, Number.isFinite(feature) ? feature : 0.1));
}
