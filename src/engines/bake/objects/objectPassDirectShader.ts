import { fragmentPass } from '../../../../shaders/fragmentPass.glsl';
import { objectTracing } from '../../../../shaders/objectTracing.glsl';
import { directLampConstants, directPointSum, withLampSpec, type DirectLamp, type DirectPass } from '../generateDirectShader';

/** The atlas direct pass's uniforms: the profile table, the BVH, and the G-buffer's points (a = coverage) and normals. */
export const objectDirectUniforms = {
  uProfiles: 'sampler2D',
  uBvhNodes: 'sampler2D',
  uBvhTriangles: 'sampler2D',
  uPoints: 'sampler2D',
  uNormals: 'sampler2D',
} as const;

/**
 * The direct pass of the objects' atlas (docs/baker.md, "Objects: passes"): a fullscreen pass over
 * the atlas whose texel point and normal come from the G-buffer (objects/preparedObjects.ts)
 * instead of a surface frame. E = Σ I(γ, C)·cos(incidence)/d² (CIE 171:2006 §5.2) over every
 * luminaire's point sources on the front side of the texel, each times its visibility (one shadow
 * ray through the BVH). Centre values: an atlas texel's sample point is its centre (or the nearest
 * point of its chart), and the texel-mean sub-sampling of the walls is not applied here.
 * Empty texels (coverage 0) do no work and stay 0. With `withLampUniforms` the lamps are uniforms
 * (generateDirectShader.ts lampUniforms, when they fit): the program then depends on the
 * photometry and source counts only, and its `lampValues` are set with the other uniforms.
 */
export function generateObjectDirectShader(lamps: DirectLamp[], bvhWidth: number, withLampUniforms = false): DirectPass<typeof objectDirectUniforms> {
  const spec = withLampSpec(objectDirectUniforms, lamps, false, withLampUniforms);
  const pass: DirectPass<typeof objectDirectUniforms> = fragmentPass(
    spec.uniforms,
    `// direct pass, objects' atlas, ${lamps.length} luminaire(s), shadowed by objects${spec.lamps ? ', lamps as uniforms' : ''}
${objectTracing(bvhWidth)}${directLampConstants(lamps, false, spec.lamps !== null)}
out vec4 outColor;
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 point = texelFetch(uPoints, texel, 0);
  if (point.a <= 0.0) {
    outColor = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  vec3 p = point.xyz;
  vec3 n = normalize(texelFetch(uNormals, texel, 0).xyz);
  vec3 lux = vec3(0.0);
${directPointSum(lamps, 'p', 'n', true)}
  outColor = vec4(lux, 1.0);
}
`,
  );
  if (spec.lamps) pass.lampValues = spec.lamps.values;
  return pass;
}
