import { glslFloat } from './glslFormat';
import type { AxisLayout, ProfileLayout } from './profileTable';

/** GLSL that finds the grid cell (index `<out>i`, weight `<out>t`) of `angle` on one axis of the profile table (shaders/profileLookup.glsl.ts). */
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
 * GLSL `float intensity<id>(vec3 l)`: one profile's intensity (cd) toward a
 * local direction, the bilinear interpolation of the measured grid in (γ, C)
 * (the same as core/photometry/intensity.ts). Rotationally symmetric profiles
 * get a 1D lookup (two fetches, no atan).
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
