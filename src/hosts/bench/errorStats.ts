/** RMS and largest relative error of `values` against `reference` (pairs with a reference ≤ floor are skipped). */
export function relativeErrors(values: ArrayLike<number>, reference: ArrayLike<number>, floor = 0): { rms: number; max: number; n: number } {
  let sum = 0;
  let max = 0;
  let n = 0;
  for (let i = 0; i < values.length; i++) {
    const r = reference[i];
    if (!(r > floor)) continue;
    const e = Math.abs(values[i] - r) / r;
    sum += e * e;
    max = Math.max(max, e);
    n++;
  }
  return { rms: n > 0 ? Math.sqrt(sum / n) : 0, max, n };
}
