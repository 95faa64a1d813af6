import { glazingTransmittance } from '../../../core/daylight/glazing';
import type { BakeDaylight } from './bakeDaylight';
import type { BakeWindow } from './daylightWindows';

/** Rings (in cos θ to the window's outward normal) and sectors of the quadrature: 48 × 96 midpoint cells, ≤ 0.3 % on a uniform sky (tested). */
const RINGS = 48;
const SECTORS = 96;

/**
 * Luminous flux entering through the windows, lm: for each window of area A with outward normal n,
 * A · ∫ L(d) · τ(d·n) · (d·n) dω over the outward hemisphere (L the sky's luminance above the
 * horizon and the ground's below it, τ the glazing's angular transmittance, core/daylight/glazing.ts)
 * plus the sun's beam A · E_n · (s·n) · τ(s·n) when it faces the window. The radiometric definition
 * of irradiance on a plane (E = ∫ L cos θ dω; DiLaura et al., *The Lighting Handbook*, 10th ed., IES
 * 2011, ch. 5) taken through the glass. Unobstructed: the room's own walls do not shade the opening
 * (a window sits in its wall's plane, so nothing of the room stands in front of it). What the eye's
 * adopted white weighs daylight by (adoptedWhite.ts): the lumens daylight brings against the lamps'.
 */
export function daylightEnteringFlux(daylight: BakeDaylight, windows: readonly BakeWindow[]): number {
  let flux = 0;
  for (const w of windows) {
    const n: [number, number, number] = [-w.inward[0], -w.inward[1], -w.inward[2]];
    const [t1, t2] = tangents(n);
    let e = 0;
    for (let i = 0; i < RINGS; i++) {
      // Midpoint in u = cos θ: dω = du dφ, so each cell weighs (1/RINGS)·(2π/SECTORS).
      const u = (i + 0.5) / RINGS;
      const s = Math.sqrt(1 - u * u);
      const tau = glazingTransmittance(w.glazing, u);
      let ring = 0;
      for (let j = 0; j < SECTORS; j++) {
        const phi = ((j + 0.5) * 2 * Math.PI) / SECTORS;
        const c = Math.cos(phi) * s;
        const q = Math.sin(phi) * s;
        const d: [number, number, number] = [n[0] * u + t1[0] * c + t2[0] * q, n[1] * u + t1[1] * c + t2[1] * q, n[2] * u + t1[2] * c + t2[2] * q];
        ring += d[1] > 0 ? (daylight.sky?.luminance(d) ?? 0) : daylight.groundLuminance;
      }
      e += tau * u * ring * (1 / RINGS) * ((2 * Math.PI) / SECTORS);
    }
    const sun = daylight.sun;
    if (sun) {
      const cos = sun.direction[0] * n[0] + sun.direction[1] * n[1] + sun.direction[2] * n[2];
      if (cos > 0 && sun.direction[1] > 0) e += sun.normalIlluminance * cos * glazingTransmittance(w.glazing, cos);
    }
    if (Number.isFinite(e) && e > 0) flux += e * w.area;
  }
  return flux;
}

/** Two unit vectors perpendicular to n and to each other. */
function tangents(n: readonly [number, number, number]): [[number, number, number], [number, number, number]] {
  const a: [number, number, number] = Math.abs(n[1]) < 0.9 ? [0, 1, 0] : [1, 0, 0];
  const t1 = normalise(cross(a, n));
  return [t1, cross(n, t1)];
}

function cross(a: readonly number[], b: readonly number[]): [number, number, number] {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

function normalise(v: [number, number, number]): [number, number, number] {
  const l = Math.hypot(v[0], v[1], v[2]);
  return [v[0] / l, v[1] / l, v[2] / l];
}
