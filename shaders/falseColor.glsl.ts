const vec = (k: readonly number[]) => `vec3(${k.slice(0, 3).join(', ')}), vec3(${k.slice(3).join(', ')})`;

/**
 * False-colour illuminance with isolines (see falseColorScale.ts for the scale
 * and legend, which this mirrors).
 *
 * Isolines are drawn where log(E) crosses a level, within about one pixel,
 * measured with screen-space derivatives (fwidth) so lines keep a constant
 * width whatever the distance. A line is only drawn where its position is
 * well-conditioned; it fades out
 * - where the surface is seen at a grazing angle (|cos| of the view angle
 *   below ~0.3): a wall seen edge-on compresses metres of gradient into a few
 *   pixels, and its lines collapse into a smear along the room outline;
 * - where neighbouring levels would be less than ~3 pixels apart (log E
 *   changes by more than log(2)/3 per pixel; log(2) is the smallest ratio of
 *   two 1–2–5 levels): lines that close merge into dark bands.
 * The caller passes the illuminance for the lines separately from the one
 * for the colour, so it can smooth it: a level crossing in a nearly flat
 * field moves with every percent of Monte-Carlo noise (roomSurface.glsl.ts averages
 * the neighbouring texels).
 *
 * The scale's facts are parameters, so this chunk mirrors falseColorScale.ts without importing
 * it: `maxLevels` is the size of the level array, `turbo` the red, green and blue polynomial
 * coefficients of the colour map (six each, lowest power first).
 */
export interface FalseColorScaleFacts {
  maxLevels: number;
  turbo: readonly [readonly number[], readonly number[], readonly number[]];
}

export const falseColorGlsl = ({ maxLevels, turbo: [TURBO_R, TURBO_G, TURBO_B] }: FalseColorScaleFacts): string => /* glsl */ `
#define LUX_MAX_LEVELS ${maxLevels}
uniform float uLevels[LUX_MAX_LEVELS];
uniform int uLevelCount;
float luxPoly(vec3 a, vec3 b, float x) {
  return a.x + x * (a.y + x * (a.z + x * (b.x + x * (b.y + x * b.z))));
}
vec3 luxTurbo(float t) {
  float x = clamp(t, 0.0, 1.0);
  return clamp(vec3(luxPoly(${vec(TURBO_R)}, x), luxPoly(${vec(TURBO_G)}, x), luxPoly(${vec(TURBO_B)}, x)), 0.0, 1.0);
}
float luxLegendPosition(float lux) {
  float l = log(max(lux, 1e-6));
  float n = float(uLevelCount - 1);
  for (int i = 0; i < LUX_MAX_LEVELS - 1; i++) {
    if (i >= uLevelCount - 1) break;
    float a = log(uLevels[i]);
    float b = log(uLevels[i + 1]);
    if (l < b || i == uLevelCount - 2) return clamp((float(i) + (l - a) / (b - a)) / n, 0.0, 1.0);
  }
  return 1.0;
}
// Opacity 0..1 of the isolines at log-illuminance l; w = fwidth(l) (change per pixel); facing = |cos| of the view angle.
float luxIsolineAlpha(float l, float w, float facing) {
  float width = max(w, 1e-5);
  float line = 0.0;
  for (int i = 0; i < LUX_MAX_LEVELS; i++) {
    if (i >= uLevelCount) break;
    line = max(line, 1.0 - smoothstep(0.5, 1.5, abs(l - log(uLevels[i])) / width));
  }
  float spacingPx = 0.6931 / width;
  return line * smoothstep(2.0, 3.5, spacingPx) * smoothstep(0.12, 0.3, facing);
}
vec3 luxFalseColor(float lux, float lineLux, float facing) {
  vec3 color = luxTurbo(luxLegendPosition(lux));
  float l = log(max(lineLux, 1e-6));
  return mix(color, vec3(0.05), luxIsolineAlpha(l, fwidth(l), facing) * 0.85);
}
`;
