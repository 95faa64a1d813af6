import { SURFACE_NAMES, type Rgb, type Vec3 } from '../../core/model/lightingScene';
import { fragmentPass, type FragmentPass } from '../../../shaders/fragmentPass.glsl';
import { rayBox } from '../../../shaders/rayBox.glsl';
import { sampling } from '../../../shaders/sampling.glsl';
import { glslVec3 } from './glslFormat';
import { surfaceFrameGlsl } from './surfaceFrameGlsl';
import { axisVector, SURFACE_FRAMES, type SurfaceLayout } from './surfaceLayout';

/**
 * The gather pass's uniforms. uSource<s>: what surface s emits this bounce
 * (declared for all six; those the pass never samples are optimised away).
 * Integers are passed as int: headless-gl 9 silently ignores uniform1ui
 * (measured), and uint(int) keeps the bit pattern, so seeds above 2^31 survive.
 */
export const gatherUniforms = {
  uSource0: 'sampler2D',
  uSource1: 'sampler2D',
  uSource2: 'sampler2D',
  uSource3: 'sampler2D',
  uSource4: 'sampler2D',
  uSource5: 'sampler2D',
  /** This surface's samples so far (the other half of its ping-pong pair). */
  uAccumulated: 'sampler2D',
  /** Bounce 1 only: the exact illuminance from the bright patches (runBrightPatchPass.ts), added once per sample with weight uBrightWeight. */
  uBright: 'sampler2D',
  uBrightWeight: 'float',
  uFirstSample: 'int',
  uSampleCount: 'int',
  /** 1/S when the input is the previous bounce's sum of S samples, 1 for the direct maps. */
  uInputScale: 'float',
  uSeed: 'int',
} as const;

const AXIS_NAME = ['x', 'y', 'z'];

/**
 * `exitance(origin, dir)`: the light leaving the point where a ray from inside
 * the room exits it, ρ·E of the surface hit, one branch per reflecting surface
 * other than the receiver. Which wall a ray hits and where in its map follow
 * from the same SURFACE_FRAMES as the layouts; branches in the order of the
 * hit axis (x, y, z), min side first.
 */
function exitanceFunction(receiver: number, reflectance: Rgb[]): string {
  const hit = SURFACE_NAMES.map((name, index) => {
    const [u, v, axis, onMax] = SURFACE_FRAMES[name];
    return { index, u: AXIS_NAME[u], v: AXIS_NAME[v], axis, onMax };
  })
    .filter((t) => t.index !== receiver && reflectance[t.index].some((r) => r > 0))
    .sort((a, b) => a.axis - b.axis || Number(a.onMax) - Number(b.onMax));
  const constants = hit.map((t) => `const vec3 RHO${t.index} = ${glslVec3(reflectance[t.index])};\n`).join('');
  const branches = hit
    .map(
      (t) =>
        `  if (axis == ${t.axis} && dir.${AXIS_NAME[t.axis]} ${t.onMax ? '>' : '<'} 0.0) return RHO${t.index} * texture(uSource${t.index}, vec2(hit.${t.u}, hit.${t.v}) / vec2(ROOM.${t.u}, ROOM.${t.v})).rgb;\n`,
    )
    .join('');
  return `// sampling ${hit.length} reflecting surface(s)
${constants}vec3 exitance(vec3 origin, vec3 dir) {
  int axis;
  float t = rayExit(origin, dir, ROOM, axis);
  vec3 hit = clamp(origin + t * dir, vec3(0.0), ROOM);
${branches}  return vec3(0.0);
}
`;
}

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
 * an accumulation map, so a bounce can be spread over many frames.
 */
export function generateGatherShader(surface: SurfaceLayout, room: Vec3, reflectance: Rgb[]): FragmentPass<typeof gatherUniforms> {
  return fragmentPass(
    gatherUniforms,
    `// gather pass, surface ${surface.name}
const vec3 ROOM = ${glslVec3(room)};
${surfaceFrameGlsl(surface)}const vec3 TANGENT = ${glslVec3(axisVector(surface.uAxisIndex, 1))};
const vec3 BITANGENT = ${glslVec3(axisVector(surface.vAxisIndex, 1))};
${sampling}
${rayBox}
${exitanceFunction(surface.index, reflectance)}out vec4 outColor;
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
`,
  );
}
