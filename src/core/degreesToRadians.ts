/**
 * Degrees to radians with the angle reduced first (issue 32): `deg · π / 180` overflows to
 * Infinity for |deg| ≥ 5.7e307 (and cos/sin of Infinity are NaN), while `deg % 360` is exact for
 * every finite double (IEEE 754 remainder), so any finite angle gives a finite, and accurate,
 * rotation. A non-finite angle stays non-finite: the readers refuse those before anything turns.
 */
export function degreesToRadians(deg: number): number {
  return ((deg % 360) * Math.PI) / 180;
}
