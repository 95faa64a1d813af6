import type { Rgb, Vec3 } from '../../core/model/lightingScene';
import { fragmentHeader } from '../../../shaders/fullscreen.glsl';
import { rayBox } from '../../../shaders/rayBox.glsl';
import { sampling } from '../../../shaders/sampling.glsl';
import { glslFloat, glslVec3 } from './glslFormat';
import type { SurfaceLayout } from './surfaceLayout';

/**
 * The indirect ("gather") pass for one receiving surface, the configurator paper's
 * reverse path tracing (§3.1): from each texel centre, cosine-weighted
 * directions; the analytic exit point of the box; the light leaving that
 * point, read from the previous bounce's maps. With exitance M = ρ·E of a
 * Lambertian surface and cosine-weighted sampling (pdf cosθ/π),
 * E_in = ∫ (M/π) cosθ dω = mean(M(hit)) — the π cancels (Pharr et al.,
 * PBRT 3rd ed. §13.6.3).
 *
 * Only surfaces with non-zero reflectance are sampled; the receiving surface
 * itself is never (a ray leaving a plane cannot return to it). Samples add to
 * an accumulation map, so a bounce can be spread over many frames; the
 * previous bounce's accumulation (S samples) is read with uInputScale = 1/S.
 * For bounce 1 the sampled maps may be residual direct maps with the bright
 * patches cut out; their light is added exactly from uBright (brightPatches.ts).
 */
export function generateGatherShader(
  surface: SurfaceLayout,
  room: Vec3,
  reflectance: Rgb[],
): string {
  const uAxis: Vec3 = [0, 0, 0];
  uAxis[surface.uAxisIndex] = surface.lengthU;
  const vAxis: Vec3 = [0, 0, 0];
  vAxis[surface.vAxisIndex] = surface.lengthV;
  const tangent: Vec3 = [0, 0, 0];
  tangent[surface.uAxisIndex] = 1;
  const bitangent: Vec3 = [0, 0, 0];
  bitangent[surface.vAxisIndex] = 1;
  // Hit surfaces: [surface index, hit axis, on the max side], lookup coordinates from its layout.
  const targets = [
    { index: 4, axis: 0, max: false, u: 'z', v: 'y' },
    { index: 5, axis: 0, max: true, u: 'z', v: 'y' },
    { index: 0, axis: 1, max: false, u: 'x', v: 'z' },
    { index: 1, axis: 1, max: true, u: 'x', v: 'z' },
    { index: 2, axis: 2, max: false, u: 'x', v: 'y' },
    { index: 3, axis: 2, max: true, u: 'x', v: 'y' },
  ].filter((t) => t.index !== surface.index && reflectance[t.index].some((r) => r > 0));
  const axisName = ['x', 'y', 'z'];
  const branches = targets
    .map(
      (t) =>
        `  if (axis == ${t.axis} && dir.${axisName[t.axis]} ${t.max ? '>' : '<'} 0.0) return RHO${t.index} * texture(uSource${t.index}, vec2(hit.${t.u}, hit.${t.v}) / vec2(ROOM.${t.u}, ROOM.${t.v})).rgb;`,
    )
    .join('\n');
  const samplers = targets.map((t) => `uniform sampler2D uSource${t.index};\nconst vec3 RHO${t.index} = ${glslVec3(reflectance[t.index])};`).join('\n');
  return `${fragmentHeader}
// gather pass, surface ${surface.name}, sampling ${targets.length} reflecting surface(s)
const vec3 ROOM = ${glslVec3(room)};
const vec3 ORIGIN = ${glslVec3(surface.origin)};
const vec3 U_AXIS = ${glslVec3(uAxis)};
const vec3 V_AXIS = ${glslVec3(vAxis)};
const vec3 NORMAL = ${glslVec3(surface.normal)};
const vec3 TANGENT = ${glslVec3(tangent)};
const vec3 BITANGENT = ${glslVec3(bitangent)};
const vec2 RESOLUTION = vec2(${glslFloat(surface.width)}, ${glslFloat(surface.height)});
${samplers}
uniform sampler2D uAccumulated;
// Integers passed as int: headless-gl 9 silently ignores uniform1ui (measured), and
// uint(int) keeps the bit pattern, so seeds above 2^31 survive.
uniform int uFirstSample;
uniform int uSampleCount;
uniform float uInputScale;
uniform int uSeed;
// Bounce 1 only: the exact illuminance from the bright patches (brightPatches.ts), once per sample.
uniform sampler2D uBright;
uniform float uBrightWeight;
${sampling}
${rayBox}
vec3 exitance(vec3 origin, vec3 dir) {
  int axis;
  float t = rayExit(origin, dir, axis);
  vec3 hit = clamp(origin + t * dir, vec3(0.0), ROOM);
${branches}
  return vec3(0.0);
}
out vec4 outColor;
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec2 uv = gl_FragCoord.xy / RESOLUTION;
  vec3 p = ORIGIN + U_AXIS * uv.x + V_AXIS * uv.y;
  uint h = hash32(uint(texel.x) ^ hash32(uint(texel.y) ^ hash32(uint(uSeed))));
  uvec2 rotation = uvec2(h, hash32(h + 0x9e3779b9u));
  vec3 sum = vec3(0.0);
  for (int k = 0; k < uSampleCount; k++) {
    vec3 dir = cosineDirection(r2Sample(uint(uFirstSample + k), rotation), NORMAL, TANGENT, BITANGENT);
    sum += exitance(p, dir);
  }
  vec3 bright = uBrightWeight > 0.0 ? uBrightWeight * float(uSampleCount) * texelFetch(uBright, texel, 0).rgb : vec3(0.0);
  outColor = vec4(texelFetch(uAccumulated, texel, 0).rgb + sum * uInputScale + bright, 1.0);
}
`;
}
