/**
 * Display transform of the viewer, shared by the browser and `luxbox render`
 * (docs/viewer.md, "Display: illuminance → pixels"):
 *
 *   scene luminance (cd/m², linear sRGB) × exposure
 *   → chromatic adaptation: a 3×3 on linear sRGB (CAT16 to the display white, cat16.ts), computed
 *     on the CPU per frame and passed as a uniform;
 *   → hue-preserving gamut mapping: a colour with a negative component is desaturated towards the
 *     grey of its own luminance, just to the gamut boundary (clipping towards the lightness axis at
 *     constant lightness; Morovič & Luo, "The fundamentals of gamut mapping: a survey", J. Imaging
 *     Sci. Technol. 45(3):283–290, 2001): the chromaticity moves on the straight line to the white
 *     point, so the dominant wavelength stays;
 *   → the AgX tone curve (Troy Sobotka's AgX, the minimal fit of Filament and three.js
 *     AgXToneMapping, no look: Rec. 2020 working space, inset matrix, log2 encoding of
 *     −12.47…+4.03 stops around 0.18, polynomial sigmoid, outset matrix, 2.2 power; a soft
 *     roll-off up to 16 × middle grey), applied to the largest component with the colour scaled
 *     alike ("max-RGB": ratios, hence chromaticity and hue, kept at every level; a grey gets AgX's
 *     grey exactly). Chosen over ACES, the Khronos PBR Neutral curve and per-channel AgX by
 *     measurement (docs/viewer.md, "Choosing the tone curve");
 *   → sRGB OETF (IEC 61966-2-1).
 *
 * toneMap.ts mirrors this in TypeScript; a test compares both on the compiled GLSL.
 */
export const toneMapGlsl = /* glsl */ `
vec3 luxGamutMap(vec3 c) {
  float y = dot(c, vec3(0.2126, 0.7152, 0.0722));
  if (y <= 0.0) return vec3(0.0);
  float m = min(c.r, min(c.g, c.b));
  if (m >= 0.0) return c;
  return vec3(y) + (y / (y - m)) * (c - vec3(y));
}
vec3 luxAgxContrast(vec3 x) {
  vec3 x2 = x * x;
  vec3 x4 = x2 * x2;
  return 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
}
vec3 luxAgx(vec3 color) {
  // Column-major, as three.js: linear sRGB <-> Rec. 2020, AgX inset and outset.
  const mat3 toRec2020 = mat3(0.6274, 0.0691, 0.0164, 0.3293, 0.9195, 0.0880, 0.0433, 0.0113, 0.8956);
  const mat3 fromRec2020 = mat3(1.6605, -0.1246, -0.0182, -0.5876, 1.1329, -0.1006, -0.0728, -0.0083, 1.1187);
  const mat3 inset = mat3(0.856627153315983, 0.137318972929847, 0.11189821299995, 0.0951212405381588, 0.761241990602591, 0.0767994186031903, 0.0482516061458583, 0.101439036467562, 0.811302368396859);
  const mat3 outset = mat3(1.1271005818144368, -0.1413297634984383, -0.14132976349843826, -0.11060664309660323, 1.157823702216272, -0.11060664309660294, -0.016493938717834573, -0.016493938717834257, 1.2519364065950405);
  const float minEv = -12.47393;
  const float maxEv = 4.026069;
  color = inset * (toRec2020 * color);
  color = clamp((log2(max(color, 1e-10)) - minEv) / (maxEv - minEv), 0.0, 1.0);
  color = outset * luxAgxContrast(color);
  color = pow(max(color, 0.0), vec3(2.2));
  return clamp(fromRec2020 * color, 0.0, 1.0);
}
vec3 luxAgxMaxRgb(vec3 c) {
  float peak = max(c.r, max(c.g, c.b));
  if (peak <= 0.0) return vec3(0.0);
  return c * (luxAgx(vec3(peak)).g / peak);
}
vec3 luxLinearToSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
vec3 luxDisplay(vec3 luminance, float exposure, mat3 adapt) {
  return luxLinearToSrgb(luxAgxMaxRgb(luxGamutMap(adapt * (luminance * exposure))));
}
// Mode 2: the glare pass's HDR target (glarePass.glsl.ts) takes the exposed, adapted light; the pass applies the rest.
vec3 luxShade(vec3 luminance, float exposure, mat3 adapt, int mode) {
  return mode == 2 ? adapt * (luminance * exposure) : luxDisplay(luminance, exposure, adapt);
}
`;
