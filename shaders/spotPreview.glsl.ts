/**
 * The aiming preview's direct light (src/engines/view/spotPreview.ts, whose previewIlluminance is
 * this function's CPU mirror): RGB lux at world point p on a surface with inward normal n from one
 * lamp, E = I(γ, C)·cos θ / d² × weight, no shadows. γ from the lamp's local −y, C from local +x
 * toward local −z (docs/scene-format.md); the candela texture holds C over 0…360 in its columns and
 * γ over 0…180 in its rows, sampled at texel centres.
 */
export interface CandelaGridFacts {
  /** Columns: C over 0…360 inclusive. */
  cSamples: number;
  /** Rows: γ over 0…180 inclusive. */
  gammaSamples: number;
}

export const spotPreviewGlsl = (grid: CandelaGridFacts): string => /* glsl */ `
uniform int uSpotOn;
uniform vec3 uSpotPos;
uniform mat3 uSpotToLocal;
uniform vec3 uSpotWeight;
uniform sampler2D uSpotCandela;
vec3 spotPreviewE(vec3 p, vec3 n) {
  if (uSpotOn == 0) return vec3(0.0);
  vec3 d = uSpotPos - p;
  float r2 = max(dot(d, d), 1e-8);
  float cosI = dot(n, d) * inversesqrt(r2);
  if (cosI <= 0.0) return vec3(0.0);
  vec3 l = uSpotToLocal * (-d);
  float gammaT = acos(clamp(-l.y / length(l), -1.0, 1.0)) / 3.14159265358979;
  float c = atan(-l.z, l.x);
  if (c < 0.0) c += 6.28318530717959;
  vec2 cells = vec2(${(grid.cSamples - 1).toFixed(1)}, ${(grid.gammaSamples - 1).toFixed(1)});
  vec2 uv = (vec2(c / 6.28318530717959, gammaT) * cells + 0.5) / (cells + 1.0);
  float I = texture(uSpotCandela, uv).r;
  return uSpotWeight * (I * cosI / r2);
}
`;
