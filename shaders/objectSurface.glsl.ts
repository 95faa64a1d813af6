import { falseColorGlsl, type FalseColorScaleFacts } from './falseColor.glsl';
import { toneMapGlsl } from './toneMap.glsl';

/**
 * The objects' vertex shader (three.js GLSL3 material): world-space triangles (no model
 * transform beyond the identity the view gives them), the light-map atlas uv, the front normal
 * and the object's index (for the selection highlight).
 */
export const objectSurfaceVertex = /* glsl */ `
in float objectIndex;
out vec2 vUv;
out vec3 vWorld;
out vec3 vNormal;
flat out float vObject;
void main() {
  vUv = uv;
  vWorld = (modelMatrix * vec4(position, 1.0)).xyz;
  vNormal = normalize(mat3(modelMatrix) * normal);
  vObject = objectIndex;
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
`;

/**
 * The objects' fragment shader: the same display transform as the room's surfaces
 * (roomSurface.glsl.ts) on the objects' atlas. E (RGB lux) is sampled from the atlas with the
 * uv the baker rasterised it with (bilinear: the baker dilates each chart two texels into its
 * gutter, so taps at a chart border never read an empty texel); ρ comes from the atlas
 * G-buffer's reflectance, nearest texel (a material boundary inside a chart is as sharp as one
 * texel); luminance L = ρ·E/π per channel → exposure → adaptation → PBR Neutral → sRGB, or false-colour lux of
 * Y(E). The back of a surface is dark (the baker lights only the counterclockwise side; closed
 * meshes never show it). The isolines follow E itself (no 4-tap smoothing as on the walls: the
 * taps would cross into a neighbouring chart's gutter). The selected object (uSelected = its
 * index, −1 = none) is tinted towards the UI accent. In light mode a texel whose ρ is one of
 * the textured object finishes' (uSlotRho, createRoomObjects.ts) is modulated by that finish's
 * pattern m (mean exactly 1, finishTexture.ts), so the mean displayed reflectance stays the ρ the
 * baker used (docs/viewer.md, "Surface textures"). The pattern is projected on the plane the face
 * turns to most (world metres): tops and seats show it in x, z; upright faces with u along y, so
 * the grain of legs and sides runs up.
 */
export const objectSurfaceFragment = (scale: FalseColorScaleFacts): string => /* glsl */ `
precision highp float;
in vec2 vUv;
in vec3 vWorld;
in vec3 vNormal;
flat in float vObject;
uniform sampler2D uIlluminance;
uniform sampler2D uReflectance;
uniform float uExposure;
uniform mat3 uAdapt;
uniform int uMode;
uniform float uSelected;
uniform sampler2D uSlot0;
uniform sampler2D uSlot1;
uniform vec3 uSlotRho[2];
uniform vec3 uSlotGain[2];
uniform float uSlotPeriod[2];
uniform float uSlotOn[2];
// Objects with an index below this are a shaped room's surfaces (engines/bake/shapedRoom): seen from outside they are not drawn, as the box's walls are culled.
uniform float uFrontOnlyBelow;
out vec4 fragColor;
${toneMapGlsl}
${falseColorGlsl(scale)}
void main() {
  if (!gl_FrontFacing && vObject < uFrontOnlyBelow) discard;
  vec3 E = gl_FrontFacing ? max(texture(uIlluminance, vUv).rgb, 0.0) : vec3(0.0);
  ivec2 size = textureSize(uReflectance, 0);
  ivec2 texel = clamp(ivec2(floor(vUv * vec2(size))), ivec2(0), size - 1);
  vec3 rho = texelFetch(uReflectance, texel, 0).rgb;
  vec3 color;
  if (uMode == 1) {
    const vec3 Y = vec3(0.2126, 0.7152, 0.0722);
    float facing = abs(dot(normalize(vNormal), normalize(cameraPosition - vWorld)));
    float lux = dot(E, Y);
    color = luxFalseColor(lux, lux, facing);
  } else {
    vec3 n = abs(vNormal);
    vec2 st = n.y >= max(n.x, n.z) ? vWorld.xz : (n.x >= n.z ? vWorld.yz : vWorld.yx);
    // Both patterns sampled outside the branch: implicit mip derivatives are undefined in non-uniform control flow.
    vec3 m0 = texture(uSlot0, st / uSlotPeriod[0]).rgb * uSlotGain[0];
    vec3 m1 = texture(uSlot1, st / uSlotPeriod[1]).rgb * uSlotGain[1];
    vec3 m = vec3(1.0);
    if (uSlotOn[0] > 0.5 && all(lessThan(abs(rho - uSlotRho[0]), vec3(1e-4)))) m = m0;
    else if (uSlotOn[1] > 0.5 && all(lessThan(abs(rho - uSlotRho[1]), vec3(1e-4)))) m = m1;
    color = luxShade(rho * m * E / 3.14159265358979, uExposure, uAdapt, uMode);
  }
  if (abs(vObject - uSelected) < 0.5) color = mix(color, vec3(0.16, 0.56, 0.98), 0.3);
  fragColor = vec4(color, 1.0);
}
`;
