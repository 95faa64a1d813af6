import { CIE_GENERAL_SKY_TYPES, type Sky } from '../../core/daylight/skies';
import type { Glazing } from '../../core/daylight/glazing';

/**
 * The night sky seen through a window when the scene has no daylight (or the view shows electric
 * light only), cd/m²: a moonless rural night sky is about 2·10⁻⁴ cd/m² and a city's sky glow about
 * 10⁻³ (Falchi et al., "The new world atlas of artificial night sky brightness", Sci. Adv. 2016:
 * 174 µcd/m² natural, up to ~0.01 cd/m² in cities); at any room exposure it is black.
 */
export const NIGHT_SKY_LUMINANCE = 0.001;

/** Width of the drawn window frame, m, and its grey as a share of middle grey at the exposure in force (a drawing aid, windowPane.glsl.ts). */
export const WINDOW_FRAME_WIDTH = 0.05;
export const WINDOW_FRAME_GREY = 0.7;

/** The sky's part of windowPane.glsl.ts's uniforms (uSky, uZenith, uGradation, uIndicatrix, uSun). */
export interface WindowSkyUniforms {
  sky: 0 | 1 | 2;
  zenith: number;
  /** a, b, 1 / (f(Z_s) φ(0)). */
  gradation: [number, number, number];
  /** c, d, e. */
  indicatrix: [number, number, number];
  sun: [number, number, number];
}

/** A sky as the window shader draws it: the CIE overcast sky as itself, the uniform sky as a general sky with a = c = e = 0, the CIE general types with their parameters; null: the night sky. */
export function windowSkyUniforms(sky: Sky | null): WindowSkyUniforms {
  if (!sky) return { sky: 0, zenith: 0, gradation: [0, -1, 1], indicatrix: [0, -1, 0], sun: [0, 1, 0] };
  if (sky.kind === 'cie-overcast') return { sky: 1, zenith: sky.zenithLuminance, gradation: [0, -1, 1], indicatrix: [0, -1, 0], sun: [0, 1, 0] };
  if (sky.kind === 'uniform') return { sky: 2, zenith: sky.zenithLuminance, gradation: [0, -1, 1], indicatrix: [0, -1, 0], sun: [0, 1, 0] };
  const p = CIE_GENERAL_SKY_TYPES.find((t) => t.type === sky.cieType);
  if (!p || !sky.sunDirection) throw new Error(`window sky: a CIE general sky needs its type and the sun (type ${String(sky.cieType)})`);
  const s = sky.sunDirection;
  const cosZs = Math.min(1, Math.max(-1, s[1]));
  const zs = Math.acos(cosZs);
  // f(Z_s) φ(0), as generalSkyRelativeLuminance's denominator (skies.ts).
  const fZs = 1 + p.c * (Math.exp(p.d * zs) - Math.exp((p.d * Math.PI) / 2)) + p.e * cosZs * cosZs;
  return { sky: 2, zenith: sky.zenithLuminance, gradation: [p.a, p.b, 1 / (fZs * (1 + p.a * Math.exp(p.b)))], indicatrix: [p.c, p.d, p.e], sun: [s[0], s[1], s[2]] };
}

/** The glazing's part: τ_n (1 − f) and the panes that shape τ(θ) (0: no glass, τ constant). */
export function windowGlazingUniforms(g: Glazing): { transmittance: number; panes: number } {
  return { transmittance: g.normalTransmittance * (1 - g.frameFraction), panes: g.panes };
}
