import { glslFloat, glslVec3 } from './glslFormat';
import { axisVector, type SurfaceLayout } from './surfaceLayout';

/**
 * The receiving surface of a generated pass as GLSL constants, from its
 * layout (SURFACE_FRAMES via surfaceLayouts): ORIGIN, U_AXIS and V_AXIS (the
 * full edges), NORMAL and RESOLUTION, so that texel centre (i + ½, j + ½) is at
 * ORIGIN + U_AXIS·u + V_AXIS·v with (u, v) = gl_FragCoord.xy / RESOLUTION
 * (docs/baker.md, "Texel → world mapping").
 */
export function surfaceFrameGlsl(surface: SurfaceLayout): string {
  return `const vec3 ORIGIN = ${glslVec3(surface.origin)};
const vec3 U_AXIS = ${glslVec3(axisVector(surface.uAxisIndex, surface.lengthU))};
const vec3 V_AXIS = ${glslVec3(axisVector(surface.vAxisIndex, surface.lengthV))};
const vec3 NORMAL = ${glslVec3(surface.normal)};
const vec2 RESOLUTION = vec2(${glslFloat(surface.width)}, ${glslFloat(surface.height)});
`;
}
