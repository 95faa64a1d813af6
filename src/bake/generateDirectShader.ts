import type { Rgb, Vec3 } from '../model/lightingScene';
import { fragmentHeader } from '../../shaders/fullscreen.glsl';
import { profileLookup } from '../../shaders/profileLookup.glsl';
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
  /** colour · dimming / number of sources. */
  weight: Rgb;
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

/**
 * The direct pass for one surface: E = Σ I(γ, C)·cos(incidence)/d² at each
 * texel centre (CIE 171:2006 §5.2, the inverse-square cosine law), summed
 * over the point sources of the luminaires that can reach this surface.
 * Everything scene-specific is a compile-time constant.
 */
export function generateDirectShader(surface: SurfaceLayout, lamps: DirectLamp[]): string {
  const uAxis: Vec3 = [0, 0, 0];
  uAxis[surface.uAxisIndex] = surface.lengthU;
  const vAxis: Vec3 = [0, 0, 0];
  vAxis[surface.vAxisIndex] = surface.lengthV;
  const profiles = [...new Map(lamps.map((l) => [l.profile.id, l.profile])).values()];
  const lampCode = lamps
    .map((lamp, k) => {
      const n = lamp.sources.length;
      return `const vec3 LAMP${k}_SOURCES[${n}] = vec3[${n}](${lamp.sources.map(glslVec3).join(', ')});
const mat3 LAMP${k}_TO_LOCAL = ${glslMat3Transposed(lamp.rotation)};
const vec3 LAMP${k}_WEIGHT = ${glslVec3(lamp.weight)};
`;
    })
    .join('');
  const sums = lamps
    .map(
      (lamp, k) => `  {
    float e = 0.0;
    for (int s = 0; s < ${lamp.sources.length}; s++) {
      vec3 d = p - LAMP${k}_SOURCES[s];
      float d2 = max(dot(d, d), 1e-12);
      float invD = inversesqrt(d2);
      float cosIncidence = -dot(d, NORMAL) * invD;
      if (cosIncidence > 0.0) e += intensity${lamp.profile.id}(LAMP${k}_TO_LOCAL * (d * invD)) * cosIncidence / d2;
    }
    lux += LAMP${k}_WEIGHT * e;
  }`,
    )
    .join('\n');
  return `${fragmentHeader}
// direct pass, surface ${surface.name}, ${lamps.length} luminaire(s)
#define DATA_WIDTH ${DATA_TEXTURE_WIDTH}
${profileLookup}
const vec3 ORIGIN = ${glslVec3(surface.origin)};
const vec3 U_AXIS = ${glslVec3(uAxis)};
const vec3 V_AXIS = ${glslVec3(vAxis)};
const vec3 NORMAL = ${glslVec3(surface.normal)};
const vec2 RESOLUTION = vec2(${glslFloat(surface.width)}, ${glslFloat(surface.height)});
${profiles.map(profileFunction).join('')}
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
