import { toneMapGlsl } from './toneMap.glsl';

/**
 * The veiling-glare pass (docs/viewer.md, "Glare"; src/engines/view/glare/createGlarePass.ts): a
 * pyramid over the linear HDR image (exposed and adapted, before the display curve). Down: each
 * level is the previous one filtered by 13 bilinear taps (five overlapping 4×4 boxes, the centre
 * one weighted ½, the corners ⅛ each: Jimenez, "Next generation post processing in Call of Duty:
 * Advanced Warfare", SIGGRAPH 2014), which keep the mean and do not flicker on small bright
 * emitters. Up: from the coarsest level, each level's sum = its own level × its PSF weight + the
 * coarser sum through a 3×3 tent; the composite adds the finest sum to core × the image and applies
 * the display transform. Every filter's weights sum to 1, so light is moved, never made.
 *
 * Only the light **above the exposure's white** scatters (glareExcessGlsl): the linear value 1 is
 * the luminance L_max that the exposure maps to the display's top (photographicExposure.ts), and up
 * to it the display shows the light, so the viewer's own eye already scatters it from the screen;
 * a veil drawn from it as well would count that scatter twice and fog the whole picture. Beyond
 * L_max the display cannot show the light (the tone curve compresses it), and the veil is how the
 * eye would still see it (docs/viewer.md, "Glare").
 */
export const glareVertex = /* glsl */ `
out vec2 vUv;
void main() {
  vUv = uv;
  gl_Position = vec4(position.xy, 0.0, 1.0);
}
`;

/**
 * The part of a pixel of the HDR image that scatters: a light pixel (alpha > ½) scaled by
 * max(0, 1 − 1/m), m = max(R, G, B), i.e. the colour above the white m = 1 with its hue kept; a flat
 * display colour (alpha ¼) and the cleared background (0) scatter nothing.
 */
const glareExcessGlsl = /* glsl */ `
vec3 glareExcess(vec4 p) {
  float m = max(max(p.r, p.g), p.b);
  return p.a > 0.5 && m > 1.0 ? p.rgb * (1.0 - 1.0 / m) : vec3(0.0);
}
`;

/** The light above white of each pixel of the HDR image, at full size: what the pyramid scatters. */
export const glareExcessFragment = /* glsl */ `
precision highp float;
uniform sampler2D uHdr;
out vec4 fragColor;
${glareExcessGlsl}
void main() {
  fragColor = vec4(glareExcess(texelFetch(uHdr, ivec2(gl_FragCoord.xy), 0)), 1.0);
}
`;

/** One level down: 13 taps around the destination texel's centre, in source texels (uTexel = 1 / source size). */
export const glareDownFragment = /* glsl */ `
precision highp float;
in vec2 vUv;
uniform sampler2D uSource;
uniform vec2 uTexel;
out vec4 fragColor;
vec3 tap(vec2 o) {
  return texture(uSource, vUv + o * uTexel).rgb;
}
void main() {
  vec3 a = tap(vec2(-2.0, 2.0)), b = tap(vec2(0.0, 2.0)), c = tap(vec2(2.0, 2.0));
  vec3 d = tap(vec2(-1.0, 1.0)), e = tap(vec2(1.0, 1.0));
  vec3 f = tap(vec2(-2.0, 0.0)), g = tap(vec2(0.0)), h = tap(vec2(2.0, 0.0));
  vec3 i = tap(vec2(-1.0, -1.0)), j = tap(vec2(1.0, -1.0));
  vec3 k = tap(vec2(-2.0, -2.0)), l = tap(vec2(0.0, -2.0)), m = tap(vec2(2.0, -2.0));
  vec3 sum = (d + e + i + j) * 0.125 + (a + b + g + f) * 0.03125 + (b + c + h + g) * 0.03125 + (f + g + l + k) * 0.03125 + (g + h + m + l) * 0.03125;
  fragColor = vec4(sum, 1.0);
}
`;

/** The 3×3 tent (1 2 1 / 2 4 2 / 1 2 1, /16) of a coarser level at this point, in that level's texels. */
const tentGlsl = /* glsl */ `
vec3 tent(sampler2D s, vec2 uv, vec2 texel) {
  vec3 sum = texture(s, uv).rgb * 4.0;
  sum += (texture(s, uv + vec2(texel.x, 0.0)).rgb + texture(s, uv - vec2(texel.x, 0.0)).rgb + texture(s, uv + vec2(0.0, texel.y)).rgb + texture(s, uv - vec2(0.0, texel.y)).rgb) * 2.0;
  sum += texture(s, uv + texel).rgb + texture(s, uv - texel).rgb + texture(s, uv + vec2(texel.x, -texel.y)).rgb + texture(s, uv + vec2(-texel.x, texel.y)).rgb;
  return sum / 16.0;
}
`;

/** One level up: this level × its weight + the coarser sum through the tent (uHasCoarser 0 at the coarsest). */
export const glareUpFragment = /* glsl */ `
precision highp float;
in vec2 vUv;
uniform sampler2D uLevel;
uniform sampler2D uCoarser;
uniform vec2 uCoarserTexel;
uniform float uWeight;
uniform int uHasCoarser;
out vec4 fragColor;
${tentGlsl}
void main() {
  vec3 sum = texture(uLevel, vUv).rgb * uWeight;
  if (uHasCoarser == 1) sum += tent(uCoarser, vUv, uCoarserTexel);
  fragColor = vec4(sum, 1.0);
}
`;

/**
 * The composite: the pixel less the share of its excess it scatters, (1 − core) × excess, plus the
 * scattered light, then the display transform (gamut map,
 * AgX on max(R,G,B), sRGB: toneMap.glsl.ts, as the room's shaders do without glare). Alpha tells
 * what a pixel of the HDR image holds: 1 light, ¼ a flat display colour (a selected module in the
 * accent blue) that keeps its colour, 0 nothing drawn (cleared), which shows uBackground (display
 * sRGB); over the last two the scattered light is added after the display curve. uLinear 1 writes the linear sum instead
 * (for tests on a float target).
 */
export const glareCompositeFragment = /* glsl */ `
precision highp float;
in vec2 vUv;
uniform sampler2D uHdr;
uniform sampler2D uScattered;
uniform vec2 uScatteredTexel;
uniform float uCore;
uniform int uHasScattered;
uniform int uLinear;
uniform vec3 uBackground;
out vec4 fragColor;
${toneMapGlsl}
${tentGlsl}
${glareExcessGlsl}
vec3 display(vec3 c) {
  return luxLinearToSrgb(luxAgxMaxRgb(luxGamutMap(c)));
}
void main() {
  vec4 pixel = texelFetch(uHdr, ivec2(gl_FragCoord.xy), 0);
  vec3 scattered = uHasScattered == 1 ? tent(uScattered, vUv, uScatteredTexel) : vec3(0.0);
  vec3 kept = pixel.rgb - (1.0 - uCore) * glareExcess(pixel);
  if (uLinear == 1) {
    fragColor = vec4(kept + scattered, 1.0);
    return;
  }
  if (pixel.a > 0.5) fragColor = vec4(display(kept + scattered), 1.0);
  else fragColor = vec4(min((pixel.a > 0.125 ? pixel.rgb : uBackground) + display(scattered), vec3(1.0)), 1.0);
}
`;
