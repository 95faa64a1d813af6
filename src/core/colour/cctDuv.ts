/**
 * Correlated colour temperature and Duv of a chromaticity. CCT is the temperature of the Planckian
 * radiator whose chromaticity is nearest in the CIE 1960 UCS (u, v) = (u', 2/3 v') diagram
 * (CIE 15:2004, §9.5); Duv is that nearest distance, positive above the locus (toward green) and
 * negative below (toward magenta) (Y. Ohno, "Practical use and calculation of CCT and Duv",
 * LEUKOS 10(1), 2014, 47–55). Ohno's paper approximates the nearest point with a table and a
 * parabola; here the nearest point is found directly: a 1 % table of the locus (computed from the
 * same CMF sums as planckianXyz), then a golden-section search on ln T between the neighbours of
 * the nearest entry, to well under 0.1 K.
 */
import { CCT_MAX_K, CCT_MIN_K, planckianXyz } from '../photometry/cct';

export interface CctDuv {
  /** Kelvin. */
  readonly cct: number;
  /** Signed distance from the Planckian locus in (u, v). */
  readonly duv: number;
}

/** CIE 1960 UCS u, v of a chromaticity x, y (CIE 15:2004, §8.1: u = 4x/(−2x+12y+3), v = 6y/(−2x+12y+3)). */
export function xyToUv(x: number, y: number): [number, number] {
  const d = -2 * x + 12 * y + 3;
  return [(4 * x) / d, (6 * y) / d];
}

function locusUv(kelvin: number): [number, number] {
  // exp(ln 1000) comes back as 999.9999999999998: keep the table's ends inside the covered range.
  const [X, Y, Z] = planckianXyz(Math.min(CCT_MAX_K, Math.max(CCT_MIN_K, kelvin)));
  const s = X + Y + Z;
  return xyToUv(X / s, Y / s);
}

const STEP = Math.log(1.01);
let table: { lnT: number; u: number; v: number }[] | null = null;

function locusTable(): { lnT: number; u: number; v: number }[] {
  if (table) return table;
  const lo = Math.log(CCT_MIN_K);
  const hi = Math.log(CCT_MAX_K);
  const n = Math.ceil((hi - lo) / STEP);
  table = Array.from({ length: n + 1 }, (_, i) => {
    const lnT = Math.min(hi, lo + i * STEP);
    const [u, v] = locusUv(Math.exp(lnT));
    return { lnT, u, v };
  });
  return table;
}

/**
 * CCT and Duv of chromaticity (x, y), or null where the nearest point of the locus lies at or
 * beyond the ends of the range luxbox covers (1000–20000 K): no temperature describes such a colour.
 */
export function cctAndDuv(x: number, y: number): CctDuv | null {
  if (!Number.isFinite(x) || !Number.isFinite(y)) return null;
  const [u, v] = xyToUv(x, y);
  const t = locusTable();
  const dist2 = (e: { u: number; v: number }) => (e.u - u) ** 2 + (e.v - v) ** 2;
  let best = 0;
  for (let i = 1; i < t.length; i++) if (dist2(t[i]) < dist2(t[best])) best = i;
  if (best === 0 || best === t.length - 1) return null;
  // The distance along the locus is unimodal between the best entry's neighbours: golden section on ln T.
  const at = (lnT: number) => {
    const [lu, lv] = locusUv(Math.exp(lnT));
    return (lu - u) ** 2 + (lv - v) ** 2;
  };
  const g = (Math.sqrt(5) - 1) / 2;
  let a = t[best - 1].lnT;
  let b = t[best + 1].lnT;
  let c = b - g * (b - a);
  let d = a + g * (b - a);
  let fc = at(c);
  let fd = at(d);
  while (b - a > 1e-7) {
    if (fc < fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - g * (b - a);
      fc = at(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + g * (b - a);
      fd = at(d);
    }
  }
  const cct = Math.exp((a + b) / 2);
  const [lu, lv] = locusUv(cct);
  const duv = Math.hypot(u - lu, v - lv);
  return { cct, duv: v >= lv ? duv : -duv };
}
