/**
 * Display transform of the viewer, shared by the browser and `luxbox render`:
 * scene luminance (cd/m²) × exposure → ACES filmic tone curve → sRGB.
 *
 * ACES: the fit of the RRT+ODT by Stephen Hill (BakingLab, MIT licence), the
 * same curve and input/output matrices as three.js ACESFilmicToneMapping
 * (including its 1/0.6 exposure pre-scale), so a value of 0.18 after exposure
 * lands near sRGB middle grey. sRGB encoding: IEC 61966-2-1 piecewise OETF.
 * toneMap.ts mirrors this in TypeScript; a test compares both.
 */
export const toneMapGlsl = /* glsl */ `
vec3 luxRrtOdtFit(vec3 v) {
  vec3 a = v * (v + 0.0245786) - 0.000090537;
  vec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
  return a / b;
}
vec3 luxAcesFilmic(vec3 color) {
  // Column-major: sRGB -> ACES AP1 (with the RRT saturation) and back.
  const mat3 inputMat = mat3(0.59719, 0.07600, 0.02840, 0.35458, 0.90834, 0.13383, 0.04823, 0.01566, 0.83777);
  const mat3 outputMat = mat3(1.60475, -0.10208, -0.00327, -0.53108, 1.10813, -0.07276, -0.07367, -0.00605, 1.07602);
  color = inputMat * (color / 0.6);
  color = luxRrtOdtFit(color);
  return clamp(outputMat * color, 0.0, 1.0);
}
vec3 luxLinearToSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
vec3 luxDisplay(vec3 luminance, float exposure) {
  return luxLinearToSrgb(luxAcesFilmic(luminance * exposure));
}
`;
