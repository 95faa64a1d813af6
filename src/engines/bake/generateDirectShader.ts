import type { Rgb, Vec3 } from '../../core/model/lightingScene';
import { fragmentPass, type FragmentPass } from '../../../shaders/fragmentPass.glsl';
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
  const centre = [0, 1, 2].map((a) => lamp.sources.reduce((acc, p) => acc + p[a], 0) / n) as Vec3;
  const radius = Math.max(...lamp.sources.map((p) => Math.hypot(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2])));
  return `const vec3 LAMP${k}_SOURCES[${n}] = vec3[${n}](${lamp.sources.map(glslVec3).join(', ')});
const mat3 LAMP${k}_TO_LOCAL = ${glslMat3Transposed(lamp.rotation)};
const vec3 LAMP${k}_WEIGHT = ${glslVec3(lamp.weight)};
${hasSides(lamp) ? `const float LAMP${k}_SIDE[${n}] = float[${n}](${lamp.sides!.map(glslFloat).join(', ')});\n` : ''}${subsampled ? `const vec3 LAMP${k}_CENTRE = ${glslVec3(centre)};
const float LAMP${k}_RADIUS = ${glslFloat(radius)};
` : ''}`;
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
export function generateDirectShader(surface: SurfaceLayout, lamps: DirectLamp[], supersampling = 1): FragmentPass<typeof directUniforms> {
  return directShader(surface, lamps, supersampling, null);
}

/**
 * The direct pass of a room surface when the scene has objects: the same sum, each source only
 * where the point (every sub-sample of a texel mean) sees it past the objects, one shadow ray
 * through the objects' BVH per source and point (bvhAnyHit; width `bvhWidth` of its textures).
 */
export function generateShadowedDirectShader(
  surface: SurfaceLayout,
  lamps: DirectLamp[],
  supersampling: number,
  bvhWidth: number,
): FragmentPass<typeof shadowedDirectUniforms> {
  return directShader(surface, lamps, supersampling, bvhWidth);
}

/** Profile lookups and per-lamp constants of a direct pass. */
export function directLampConstants(lamps: DirectLamp[], subsampled: boolean): string {
  const profiles = [...new Map(lamps.map((l) => [l.profile.id, l.profile])).values()];
  return `${profileLookup({ table: 'uProfiles', dataWidth: DATA_TEXTURE_WIDTH })}
${profiles.map(profileFunction).join('')}
${lamps.map((lamp, k) => lampConstants(lamp, k, subsampled)).join('')}`;
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

function directShader<U extends typeof directUniforms | typeof shadowedDirectUniforms>(
  surface: SurfaceLayout,
  lamps: DirectLamp[],
  supersampling: number,
  bvhWidth: number | null,
): FragmentPass<U> {
  const texelU = surface.lengthU / surface.width;
  const texelV = surface.lengthV / surface.height;
  const sub = Math.max(1, Math.floor(supersampling));
  const profiles = [...new Map(lamps.map((l) => [l.profile.id, l.profile])).values()];
  const shadowed = bvhWidth !== null;
  return fragmentPass(
    (shadowed ? shadowedDirectUniforms : directUniforms) as U,
    `// direct pass, surface ${surface.name}, ${lamps.length} luminaire(s)${sub > 1 ? `, texel means (≤ ${sub}² sub-samples)` : ''}${shadowed ? ', shadowed by objects' : ''}
${profileLookup({ table: 'uProfiles', dataWidth: DATA_TEXTURE_WIDTH })}
${shadowed ? objectTracing(bvhWidth) : ''}${surfaceFrameGlsl(surface)}${sub > 1 ? `const vec3 TEXEL_U = ${glslVec3(axisVector(surface.uAxisIndex, texelU))};
const vec3 TEXEL_V = ${glslVec3(axisVector(surface.vAxisIndex, texelV))};
const float TEXEL_DIAGONAL = ${glslFloat(Math.hypot(texelU, texelV))};
` : ''}${profiles.map(profileFunction).join('')}
${lamps.map((lamp, k) => lampConstants(lamp, k, sub > 1)).join('')}
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
}
