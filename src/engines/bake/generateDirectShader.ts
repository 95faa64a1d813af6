import type { Rgb, Vec3 } from '../../core/model/lightingScene';
import { fragmentHeader } from '../../../shaders/fullscreen.glsl';
import { profileLookup } from '../../../shaders/profileLookup.glsl';
import { glslFloat, glslMat3Transposed, glslVec3 } from './glslFormat';
import type { Mat3 } from './luminaireRotation';
import { DATA_TEXTURE_WIDTH, type AxisLayout, type ProfileLayout } from './profileTable';
import type { SurfaceLayout } from './surfaceLayout';

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

function locateCall(axis: AxisLayout, angle: string, out: string): string {
  if (axis.uniform) {
    return `locateUniform(${angle}, ${glslFloat(axis.first)}, ${glslFloat(axis.invStep)}, ${axis.count}, ${out}i, ${out}t);`;
  }
  const binWidth = (axis.last - axis.first) / axis.mapSize;
  // Grid angles that can fall inside one bin (1 when the table is finer than the grid).
  const maxSearch = 1 + Math.ceil(binWidth / axis.minStep);
  return `locateMapped(${angle}, ${axis.anglesOffset}, ${axis.count}, ${glslFloat(axis.first)}, ${axis.mapOffset}, ${axis.mapSize}, ${glslFloat(axis.invStep)}, ${maxSearch}, ${out}i, ${out}t);`;
}

/**
 * GLSL for one profile's intensity toward a local direction. Rotationally
 * symmetric profiles get a 1D lookup (two fetches); others bilinear in (γ, C).
 */
export function profileFunction(p: ProfileLayout): string {
  const v = p.vertical;
  const cd = (h: string, i: string) => `profileValue(${p.candelaOffset} + (${h}) * ${v.count} + ${i})`;
  const head = `float intensity${p.id}(vec3 l) {
  float g = degrees(acos(clamp(-l.y, -1.0, 1.0)));
  int vi; float vt;
  ${locateCall(v, 'g', 'v')}`;
  if (!p.horizontal) {
    return `${head}
  return mix(${cd('0', 'vi')}, ${cd('0', 'vi + 1')}, vt);
}
`;
  }
  const h = p.horizontal;
  return `${head}
  float c = (abs(l.x) + abs(l.z) < 1e-12) ? 0.0 : degrees(atan(-l.z, l.x));
  c = c < 0.0 ? c + 360.0 : c;
  int hi; float ht;
  ${locateCall(h, 'c', 'h')}
  float a = mix(${cd('hi', 'vi')}, ${cd('hi', 'vi + 1')}, vt);
  float b = mix(${cd('hi + 1', 'vi')}, ${cd('hi + 1', 'vi + 1')}, vt);
  return mix(a, b, ht);
}
`;
}

const hasSides = (lamp: DirectLamp): boolean => !!lamp.sides && lamp.sides.some((x) => x !== 0);

/**
 * Largest angle (radians) a direct-pass sub-sample cell may subtend from a
 * luminaire: 0.1 rad for smooth distributions (the midpoint rule on I·cosθ/d²
 * is then good to a fraction of a per cent), a quarter of the profile's feature
 * angle for steep ones (a narrow spot's flank), at least 0.5°.
 */
export function subsampleAngle(profile: ProfileLayout): number {
  const feature = (profile.featureAngle * Math.PI) / 180 / 4;
  return Math.max((0.5 * Math.PI) / 180, Math.min(0.1, Number.isFinite(feature) ? feature : 0.1));
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
export function generateDirectShader(surface: SurfaceLayout, lamps: DirectLamp[], supersampling = 1): string {
  const uAxis: Vec3 = [0, 0, 0];
  uAxis[surface.uAxisIndex] = surface.lengthU;
  const vAxis: Vec3 = [0, 0, 0];
  vAxis[surface.vAxisIndex] = surface.lengthV;
  const texelU: Vec3 = [0, 0, 0];
  texelU[surface.uAxisIndex] = surface.lengthU / surface.width;
  const texelV: Vec3 = [0, 0, 0];
  texelV[surface.vAxisIndex] = surface.lengthV / surface.height;
  const texelDiagonal = Math.hypot(surface.lengthU / surface.width, surface.lengthV / surface.height);
  const sub = Math.max(1, Math.floor(supersampling));
  const profiles = [...new Map(lamps.map((l) => [l.profile.id, l.profile])).values()];
  const lampCode = lamps
    .map((lamp, k) => {
      const n = lamp.sources.length;
      const centre = [0, 1, 2].map((a) => lamp.sources.reduce((acc, p) => acc + p[a], 0) / n) as Vec3;
      const radius = Math.max(...lamp.sources.map((p) => Math.hypot(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2])));
      return `const vec3 LAMP${k}_SOURCES[${n}] = vec3[${n}](${lamp.sources.map(glslVec3).join(', ')});
const mat3 LAMP${k}_TO_LOCAL = ${glslMat3Transposed(lamp.rotation)};
const vec3 LAMP${k}_WEIGHT = ${glslVec3(lamp.weight)};
${hasSides(lamp) ? `const float LAMP${k}_SIDE[${n}] = float[${n}](${lamp.sides!.map(glslFloat).join(', ')});\n` : ''}${sub > 1 ? `const vec3 LAMP${k}_CENTRE = ${glslVec3(centre)};
const float LAMP${k}_RADIUS = ${glslFloat(radius)};
` : ''}`;
    })
    .join('');
  const sourceLoop = (k: number, count: number, point: string) => `for (int s = 0; s < ${count}; s++) {
      vec3 d = ${point} - LAMP${k}_SOURCES[s];
      float d2 = max(dot(d, d), 1e-12);
      float invD = inversesqrt(d2);
      float cosIncidence = -dot(d, NORMAL) * invD;
      ${
        hasSides(lamps[k])
          ? `vec3 l = LAMP${k}_TO_LOCAL * (d * invD);
      // A face of a tall opening emits only its own hemisphere.
      if (cosIncidence > 0.0 && LAMP${k}_SIDE[s] * l.y >= 0.0) e += intensity${lamps[k].profile.id}(l) * cosIncidence / d2;`
          : `if (cosIncidence > 0.0) e += intensity${lamps[k].profile.id}(LAMP${k}_TO_LOCAL * (d * invD)) * cosIncidence / d2;`
      }
    }`;
  const sums = lamps
    .map((lamp, k) =>
      sub > 1
        ? `  {
    float e = 0.0;
    float near = max(distance(p, LAMP${k}_CENTRE) - LAMP${k}_RADIUS, 1e-6);
    int n = int(clamp(ceil(TEXEL_DIAGONAL / (near * ${glslFloat(subsampleAngle(lamp.profile))})), 1.0, ${glslFloat(sub)}));
    float inv = 1.0 / float(n);
    for (int sj = 0; sj < n; sj++) {
      for (int si = 0; si < n; si++) {
        vec3 q = p + TEXEL_U * ((float(si) + 0.5) * inv - 0.5) + TEXEL_V * ((float(sj) + 0.5) * inv - 0.5);
        ${sourceLoop(k, lamp.sources.length, 'q')}
      }
    }
    lux += LAMP${k}_WEIGHT * (e * inv * inv);
  }`
        : `  {
    float e = 0.0;
    ${sourceLoop(k, lamp.sources.length, 'p')}
    lux += LAMP${k}_WEIGHT * e;
  }`,
    )
    .join('\n');
  return `${fragmentHeader}
// direct pass, surface ${surface.name}, ${lamps.length} luminaire(s)${sub > 1 ? `, texel means (≤ ${sub}² sub-samples)` : ''}
#define DATA_WIDTH ${DATA_TEXTURE_WIDTH}
${profileLookup}
const vec3 ORIGIN = ${glslVec3(surface.origin)};
const vec3 U_AXIS = ${glslVec3(uAxis)};
const vec3 V_AXIS = ${glslVec3(vAxis)};
const vec3 NORMAL = ${glslVec3(surface.normal)};
const vec2 RESOLUTION = vec2(${glslFloat(surface.width)}, ${glslFloat(surface.height)});
${sub > 1 ? `const vec3 TEXEL_U = ${glslVec3(texelU)};
const vec3 TEXEL_V = ${glslVec3(texelV)};
const float TEXEL_DIAGONAL = ${glslFloat(texelDiagonal)};
` : ''}${profiles.map(profileFunction).join('')}
${lampCode}
out vec4 outColor;
void main() {
  vec2 uv = gl_FragCoord.xy / RESOLUTION;
  vec3 p = ORIGIN + U_AXIS * uv.x + V_AXIS * uv.y;
  vec3 lux = vec3(0.0);
${sums}
  outColor = vec4(lux, 1.0);
}
`;
}
