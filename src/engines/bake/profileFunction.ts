import { glslFloat } from './glslFormat';
import type { AxisLayout, DenseLookup, MeasuredLookup, ProfileLayout } from './profileTable';

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
 * local direction. Dense (default): the bilinear interpolation of the
 * profile's uniform grid (denseProfileGrid.ts), cell found arithmetically,
 * four fetches (two for a rotational profile), C folded by the file's
 * symmetry; the same function as `denseIntensity` on the CPU. Measured: the
 * bilinear interpolation of the file's grid with bin tables (the same as
 * core/photometry/intensity.ts).
 */
export function profileFunction(p: ProfileLayout): string {
  return p.lookup.kind === 'dense' ? denseFunction(p.id, p.lookup) : measuredFunction(p.id, p.lookup);
}

/** GLSL that folds `c` (degrees in [0, 360)) onto the stored range of a symmetric profile (denseProfileGrid.ts `foldC`). */
function foldGlsl(fold: DenseLookup['fold']): string {
  if (fold === 'bilateral-c0') return 'c = c > 180.0 ? 360.0 - c : c;';
  if (fold === 'quadrant') return 'c = c > 180.0 ? 360.0 - c : c;\n  c = c > 90.0 ? 180.0 - c : c;';
  if (fold === 'bilateral-c90') return 'c = c < 90.0 ? 180.0 - c : (c > 270.0 ? 540.0 - c : c);';
  return '';
}

function denseFunction(id: number, d: DenseLookup): string {
  const n = d.gamma.count;
  const last = d.gamma.first + (n - 1) * d.gamma.step;
  // Outside the stored γ range the profile is zero (denseProfileGrid.ts gammaKnots); a range
  // that reaches the pole clamps instead, so float rounding of acos at 0° or 180° stays inside.
  // A thousandth of a cell of slack keeps the last measured angle itself inside under float rounding.
  const below = d.gamma.first > 1e-9 ? 'f < -0.001 || ' : '';
  const above = last < 180 - 1e-9 ? `f > ${glslFloat(n - 1 + 0.001)} || ` : '';
  const cut = below || above ? `if (${below}${above}false) return 0.0;\n  ` : '';
  const head = `float intensity${id}(vec3 l) {
  float g = degrees(acos(clamp(-l.y, -1.0, 1.0)));
  float f = (g - ${glslFloat(d.gamma.first)}) * ${glslFloat(1 / d.gamma.step)};
  ${cut}f = clamp(f, 0.0, ${glslFloat(n - 1)});
  int vi = min(int(f), ${n - 2});
  float vt = f - float(vi);`;
  if (!d.c) {
    return `${head}
  int k = ${d.offset} + vi;
  return mix(profileValue(k), profileValue(k + 1), vt);
}
`;
  }
  const m = d.c.count;
  return `${head}
  float c = (abs(l.x) + abs(l.z) < 1e-12) ? 0.0 : degrees(atan(-l.z, l.x));
  c = c < 0.0 ? c + 360.0 : c;
  ${foldGlsl(d.fold)}
  float fc = clamp((c - ${glslFloat(d.c.first)}) * ${glslFloat(1 / d.c.step)}, 0.0, ${glslFloat(m - 1)});
  int hi = min(int(fc), ${m - 2});
  float ht = fc - float(hi);
  int k = ${d.offset} + hi * ${n} + vi;
  float a = mix(profileValue(k), profileValue(k + 1), vt);
  float b = mix(profileValue(k + ${n}), profileValue(k + ${n + 1}), vt);
  return mix(a, b, ht);
}
`;
}

function measuredFunction(id: number, p: MeasuredLookup): string {
  const v = p.vertical;
  const cd = (h: string, i: string) => `profileValue(${p.candelaOffset} + (${h}) * ${v.count} + ${i})`;
  const head = `float intensity${id}(vec3 l) {
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
