/**
 * Exact exchange areas A₁F₁₂ between axis-aligned rectangles, from the closed-form
 * view factors of J. R. Howell's "A Catalog of Radiation Heat Transfer
 * Configuration Factors" (cases C-12 parallel and C-16 perpendicular rectangles in
 * arbitrary relative position; R. J. Ehlert & T. F. Smith, J. Thermophysics and Heat
 * Transfer 7(1), 1993). Both follow from the double contour integral
 * A₁F₁₂ = (1/2π) ∮∮ ln r ds₁·ds₂ (Mitalas & Stephenson); the 16-term alternating sums
 * are its values at the rectangles' corner coordinates.
 *
 * Being exact, they are reciprocal (A₁F₁₂ = A₂F₂₁ by symmetry of the formula) and
 * close the box (the factors from a patch to all other patches sum to 1), the two
 * properties that make a box's mean illuminance come out exactly Φ/(S(1−ρ)).
 */

const INV_2PI = 1 / (2 * Math.PI);

/** Parallel planes at distance c; dx, dy: coordinate differences of corners. */
function gParallel(dx: number, dy: number, c2: number): number {
  const a = Math.sqrt(dx * dx + c2);
  const b = Math.sqrt(dy * dy + c2);
  return dy * a * Math.atan(dy / a) + dx * b * Math.atan(dx / b) - 0.5 * c2 * Math.log(dx * dx + dy * dy + c2);
}

/**
 * Exchange area between rectangle 1 = [x1,x2]×[y1,y2] in the plane z = 0 and
 * rectangle 2 = [ξ1,ξ2]×[η1,η2] (same x/y axes) in the plane z = c, c > 0.
 */
export function parallelExchangeArea(x1: number, x2: number, y1: number, y2: number, xi1: number, xi2: number, eta1: number, eta2: number, c: number): number {
  const c2 = c * c;
  const xs = [x1, x2];
  const ys = [y1, y2];
  const xis = [xi1, xi2];
  const etas = [eta1, eta2];
  let sum = 0;
  for (let i = 0; i < 2; i++) {
    for (let j = 0; j < 2; j++) {
      for (let k = 0; k < 2; k++) {
        for (let l = 0; l < 2; l++) {
          const sign = (i + j + k + l) & 1 ? -1 : 1;
          sum += sign * gParallel(xs[i] - xis[l], ys[j] - etas[k], c2);
        }
      }
    }
  }
  return sum * INV_2PI;
}

/** Perpendicular planes meeting along the x axis; y and η: distances from that line. */
function gPerpendicular(dx: number, y: number, eta: number): number {
  const r2 = y * y + eta * eta;
  const t = dx * dx + r2;
  if (t === 0) return 0; // the limit of both terms at a shared corner
  const r = Math.sqrt(r2);
  const atanTerm = r > 0 ? dx * r * Math.atan(dx / r) : 0;
  return atanTerm + 0.25 * (dx * dx - r2) * Math.log(t);
}

/**
 * Exchange area between rectangle 1 = [x1,x2] × [y1,y2] in one plane and
 * rectangle 2 = [ξ1,ξ2] × [η1,η2] in a perpendicular plane, where x/ξ run along
 * the line where the planes meet and y, η ≥ 0 are distances from that line.
 */
export function perpendicularExchangeArea(x1: number, x2: number, y1: number, y2: number, xi1: number, xi2: number, eta1: number, eta2: number): number {
  const xs = [x1, x2];
  const ys = [y1, y2];
  const xis = [xi1, xi2];
  const etas = [eta1, eta2];
  let sum = 0;
  for (let i = 0; i < 2; i++) {
    for (let j = 0; j < 2; j++) {
      for (let k = 0; k < 2; k++) {
        for (let l = 0; l < 2; l++) {
          const sign = (i + j + k + l) & 1 ? -1 : 1;
          sum += sign * gPerpendicular(xs[i] - xis[l], ys[j], etas[k]);
        }
      }
    }
  }
  return sum * INV_2PI;
}
