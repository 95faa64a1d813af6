import { SURFACE_NAMES, type Rgb, type Vec3 } from '../../core/model/lightingScene/lightingScene';
import { fragmentPass, type FragmentPass } from '../../../shaders/fragmentPass.glsl';
import { objectTracing, SURFACE_OFFSET } from '../../../shaders/objectTracing.glsl';
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

/**
 * With objects, every gather pass also reads the objects' atlas: uSource6 is what the atlas emits
 * this bounce (as E; times uObjectRho, the G-buffer's ρ, it is the exitance), the BVH, and for
 * the atlas receiver its G-buffer points (a = coverage) and normals.
 */
export const objectGatherUniforms = {
  ...gatherUniforms,
  uSource6: 'sampler2D',
  uObjectRho: 'sampler2D',
  uBvhNodes: 'sampler2D',
  uBvhTriangles: 'sampler2D',
  uPoints: 'sampler2D',
  uNormals: 'sampler2D',
} as const;

/** What a gather pass needs to know of the objects. */
export interface GatherObjects {
  /** Width of the BVH textures (objects/preparedObjects.ts ObjectBvhTextures). */
  bvhWidth: number;
  atlasWidth: number;
  atlasHeight: number;
}

const AXIS_NAME = ['x', 'y', 'z'];

/**
 * `exitance(origin, dir)`: the light leaving the point where a ray from inside
 * the room exits it, ρ·E of the surface hit, one branch per reflecting surface
 * other than the receiver. Which wall a ray hits and where in its map follow
 * from the same SURFACE_FRAMES as the layouts; branches in the order of the
 * hit axis (x, y, z), min side first.
 */
function exitanceFunction(receiver: number, reflectance: Rgb[], objects: GatherObjects | null = null): string {
  const hit = SURFACE_NAMES.map((name, index) => {
    const [u, v, axis, onMax] = SURFACE_FRAMES[name];
    return { index, u: AXIS_NAME[u], v: AXIS_NAME[v], axis, onMax };
  })
    .filter((t) => t.index !== receiver && reflectance[t.index].some((r) => r > 0))
    .sort((a, b) => a.axis - b.axis || Number(a.onMax) - Number(b.onMax));
  const constants = hit.map((t) => `const vec3 RHO${t.index} = ${glslVec3(reflectance[t.index])};\n`).join('');
  const branches = hit
    .map((t) => `  if (axis == ${t.axis} && dir.${AXIS_NAME[t.axis]} ${t.onMax ? '>' : '<'} 0.0) return RHO${t.index} * texture(uSource${t.index}, vec2(hit.${t.u}, hit.${t.v}) / vec2(ROOM.${t.u}, ROOM.${t.v})).rgb;\n`)
    .join('');
  // With objects the ray ends at the nearer of the box exit and the first object hit; an object
  // emits ρ·E of the atlas texel hit (nearest texel, so no empty neighbour darkens hits near a
  // chart's border), nothing from its back face (which still blocks). A hit in a texel whose
  // coverage is 0 (a sliver of the chart too thin to count) reads the first covered texel of its
  // 3×3 neighbourhood: charts are ≥ 2 texels apart, so that texel is of the same chart.
  const objectHit = objects
    ? `  float tObject;
  vec2 atlasUv;
  bool frontFace;
  if (bvhClosestHit(origin, dir, t, tObject, atlasUv, frontFace)) {
    if (!frontFace) return vec3(0.0);
    ivec2 last = ivec2(ATLAS_SIZE) - 1;
    ivec2 texel = clamp(ivec2(atlasUv * ATLAS_SIZE), ivec2(0), last);
    if (texelFetch(uPoints, texel, 0).a <= 0.0) {
      ivec2 centre = texel;
      for (int k = 0; k < 9; k++) {
        ivec2 q = clamp(centre + ivec2(k % 3 - 1, k / 3 - 1), ivec2(0), last);
        if (texelFetch(uPoints, q, 0).a > 0.0) {
          texel = q;
          break;
        }
      }
    }
    return texelFetch(uObjectRho, texel, 0).rgb * texelFetch(uSource6, texel, 0).rgb;
  }
`
    : '';
  return `// sampling ${hit.length} reflecting surface(s)${objects ? ' and the objects' : ''}
${constants}vec3 exitance(vec3 origin, vec3 dir) {
  int axis;
  float t = rayExit(origin, dir, ROOM, axis);
${objectHit}  vec3 hit = clamp(origin + t * dir, vec3(0.0), ROOM);
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
${exitanceFunction(surface.index, reflectance)}${gatherMain(
      `  vec2 uv = gl_FragCoord.xy / RESOLUTION;
  vec3 p = ORIGIN + U_AXIS * uv.x + V_AXIS * uv.y;
`,
      { normal: 'NORMAL', tangent: 'TANGENT', bitangent: 'BITANGENT' },
    )}`,
  );
}

/** Constants and functions every object-aware gather pass shares. */
function objectGatherHead(room: Vec3, receiver: number, reflectance: Rgb[], objects: GatherObjects): string {
  return `const vec3 ROOM = ${glslVec3(room)};
const vec2 ATLAS_SIZE = vec2(${objects.atlasWidth}.0, ${objects.atlasHeight}.0);
${sampling}
${rayBox}
${objectTracing(objects.bvhWidth)}${exitanceFunction(receiver, reflectance, objects)}`;
}

/**
 * Every gather pass's `main`: `setup` (GLSL statements after `texel` is declared) defines the
 * receiving point p and may define its frame; then the one sample loop: cosine-weighted directions
 * about `frame` (GLSL names of the unit normal, tangent and bitangent), the light leaving where
 * each ray ends, the bright-patch light of bounce 1, added to the samples so far.
 */
function gatherMain(setup: string, frame: { normal: string; tangent: string; bitangent: string }): string {
  return `out vec4 outColor;
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
${setup}  uint h = hash32(uint(texel.x) ^ hash32(uint(texel.y) ^ hash32(uint(uSeed))));
  uvec2 rotation = uvec2(h, hash32(h + 0x9e3779b9u));
  vec3 sum = vec3(0.0);
  for (int k = 0; k < uSampleCount; k++) {
    vec3 dir = cosineDirection(r2Sample(uint(uFirstSample + k), rotation), ${frame.normal}, ${frame.tangent}, ${frame.bitangent});
    sum += exitance(p, dir);
  }
  vec3 bright = uBrightWeight > 0.0 ? uBrightWeight * float(uSampleCount) * texelFetch(uBright, texel, 0).rgb : vec3(0.0);
  outColor = vec4(texelFetch(uAccumulated, texel, 0).rgb + sum * uInputScale + bright, 1.0);
}
`;
}

/** The frame of the object-aware passes: local variables their setup defines. */
const LOCAL_FRAME = { normal: 'n', tangent: 'tangent', bitangent: 'bitangent' };

/**
 * The gather pass of a room surface in a scene with objects: as generateGatherShader, but each
 * ray ends at the nearer of the box exit and the first object hit (bvhClosestHit), and rays start
 * SURFACE_OFFSET off the wall (an object resting on the wall or floor is not missed).
 */
export function generateObjectAwareGatherShader(surface: SurfaceLayout, room: Vec3, reflectance: Rgb[], objects: GatherObjects): FragmentPass<typeof objectGatherUniforms> {
  return fragmentPass(
    objectGatherUniforms,
    `// gather pass, surface ${surface.name}, with objects
${surfaceFrameGlsl(surface)}${objectGatherHead(room, surface.index, reflectance, objects)}${gatherMain(
      `  vec2 uv = gl_FragCoord.xy / RESOLUTION;
  vec3 n = NORMAL;
  vec3 tangent = ${glslVec3(axisVector(surface.uAxisIndex, 1))};
  vec3 bitangent = ${glslVec3(axisVector(surface.vAxisIndex, 1))};
  vec3 p = ORIGIN + U_AXIS * uv.x + V_AXIS * uv.y + n * ${SURFACE_OFFSET.toExponential()};
`,
      LOCAL_FRAME,
    )}`,
  );
}

/**
 * The gather pass of the objects' atlas: per covered texel, its G-buffer point and normal, an
 * orthonormal frame about the normal (Duff et al., "Building an Orthonormal Basis, Revisited",
 * JCGT 2017), rays from p + n·SURFACE_OFFSET that end at the box (all six walls can be hit) or at
 * an object. Empty texels keep 0.
 */
export function generateObjectGatherShader(room: Vec3, reflectance: Rgb[], objects: GatherObjects): FragmentPass<typeof objectGatherUniforms> {
  return fragmentPass(
    objectGatherUniforms,
    `// gather pass, objects' atlas
${objectGatherHead(room, -1, reflectance, objects)}${gatherMain(
      `  vec4 point = texelFetch(uPoints, texel, 0);
  if (point.a <= 0.0) {
    outColor = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  vec3 n = normalize(texelFetch(uNormals, texel, 0).xyz);
  float sgn = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (sgn + n.z);
  float b = n.x * n.y * a;
  vec3 tangent = vec3(1.0 + sgn * n.x * n.x * a, sgn * b, -sgn * n.x);
  vec3 bitangent = vec3(b, sgn + n.y * n.y * a, -n.y);
  vec3 p = clamp(point.xyz + n * ${SURFACE_OFFSET.toExponential()}, vec3(0.0), ROOM);
`,
      LOCAL_FRAME,
    )}`,
  );
}
