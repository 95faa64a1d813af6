import { toneMapGlsl } from './toneMap.glsl';

/**
 * The luminaires and the track (three.js GLSL3 material; docs/viewer.md, "Luminaires"). Two roles:
 * - a surface (housing, rail, cable: uEmitter 0) of reflectance uReflectance lit by the room's mean
 *   illuminance uAmbient (RGB lux, area-weighted over the six surfaces): L = ρ·E/π, with a ±20 %
 *   directional term so the facets of a head read as facets (an approximation: the luminaires are
 *   not part of the light solution);
 * - an emitter (uEmitter 1): its luminance uLuminance (cd/m², linear RGB, already × dimming × colour).
 * Both go through the room's display transform (toneMap.glsl.ts) with the room's uniforms
 * (exposure, adaptation, mode). In lux mode (uMode 1), or when uFlat is 1 (the selection), the
 * part is drawn in its flat sRGB colour uColor with the facet shading: no glow.
 * `linear`: write adapt·(L·exposure), the value before the tone curve (for tests on a float target).
 */
export const luminaireVertex = /* glsl */ `
out vec3 vNormal;
void main() {
  vNormal = normalize(mat3(modelMatrix) * normal);
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
`;

export const luminaireFragment = (options: { linear?: boolean } = {}): string => /* glsl */ `
precision highp float;
in vec3 vNormal;
uniform float uExposure;
uniform mat3 uAdapt;
uniform int uMode;
uniform int uEmitter;
uniform int uFlat;
uniform vec3 uColor;
uniform vec3 uReflectance;
uniform vec3 uAmbient;
uniform vec3 uLuminance;
out vec4 fragColor;
${toneMapGlsl}
void main() {
  vec3 n = normalize(gl_FrontFacing ? vNormal : -vNormal);
  float facet = 0.8 + 0.2 * dot(n, vec3(0.267, 0.535, 0.802));
  if (uMode == 1 || uFlat == 1) {
    // In the glare pass's HDR target (uMode 2) a flat colour is display-referred: alpha ¼ says so (glarePass.glsl.ts).
    fragColor = vec4(uColor * (0.55 + 0.45 * facet), uMode == 2 ? 0.25 : 1.0);
    return;
  }
  vec3 L = uEmitter == 1 ? uLuminance : uReflectance * max(uAmbient, 0.0) / 3.14159265358979 * facet;
  ${options.linear ? 'fragColor = vec4(uAdapt * (L * uExposure), 1.0);' : 'fragColor = vec4(luxShade(L, uExposure, uAdapt, uMode), 1.0);'}
}
`;
