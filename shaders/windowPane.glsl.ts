import { toneMapGlsl } from './toneMap.glsl';

/** A window pane: world position for the view direction, uv for the frame band. */
export const windowPaneVertex = /* glsl */ `
out vec3 vWorld;
out vec2 vUv;
void main() {
  vUv = uv;
  vec4 world = modelMatrix * vec4(position, 1.0);
  vWorld = world.xyz;
  gl_Position = projectionMatrix * viewMatrix * world;
}
`;

/**
 * What a window shows (issue 30, docs/daylight.md "Windows in the 3D view"): the luminance outside
 * along the view ray through the pane, times the glazing's transmittance at that incidence, through
 * the display transform of every surface (toneMap.glsl.ts; uMode 2: the glare pass's HDR value).
 * Outside: the sky above the horizon, CIE standard overcast (uSky 1, L_z (1 + 2 sin θ) / 3) or a
 * CIE general sky (uSky 2: L_z f(χ) φ(Z) / (f(Z_s) φ(0)), φ(Z) = 1 + a exp(b / cos Z),
 * f(χ) = 1 + c (exp(dχ) − exp(dπ/2)) + e cos²χ, CIE S 011; the uniform sky is a = c = e = 0), the
 * ground's uGround below; uSky 0 is the night sky, uNight everywhere. Glass: τ(θ) = τ_n (1 − f)
 * τ_N(θ) / τ_N(0), τ_N the Fresnel transmittance of N clear panes with inter-reflections
 * (n = 1.526; Duffie & Beckman eqs. 5.1.1–5.1.8; glazing.ts), or τ_n (1 − f) for an opening
 * without glass. The frame: a band of uFrameWidth metres drawn at uFrameGrey of middle grey at
 * the exposure in force, so a window reads as one at night too; a drawing aid, not light (the
 * view has no light map for it). Lux mode (uMode 1) shows the frame and a dark pane (no map).
 */
export const windowPaneFragment = /* glsl */ `
precision highp float;
in vec3 vWorld;
in vec2 vUv;
uniform int uSky;
uniform float uZenith;
uniform vec3 uGradation;
uniform vec3 uIndicatrix;
uniform vec3 uSun;
uniform float uGround;
uniform float uNight;
uniform float uTransmittance;
uniform float uPanes;
uniform vec3 uOutward;
uniform vec2 uSize;
uniform float uFrameWidth;
uniform float uFrameGrey;
uniform float uExposure;
uniform mat3 uAdapt;
uniform int uMode;
out vec4 fragColor;
${toneMapGlsl}
const float PI = 3.141592653589793;
const float GLASS_N = 1.526;

float glassPanes(float c, float panes) {
  float k = 2.0 * panes - 1.0;
  if (c >= 0.999999) {
    float r = pow((GLASS_N - 1.0) / (GLASS_N + 1.0), 2.0);
    return (1.0 - r) / (1.0 + k * r);
  }
  if (c <= 0.0) return 0.0;
  float t1 = acos(c);
  float t2 = asin(sin(t1) / GLASS_N);
  float rPerp = pow(sin(t2 - t1), 2.0) / pow(sin(t2 + t1), 2.0);
  float rPar = pow(tan(t2 - t1), 2.0) / pow(tan(t2 + t1), 2.0);
  return 0.5 * ((1.0 - rPar) / (1.0 + k * rPar) + (1.0 - rPerp) / (1.0 + k * rPerp));
}

float transmittance(float cosIncidence) {
  if (uPanes < 0.5) return uTransmittance;
  return uTransmittance * glassPanes(cosIncidence, uPanes) / glassPanes(1.0, uPanes);
}

float indicatrix(float chi, float cosChi) {
  return 1.0 + uIndicatrix.x * (exp(uIndicatrix.y * chi) - exp(uIndicatrix.y * PI / 2.0)) + uIndicatrix.z * cosChi * cosChi;
}

float outside(vec3 d) {
  if (uSky == 0) return uNight;
  if (d.y <= 0.0) return uGround;
  if (uSky == 1) return uZenith * (1.0 + 2.0 * d.y) / 3.0;
  float cosChi = clamp(dot(d, uSun), -1.0, 1.0);
  // uGradation.z = 1 / (f(Z_s) φ(0)), computed with the sky (windowPaneUniforms.ts).
  return uZenith * indicatrix(acos(cosChi), cosChi) * (1.0 + uGradation.x * exp(uGradation.y / d.y)) * uGradation.z;
}

void main() {
  vec2 metres = vUv * uSize;
  bool frame = min(min(metres.x, uSize.x - metres.x), min(metres.y, uSize.y - metres.y)) < uFrameWidth;
  if (frame) {
    float grey = uMode == 1 ? 0.55 : 0.0;
    fragColor = uMode == 1 ? vec4(vec3(grey), 1.0) : vec4(luxShade(vec3(uFrameGrey * 0.18 / uExposure), uExposure, uAdapt, uMode), 1.0);
    return;
  }
  if (uMode == 1) {
    fragColor = vec4(vec3(0.12), 1.0);
    return;
  }
  vec3 d = normalize(vWorld - cameraPosition);
  float L = outside(d) * transmittance(max(dot(d, uOutward), 0.0));
  fragColor = vec4(luxShade(vec3(L), uExposure, uAdapt, uMode), 1.0);
}
`;
