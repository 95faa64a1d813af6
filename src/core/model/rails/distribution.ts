/**
 * Where modules sit along a rail, from the rail's distribution (docs/model.md).
 * n modules of lengths l₁…lₙ (in rail order) on a rail of length L; offsets oᵢ
 * are distances from the rail start to each module's start.
 *
 * - start:           packed end to end from the rail start: o₁ = 0, oᵢ₊₁ = oᵢ + lᵢ.
 * - end:             packed end to end against the rail end (mirror of start).
 * - inside-centred:  the rail is cut into n equal cells of L/n; module i is centred
 *                    in cell i. Fits only if every lᵢ ≤ L/n.
 * - outside-centred: the outer modules touch the rail ends and the module centres
 *                    are equally spaced between them (one module: centred). Fits
 *                    only if neighbouring modules do not overlap.
 *
 * Every layout also needs Σlᵢ ≤ L. Lengths in metres; EPS absorbs float noise.
 */
import type { Distribution } from '../catalogSchema/railSystemSchema';

export const LAYOUT_EPS = 1e-9;

/** Offsets of each module start, or null when the modules do not fit that way. */
export function layoutModules(lengths: readonly number[], railLength: number, distribution: Distribution): number[] | null {
  const n = lengths.length;
  if (n === 0) return [];
  const total = lengths.reduce((a, b) => a + b, 0);
  if (total > railLength + LAYOUT_EPS) return null;
  switch (distribution) {
    case 'start':
      return packed(lengths, 0);
    case 'end':
      return packed(lengths, railLength - total);
    case 'inside-centred': {
      const cell = railLength / n;
      if (lengths.some((l) => l > cell + LAYOUT_EPS)) return null;
      return lengths.map((l, i) => (i + 0.5) * cell - l / 2);
    }
    case 'outside-centred': {
      if (n === 1) return [(railLength - lengths[0]) / 2];
      const first = lengths[0] / 2;
      const last = railLength - lengths[n - 1] / 2;
      const centres = lengths.map((_, i) => first + (i * (last - first)) / (n - 1));
      for (let i = 0; i + 1 < n; i++) {
        if (centres[i + 1] - centres[i] < (lengths[i] + lengths[i + 1]) / 2 - LAYOUT_EPS) return null;
      }
      return centres.map((c, i) => c - lengths[i] / 2);
    }
  }
}

function packed(lengths: readonly number[], start: number): number[] {
  const out: number[] = [];
  let o = start;
  for (const l of lengths) {
    out.push(o);
    o += l;
  }
  return out;
}
