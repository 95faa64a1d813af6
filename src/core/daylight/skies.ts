/**
 * Sky luminance distributions, each normalised to a given horizontal illuminance from the sky
 * alone (E_h, lux, on an unobstructed horizontal plane, the sun's direct beam excluded):
 *
 * - uniform: L = E_h / π everywhere above the horizon (tests);
 * - CIE standard overcast (Moon & Spencer 1942, CIE 1955; CIE S 011 notes it beside type 1):
 *   L(θ) = L_z (1 + 2 sin θ) / 3, θ the elevation, and ∫ L sin θ dω = 7π L_z / 9 = E_h;
 * - the CIE standard general sky (CIE S 011/E:2003 = ISO 15469:2004; Darula & Kittler, "CIE
 *   general sky standard defining luminance distributions", eSim 2002): 15 types,
 *   L / L_z = f(χ) φ(Z) / (f(Z_s) φ(0)) with the gradation φ(Z) = 1 + a exp(b / cos Z)
 *   (φ(π/2) = 1) and the indicatrix f(χ) = 1 + c (exp(dχ) − exp(dπ/2)) + e cos²χ, Z the sky
 *   element's zenith angle, Z_s the sun's, χ the angle between element and sun. Type 12 is the
 *   CIE standard clear sky (CIE 22-1973, Kittler 1967: (0.91 + 10 e^{−3χ} + 0.45 cos²χ)(1 − e^{−0.32/cos Z})).
 *   L_z follows from E_h by numerical integration of L cos Z over the hemisphere
 *   (generalSkyIrradianceIntegral below).
 *
 * Directions are unit vectors in room coordinates, y up. Below the horizon the sky is 0: the
 * ground is a source of its own (groundLuminance).
 */

export type Direction = readonly [number, number, number];

export type SkyKind = 'uniform' | 'cie-overcast' | 'cie-general';

export interface Sky {
  kind: SkyKind;
  /** 1 … 15 for 'cie-general'. */
  cieType?: number;
  /** Horizontal illuminance from the sky alone, lux. */
  horizontalIlluminance: number;
  /** cd/m² at the zenith. */
  zenithLuminance: number;
  /** Unit vector toward the sun (general skies). */
  sunDirection?: Direction;
  /** cd/m² seen looking along the unit direction d (0 at or below the horizon). */
  luminance(d: Direction): number;
}

/** Gradation (a, b) and indicatrix (c, d, e) of the 15 CIE general sky types (CIE S 011, table 1). */
export const CIE_GENERAL_SKY_TYPES: readonly { type: number; a: number; b: number; c: number; d: number; e: number; description: string }[] = [
  { type: 1, a: 4.0, b: -0.7, c: 0, d: -1.0, e: 0.0, description: 'overcast, steep gradation towards the zenith, azimuthal uniformity' },
  { type: 2, a: 4.0, b: -0.7, c: 2, d: -1.5, e: 0.15, description: 'overcast, steep gradation, slight brightening towards the sun' },
  { type: 3, a: 1.1, b: -0.8, c: 0, d: -1.0, e: 0.0, description: 'overcast, moderate gradation, azimuthal uniformity' },
  { type: 4, a: 1.1, b: -0.8, c: 2, d: -1.5, e: 0.15, description: 'overcast, moderate gradation, slight brightening towards the sun' },
  { type: 5, a: 0.0, b: -1.0, c: 0, d: -1.0, e: 0.0, description: 'sky of uniform luminance' },
  { type: 6, a: 0.0, b: -1.0, c: 2, d: -1.5, e: 0.15, description: 'partly cloudy, no gradation, slight brightening towards the sun' },
  { type: 7, a: 0.0, b: -1.0, c: 5, d: -2.5, e: 0.3, description: 'partly cloudy, no gradation, brighter circumsolar region' },
  { type: 8, a: 0.0, b: -1.0, c: 10, d: -3.0, e: 0.45, description: 'partly cloudy, no gradation, distinct solar corona' },
  { type: 9, a: -1.0, b: -0.55, c: 2, d: -1.5, e: 0.15, description: 'partly cloudy, obscured sun' },
  { type: 10, a: -1.0, b: -0.55, c: 5, d: -2.5, e: 0.3, description: 'partly cloudy, brighter circumsolar region' },
  { type: 11, a: -1.0, b: -0.55, c: 10, d: -3.0, e: 0.45, description: 'white-blue sky, distinct solar corona' },
  { type: 12, a: -1.0, b: -0.32, c: 10, d: -3.0, e: 0.45, description: 'CIE standard clear sky, low luminance turbidity' },
  { type: 13, a: -1.0, b: -0.32, c: 16, d: -3.0, e: 0.3, description: 'CIE standard clear sky, polluted atmosphere' },
  { type: 14, a: -1.0, b: -0.15, c: 16, d: -3.0, e: 0.3, description: 'cloudless turbid sky, broad solar corona' },
  { type: 15, a: -1.0, b: -0.15, c: 24, d: -2.8, e: 0.15, description: 'white-blue turbid sky, broad solar corona' },
];

/** The CIE clear sky the scene format's "cie-clear" means: type 12. */
export const CIE_CLEAR_SKY_TYPE = 12;

export function uniformSky(horizontalIlluminance: number): Sky {
  const l = horizontalIlluminance / Math.PI;
  return { kind: 'uniform', horizontalIlluminance, zenithLuminance: l, luminance: (d) => (d[1] > 0 ? l : 0) };
}

/** CIE standard overcast sky: L_z = 9 E_h / (7π). */
export function cieOvercastSky(horizontalIlluminance: number): Sky {
  const lz = (9 * horizontalIlluminance) / (7 * Math.PI);
  return { kind: 'cie-overcast', horizontalIlluminance, zenithLuminance: lz, luminance: (d) => (d[1] > 0 ? (lz * (1 + 2 * d[1])) / 3 : 0) };
}

function skyParameters(type: number): (typeof CIE_GENERAL_SKY_TYPES)[number] {
  const p = CIE_GENERAL_SKY_TYPES.find((t) => t.type === type);
  if (!p) throw new RangeError(`CIE general sky type ${type} does not exist (1 … 15)`);
  return p;
}

/** L / L_z of a general sky type toward d (unit, y up) with the sun toward s (unit); 0 at or below the horizon. */
export function generalSkyRelativeLuminance(type: number, d: Direction, s: Direction): number {
  const { a, b, c, d: dd, e } = skyParameters(type);
  const cosZ = d[1];
  if (!(cosZ > 0)) return 0;
  const cosZs = Math.min(1, Math.max(-1, s[1]));
  const zs = Math.acos(cosZs);
  const cosChi = Math.min(1, Math.max(-1, d[0] * s[0] + d[1] * s[1] + d[2] * s[2]));
  const chi = Math.acos(cosChi);
  const indicatrix = (x: number, cosx: number): number => 1 + c * (Math.exp(dd * x) - Math.exp((dd * Math.PI) / 2)) + e * cosx * cosx;
  const gradation = 1 + a * Math.exp(b / cosZ);
  return (indicatrix(chi, cosChi) * gradation) / (indicatrix(zs, cosZs) * (1 + a * Math.exp(b)));
}

/** 4-point Gauss–Legendre on [−1, 1] (Abramowitz & Stegun 25.4.30). */
const GAUSS4 = [
  [-0.8611363115940526, 0.3478548451374538],
  [-0.3399810435848563, 0.6521451548625461],
  [0.3399810435848563, 0.6521451548625461],
  [0.8611363115940526, 0.3478548451374538],
] as const;

/**
 * ∫ f(d) cos Z dω over the upper hemisphere, with u = cos Z (dω = du dφ): composite 4-point
 * Gauss–Legendre in u on `intervals` pieces of [0, u_s] and of [u_s, 1] and in φ on 2·`intervals`
 * pieces starting at the sun's azimuth, so the indicatrix's cusp at the sun lies on cell corners
 * (the integrand is smooth inside every cell). With 24 intervals (73 728 points) the CIE types
 * are integrated to better than 1e-6 relative (tests/core/daylight/skies.test.ts).
 */
export function hemisphereCosineIntegral(f: (d: Direction) => number, sun: Direction = [0, 1, 0], intervals = 24): number {
  const us = Math.min(1, Math.max(0, sun[1]));
  const phiSun = Math.atan2(sun[0], -sun[2]);
  const uRanges: [number, number][] = [];
  for (const [lo, hi] of [
    [0, us],
    [us, 1],
  ]) {
    if (hi - lo < 1e-12) continue;
    for (let i = 0; i < intervals; i++) uRanges.push([lo + ((hi - lo) * i) / intervals, lo + ((hi - lo) * (i + 1)) / intervals]);
  }
  const nPhi = 2 * intervals;
  const dPhi = (2 * Math.PI) / nPhi;
  let sum = 0;
  for (const [u0, u1] of uRanges) {
    const hu = (u1 - u0) / 2;
    for (const [xu, wu] of GAUSS4) {
      const u = u0 + hu * (xu + 1);
      const sinZ = Math.sqrt(Math.max(0, 1 - u * u));
      let ring = 0;
      for (let j = 0; j < nPhi; j++) {
        for (const [xp, wp] of GAUSS4) {
          const phi = phiSun + dPhi * (j + (xp + 1) / 2);
          ring += (wp / 2) * f([sinZ * Math.sin(phi), u, -sinZ * Math.cos(phi)]);
        }
      }
      sum += wu * hu * u * ring * dPhi;
    }
  }
  return sum;
}

/** ∫ (L / L_z) cos Z dω of a general sky type: E_h = L_z × this. */
export function generalSkyIrradianceIntegral(type: number, sun: Direction): number {
  return hemisphereCosineIntegral((d) => generalSkyRelativeLuminance(type, d, sun), sun);
}

/** A CIE general sky of the given type with the sun toward `sun` (unit; it may be below the horizon), scaled to E_h. */
export function cieGeneralSky(type: number, sun: Direction, horizontalIlluminance: number): Sky {
  skyParameters(type);
  const lz = horizontalIlluminance / generalSkyIrradianceIntegral(type, sun);
  return {
    kind: 'cie-general',
    cieType: type,
    horizontalIlluminance,
    zenithLuminance: lz,
    sunDirection: sun,
    luminance: (d) => lz * generalSkyRelativeLuminance(type, d, sun),
  };
}

/**
 * The ground outside as a uniform diffuse reflector lit by the unobstructed sky and sun:
 * L_g = ρ_g (E_sky,h + E_sun,h) / π, seen through windows below the horizon.
 */
export function groundLuminance(skyHorizontalIlluminance: number, sunHorizontalIlluminance: number, groundReflectance: number): number {
  return (groundReflectance * (skyHorizontalIlluminance + sunHorizontalIlluminance)) / Math.PI;
}

/** Default ground reflectance (issue 30; the usual design value for grass and paving, e.g. CIBSE LG10). */
export const DEFAULT_GROUND_REFLECTANCE = 0.2;
