import type { Photometry } from '../core/photometry/types';

/** Index i with a[i] ≤ x ≤ a[i+1] for ascending a (clamped to the ends), by bisection. */
function bracket(a: readonly number[], x: number): number {
  let lo = 0;
  let hi = a.length - 1;
  if (x <= a[0]) return 0;
  if (x >= a[hi]) return Math.max(0, hi - 1);
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (a[mid] <= x) lo = mid;
    else hi = mid;
  }
  return lo;
}

/**
 * Intensity in cd at (γ, C) by bilinear interpolation in the expanded candela grid
 * (src/core/photometry/types.ts: symmetry unfolded, multipliers applied, C either [0] or
 * spanning 0..360). Bilinear in the angles is what LM-63 consumers conventionally
 * use and what src/core/photometry's intensity() does too.
 * Independent of src/core/photometry's lookup on purpose, so the reference checks it.
 */
export function candelaAt(ph: Photometry, gammaDeg: number, cDeg: number): number {
  const va = ph.verticalAngles;
  const ha = ph.horizontalAngles;
  const g = Math.min(Math.max(gammaDeg, va[0]), va[va.length - 1]);
  const iv = bracket(va, g);
  const v0 = va[iv];
  const v1 = va[Math.min(iv + 1, va.length - 1)];
  const tv = v1 > v0 ? (g - v0) / (v1 - v0) : 0;
  const iv1 = Math.min(iv + 1, va.length - 1);
  // No inner closures here: this is the innermost call of the reference, and
  // transpilers wrap every closure creation in a naming helper.
  const r0 = ph.candela[0];
  const a = r0[iv] + (r0[iv1] - r0[iv]) * tv;
  if (ha.length === 1) return a;
  let c = cDeg % 360;
  if (c < 0) c += 360;
  c = Math.min(Math.max(c, ha[0]), ha[ha.length - 1]);
  const ih = bracket(ha, c);
  const h0 = ha[ih];
  const h1 = ha[ih + 1];
  const th = h1 > h0 ? (c - h0) / (h1 - h0) : 0;
  const p0 = ph.candela[ih];
  const p1 = ph.candela[ih + 1];
  const b0 = p0[iv] + (p0[iv1] - p0[iv]) * tv;
  const b1 = p1[iv] + (p1[iv1] - p1[iv]) * tv;
  return b0 + (b1 - b0) * th;
}
