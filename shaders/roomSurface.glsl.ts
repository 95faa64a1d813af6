import { falseColorGlsl, type FalseColorScaleFacts } from './falseColor.glsl';
import { toneMapGlsl } from './toneMap.glsl';
import { spotPreviewGlsl, type CandelaGridFacts } from './spotPreview.glsl';

/** A room surface's vertex shader (three.js GLSL3 material): the light map's uv and the world position (for the view angle). */
export const roomSurfaceVertex = /* glsl */ `
out vec2 vUv;
out vec3 vWorld;
void main() {
  vUv = uv;
  vWorld = (modelMatrix * vec4(position, 1.0)).xyz;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
`;

/**
 * A room surface's fragment shader: stored illuminance E (RGB lux) →
 * luminance ρE/π → display (toneMap.glsl.ts), or false-colour lux
 * (uMode 1). In light mode ρ is modulated by the finish's pattern m (uFinish, tiled
 * uFinishRepeat times over the surface, mean 1: docs/viewer.md, "Surface textures"). In lux mode the isolines follow E averaged over the 4×4 texels
 * around the point (four bilinear taps one texel off diagonally): the fill
 * keeps every texel's value, the lines do not wiggle with the noise of the
 * indirect light (falseColor.glsl.ts). `scale` is the false-colour scale's
 * facts (falseColorScale.ts), passed on to the false-colour chunk. With `preview` (the candela
 * grid's size), one aimed lamp's direct light is added per fragment (spotPreview.glsl.ts, docs/aiming.md).
 */
export const roomSurfaceFragment = (scale: FalseColorScaleFacts, preview?: CandelaGridFacts): string => /* glsl */ `
precision highp float;
in vec2 vUv;
in vec3 vWorld;
uniform sampler2D uIlluminance;
uniform vec3 uNormal;
uniform vec3 uReflectance;
uniform float uExposure;
uniform mat3 uAdapt;
uniform int uMode;
uniform sampler2D uFinish;
uniform vec3 uFinishGain;
uniform vec2 uFinishRepeat;
uniform float uFinishOn;
out vec4 fragColor;
${toneMapGlsl}
${falseColorGlsl(scale)}
${preview ? spotPreviewGlsl(preview) : ''}
void main() {
  vec3 E = max(texture(uIlluminance, vUv).rgb, 0.0);${preview ? '\n  E += spotPreviewE(vWorld, uNormal);' : ''}
  if (uMode == 1) {
    const vec3 Y = vec3(0.2126, 0.7152, 0.0722);
    vec2 t = 1.0 / vec2(textureSize(uIlluminance, 0));
    vec3 Es = texture(uIlluminance, vUv + vec2(t.x, t.y)).rgb + texture(uIlluminance, vUv + vec2(-t.x, t.y)).rgb
            + texture(uIlluminance, vUv + vec2(t.x, -t.y)).rgb + texture(uIlluminance, vUv - t).rgb;${preview ? '\n    Es += 4.0 * spotPreviewE(vWorld, uNormal);' : ''}
    float facing = abs(dot(uNormal, normalize(cameraPosition - vWorld)));
    fragColor = vec4(luxFalseColor(dot(E, Y), max(dot(Es, Y), 0.0) * 0.25, facing), 1.0);
  } else {
    // The finish's pattern m (mean exactly 1, finishTexture.ts) around the baked reflectance: light mode only.
    vec3 m = uFinishOn > 0.5 ? texture(uFinish, vUv * uFinishRepeat).rgb * uFinishGain : vec3(1.0);
    vec3 L = uReflectance * m * E / 3.14159265358979;
    fragColor = vec4(luxShade(L, uExposure, uAdapt, uMode), 1.0);
  }
}
`;
