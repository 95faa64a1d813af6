import type { Rgb, Vec3 } from '../../core/model/lightingScene/lightingScene';
import { fragmentPass, type FragmentPass, type UniformSpec, type UniformType } from '../../../shaders/fragmentPass.glsl';
import { objectTracing } from '../../../shaders/objectTracing.glsl';
import { profileLookup } from '../../../shaders/profileLookup.glsl';
import { glslFloat, glslMat3Transposed, glslVec3 } from './glslFormat';
import type { Mat3 } from './luminaireRotation';
import { profileFunction } from './profileFunction';
import { DATA_TEXTURE_WIDTH, type ProfileLayout } from './profileTable';
import { subsampleAngle } from './subsampleAngle';
import { surfaceFrameGlsl } from './surfaceFrameGlsl';
import { axisVector, type SurfaceLayout } from './surfaceLayout';

/** A luminaire as the direct pass sees it: world sources, rotation, profile, RGB weight per source. */
export interface DirectLamp {
  profile: ProfileLayout;
  rotation: Mat3;
  /** World positions of its point sources. */
  sources: Vec3[];
  /** colour · dimming / number of sources per grid. */
  weight: Rgb;
  /** Per source: −1 only the downward hemisphere (local y < 0), +1 only the upward one, 0 all; absent = all 0. */
  sides?: (-1 | 0 | 1)[];
}

/** The direct pass's one uniform: the profile table (profileTable.ts). */
export const directUniforms = { uProfiles: 'sampler2D' } as const;

/** With objects: the profile table and the objects' BVH (shaders/objectTracing.glsl.ts). */
export const shadowedDirectUniforms = { uProfiles: 'sampler2D', uBvhNodes: 'sampler2D', uBvhTriangles: 'sampler2D' } as const;

const hasSides = (lamp: DirectLamp): boolean => !!lamp.sides && lamp.sides.some((x) => x !== 0);

/** Lamp k's constants: sources, world → local rotation, weight, per-source hemisphere, and (sub-sampling) its centre and radius. */
function lampConstants(lamp: DirectLamp, k: number, subsampled: boolean): string {
  const n = lamp.sources.length;
  const { centre, radius } = lampBounds(lamp);
  return `const vec3 LAMP${k}_SOURCES[${n}] = vec3[${n}](${lamp.sources.map(glslVec3).join(', ')});
const mat3 LAMP${k}_TO_LOCAL = ${glslMat3Transposed(lamp.rotation)};
const vec3 LAMP${k}_WEIGHT = ${glslVec3(lamp.weight)};
${hasSides(lamp) ? `const float LAMP${k}_SIDE[${n}] = float[${n}](${lamp.sides!.map(glslFloat).join(', ')});\n` : ''}${
    subsampled
      ? `const vec3 LAMP${k}_CENTRE = ${glslVec3(centre)};
const float LAMP${k}_RADIUS = ${glslFloat(radius)};
`
      : ''
  }`;
}

/**
 * Largest number of uniform vectors the lamp uniforms of one pass may take. OpenGL ES 3.0 (§6.2,
 * Table 6.20) guarantees MAX_FRAGMENT_UNIFORM_VECTORS ≥ 224; the rest is left to the pass's own
 * uniforms and the driver's. A pass whose lamps need more (many point sources per opening) keeps
 * its lamps as constants.
 */
export const MAX_LAMP_UNIFORM_VECTORS = 192;

/** A lamp uniform's value as runPass sets it (float, vec3, vec3[n]). */
export type LampUniformValue = number | Float32Array;

/** Lamp k's uniforms (name → GLSL type) and their values: what varies when a luminaire moves, turns or dims. */
export interface LampUniforms {
  spec: Record<string, UniformType>;
  values: Record<string, LampUniformValue>;
}

/** Uniform vectors taken by lamp uniforms of `lamps` (vec3[n]: n; the rotation 3; weight, centre, radius 1 each). */
export function lampUniformVectors(lamps: readonly DirectLamp[], subsampled: boolean): number {
  return lamps.reduce((acc, l) => acc + l.sources.length + 4 + (subsampled ? 2 : 0), 0);
}

/** The centre of a lamp's sources and the largest distance of one from it (for texel sub-sampling). */
function lampBounds(lamp: DirectLamp): { centre: Vec3; radius: number } {
  const n = lamp.sources.length;
  const centre = [0, 1, 2].map((a) => lamp.sources.reduce((acc, p) => acc + p[a], 0) / n) as Vec3;
  const radius = Math.max(...lamp.sources.map((p) => Math.hypot(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2])));
  return { centre, radius };
}

/**
 * The uniforms of every lamp of a pass (lampUniforms variant): sources, world → local rotation (its
 * three columns: the columns of Rᵀ are the rows of the row-major R), weight, and with sub-sampling
 * the centre and radius. Names are per lamp index, so the program depends only on how many
 * sources each lamp has, never on where they are.
 */
export function lampUniforms(lamps: readonly DirectLamp[], subsampled: boolean): LampUniforms {
  const spec: Record<string, UniformType> = {};
  const values: Record<string, LampUniformValue> = {};
  lamps.forEach((lamp, k) => {
    spec[`uLamp${k}Sources`] = `vec3[${lamp.sources.length}]`;
    values[`uLamp${k}Sources`] = Float32Array.from(lamp.sources.flat());
    spec[`uLamp${k}ToLocal`] = 'vec3[3]';
    values[`uLamp${k}ToLocal`] = Float32Array.from(lamp.rotation.flat());
    spec[`uLamp${k}Weight`] = 'vec3';
    values[`uLamp${k}Weight`] = Float32Array.from(lamp.weight);
    if (subsampled) {
      const { centre, radius } = lampBounds(lamp);
      spec[`uLamp${k}Centre`] = 'vec3';
      values[`uLamp${k}Centre`] = Float32Array.from(centre);
      spec[`uLamp${k}Radius`] = 'float';
      values[`uLamp${k}Radius`] = radius;
    }
  });
  return { spec, values };
}

/**
 * Lamp k's names bound to its uniforms (lampUniforms), so the source loops read the same names as
 * with constants. A per-source hemisphere stays a constant: it depends only on the opening
 * (openingSources: the bottom grid −1, the top grid +1), like the source count.
 */
function lampUniformNames(lamp: DirectLamp, k: number, subsampled: boolean): string {
  const n = lamp.sources.length;
  return `#define LAMP${k}_SOURCES uLamp${k}Sources
#define LAMP${k}_TO_LOCAL mat3(uLamp${k}ToLocal[0], uLamp${k}ToLocal[1], uLamp${k}ToLocal[2])
#define LAMP${k}_WEIGHT uLamp${k}Weight
${hasSides(lamp) ? `const float LAMP${k}_SIDE[${n}] = float[${n}](${lamp.sides!.map(glslFloat).join(', ')});\n` : ''}${
    subsampled
      ? `#define LAMP${k}_CENTRE uLamp${k}Centre
#define LAMP${k}_RADIUS uLamp${k}Radius
`
      : ''
  }`;
}

/**
 * e += Σ over lamp k's sources of I·cosθ/d² at `point` (CIE 171:2006 §5.2), facing sources only;
 * with `shadowed`, only sources the point sees past the objects (objectTracing.glsl.ts `visibility`).
 */
function sourceLoop(lamp: DirectLamp, k: number, point: string, normal = 'NORMAL', shadowed = false): string {
  const visible = shadowed ? ` && visibility(${point}, ${normal}, LAMP${k}_SOURCES[s]) > 0.0` : '';
  return `for (int s = 0; s < ${lamp.sources.length}; s++) {
      vec3 d = ${point} - LAMP${k}_SOURCES[s];
      float d2 = max(dot(d, d), 1e-12);
      float invD = inversesqrt(d2);
      float cosIncidence = -dot(d, ${normal}) * invD;
      ${
        hasSides(lamp)
          ? `vec3 l = LAMP${k}_TO_LOCAL * (d * invD);
      // A face of a tall opening emits only its own hemisphere.
      if (cosIncidence > 0.0 && LAMP${k}_SIDE[s] * l.y >= 0.0${visible}) e += intensity${lamp.profile.id}(l) * cosIncidence / d2;`
          : `if (cosIncidence > 0.0${visible}) e += intensity${lamp.profile.id}(LAMP${k}_TO_LOCAL * (d * invD)) * cosIncidence / d2;`
      }
    }`;
}

/** lux += lamp k's illuminance: at the texel centre p, or the mean over an n×n grid of cells when the lamp is close (`sub` > 1). */
function lampSum(lamp: DirectLamp, k: number, sub: number, shadowed: boolean): string {
  if (sub <= 1) {
    return `  {
    float e = 0.0;
    ${sourceLoop(lamp, k, 'p', 'NORMAL', shadowed)}
    lux += LAMP${k}_WEIGHT * e;
  }`;
  }
  return `  {
    float e = 0.0;
    float near = max(distance(p, LAMP${k}_CENTRE) - LAMP${k}_RADIUS, 1e-6);
    int n = int(clamp(ceil(TEXEL_DIAGONAL / (near * ${glslFloat(subsampleAngle(lamp.profile))})), 1.0, ${glslFloat(sub)}));
    float inv = 1.0 / float(n);
    for (int sj = 0; sj < n; sj++) {
      for (int si = 0; si < n; si++) {
        vec3 q = p + TEXEL_U * ((float(si) + 0.5) * inv - 0.5) + TEXEL_V * ((float(sj) + 0.5) * inv - 0.5);
        ${sourceLoop(lamp, k, 'q', 'NORMAL', shadowed)}
      }
    }
    lux += LAMP${k}_WEIGHT * (e * inv * inv);
  }`;
}

/**
 * The direct pass for one surface: E = Σ I(γ, C)·cos(incidence)/d² (CIE 171:2006
 * §5.2, the inverse-square cosine law), summed over the point sources of the
 * luminaires that can reach this surface. Everything scene-specific is a
 * compile-time constant.
 *
 * A texel stores the mean illuminance over its area, not the value at its
 * centre: where a luminaire is close (the texel subtends more than
 * subsampleAngle from it), each luminaire's sum is taken over an n×n grid of
 * cell centres in the texel (midpoint rule), n = ⌈texel diagonal / (distance ·
 * subsampleAngle)⌉ ≤ `supersampling`. So the flux that bounces (Σ E·A) and the
 * averages shown stay right at any texel size, even for a hot spot smaller than
 * a texel. `supersampling` = 1 gives the centre value everywhere.
 */
export function generateDirectShader(surface: SurfaceLayout, lamps: DirectLamp[], supersampling = 1, withLampUniforms = false): DirectPass<typeof directUniforms> {
  return directShader(surface, lamps, supersampling, null, withLampUniforms);
}

/**
 * The direct pass of a room surface when the scene has objects: the same sum, each source only
 * where the point (every sub-sample of a texel mean) sees it past the objects, one shadow ray
 * through the objects' BVH per source and point (bvhAnyHit; width `bvhWidth` of its textures).
 */
export function generateShadowedDirectShader(surface: SurfaceLayout, lamps: DirectLamp[], supersampling: number, bvhWidth: number, withLampUniforms = false): DirectPass<typeof shadowedDirectUniforms> {
  return directShader(surface, lamps, supersampling, bvhWidth, withLampUniforms);
}

/** Profile lookups and per-lamp constants of a direct pass (with `asUniforms`, the names bound to lampUniforms instead). */
export function directLampConstants(lamps: DirectLamp[], subsampled: boolean, asUniforms = false): string {
  const profiles = [...new Map(lamps.map((l) => [l.profile.id, l.profile])).values()];
  const lampCode = asUniforms ? lampUniformNames : lampConstants;
  return `${profileLookup({ table: 'uProfiles', dataWidth: DATA_TEXTURE_WIDTH })}
${profiles.map(profileFunction).join('')}
${lamps.map((lamp, k) => lampCode(lamp, k, subsampled)).join('')}`;
}

/**
 * A direct pass with the values of its lamp uniforms when it has them (`lampValues`, to be set
 * with the pass's other uniforms); without, every lamp is a compile-time constant.
 */
export type DirectPass<U extends UniformSpec> = FragmentPass<U> & { lampValues?: Record<string, LampUniformValue> };

/**
 * The pass's uniforms and, when lamp uniforms are asked for and fit (MAX_LAMP_UNIFORM_VECTORS),
 * the lamps' uniforms added after them.
 */
export function withLampSpec<U extends UniformSpec>(base: U, lamps: readonly DirectLamp[], subsampled: boolean, wanted: boolean): { uniforms: U; lamps: LampUniforms | null } {
  if (!wanted || lampUniformVectors(lamps, subsampled) > MAX_LAMP_UNIFORM_VECTORS) return { uniforms: base, lamps: null };
  const u = lampUniforms(lamps, subsampled);
  return { uniforms: { ...base, ...u.spec } as U, lamps: u };
}

/** Σ over every lamp of its illuminance at `point` (normal `normal`), centre values, shadow-tested when `shadowed` (the objects' atlas). */
export function directPointSum(lamps: DirectLamp[], point: string, normal: string, shadowed: boolean): string {
  return lamps
    .map(
      (lamp, k) => `  {
    float e = 0.0;
    ${sourceLoop(lamp, k, point, normal, shadowed)}
    lux += LAMP${k}_WEIGHT * e;
  }`,
    )
    .join('\n');
}

function directShader<U extends typeof directUniforms | typeof shadowedDirectUniforms>(surface: SurfaceLayout, lamps: DirectLamp[], supersampling: number, bvhWidth: number | null, wantLampUniforms: boolean): DirectPass<U> {
  const texelU = surface.lengthU / surface.width;
  const texelV = surface.lengthV / surface.height;
  const sub = Math.max(1, Math.floor(supersampling));
  const profiles = [...new Map(lamps.map((l) => [l.profile.id, l.profile])).values()];
  const shadowed = bvhWidth !== null;
  const spec = withLampSpec((shadowed ? shadowedDirectUniforms : directUniforms) as U, lamps, sub > 1, wantLampUniforms);
  const lampCode = spec.lamps ? lampUniformNames : lampConstants;
  const pass: DirectPass<U> = fragmentPass(
    spec.uniforms,
    `// direct pass, surface ${surface.name}, ${lamps.length} luminaire(s)${sub > 1 ? `, texel means (≤ ${sub}² sub-samples)` : ''}${shadowed ? ', shadowed by objects' : ''}${spec.lamps ? ', lamps as uniforms' : ''}
${profileLookup({ table: 'uProfiles', dataWidth: DATA_TEXTURE_WIDTH })}
${shadowed ? objectTracing(bvhWidth) : ''}${surfaceFrameGlsl(surface)}${
      sub > 1
        ? `const vec3 TEXEL_U = ${glslVec3(axisVector(surface.uAxisIndex, texelU))};
const vec3 TEXEL_V = ${glslVec3(axisVector(surface.vAxisIndex, texelV))};
const float TEXEL_DIAGONAL = ${glslFloat(Math.hypot(texelU, texelV))};
`
        : ''
    }${profiles.map(profileFunction).join('')}
${lamps.map((lamp, k) => lampCode(lamp, k, sub > 1)).join('')}
out vec4 outColor;
void main() {
  vec2 uv = gl_FragCoord.xy / RESOLUTION;
  vec3 p = ORIGIN + U_AXIS * uv.x + V_AXIS * uv.y;
  vec3 lux = vec3(0.0);
${lamps.map((lamp, k) => lampSum(lamp, k, sub, shadowed)).join('\n')}
  outColor = vec4(lux, 1.0);
}
`,
  );
  if (spec.lamps) pass.lampValues = spec.lamps.values;
  return pass;
}
