import { MAX_LEVELS, TURBO_B, TURBO_G, TURBO_R } from './falseColorScale';

const vec = (k: number[]) => `vec3(${k.slice(0, 3).join(', ')}), vec3(${k.slice(3).join(', ')})`;

/**
 * False-colour illuminance with isolines (see falseColorScale.ts for the scale
 * and legend, which this mirrors). Isolines: where log(E) crosses a level,
 * within one pixel, measured with screen-space derivatives so lines keep a
 * constant width whatever the distance.
 */
export const falseColorGlsl = /* glsl */ `
#define LUX_MAX_LEVELS ${MAX_LEVELS}
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
vec3 luxFalseColor(float lux) {
  vec3 color = luxTurbo(luxLegendPosition(lux));
  float l = log(max(lux, 1e-6));
  float w = max(fwidth(l), 1e-5);
  float line = 0.0;
  for (int i = 0; i < LUX_MAX_LEVELS; i++) {
    if (i >= uLevelCount) break;
    line = max(line, 1.0 - smoothstep(0.5, 1.5, abs(l - log(uLevels[i])) / w));
  }
  // Where lux changes by a large factor per pixel (grazing views of a wall), lines would merge into smears: fade them.
  line *= 1.0 - smoothstep(0.15, 0.4, w);
  return mix(color, vec3(0.05), line * 0.85);
}
`;
