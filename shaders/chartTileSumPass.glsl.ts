/**
 * Tile sums of one chart of the objects' atlas for the bright-patch search
 * (src/engines/bake/readTileSums.ts, docs/baker.md "Rooms of any shape"): tileSumPass.glsl.ts's
 * sums over the chart's texels (atlas texel uChartCorner + chart texel), with what differs on an
 * atlas: a texel counts only where it belongs to the chart (uNormals' a = chart id + 1), its area
 * is texel² × its coverage (uPoints' a: a chart's edge texels are partly outside its polygon), and
 * ρ is each texel's own (uRho), so mode 0 sums (Σ ρE_r·a, Σ ρE_g·a, Σ ρE_b·a, Σ y²·a) and the
 * selection multiplies by ρ = 1. Mode 1: (Σ y·a·u, Σ y·a·v, Σ y·a·u², Σ y·a·v²) from the tile's corner.
 */
import { fragmentPass } from './fragmentPass.glsl';

export const chartTileSumPass = (luminance: readonly [number, number, number]) =>
  fragmentPass(
    {
      uMap: 'sampler2D',
      uPoints: 'sampler2D',
      uNormals: 'sampler2D',
      uRho: 'sampler2D',
      uOffset: 'ivec2',
      uChartCorner: 'ivec2',
      uChartSize: 'ivec2',
      uChartId: 'float',
      uTile: 'int',
      uMode: 'int',
      uTexel: 'float',
    },
    /* glsl */ `out vec4 outColor;
void main() {
  ivec2 tile = ivec2(gl_FragCoord.xy) - uOffset;
  vec4 sum = vec4(0.0);
  for (int j = 0; j < uTile; j++) {
    for (int i = 0; i < uTile; i++) {
      ivec2 q = tile * uTile + ivec2(i, j);
      if (q.x >= uChartSize.x || q.y >= uChartSize.y) continue;
      ivec2 at = uChartCorner + q;
      float coverage = texelFetch(uPoints, at, 0).a;
      if (coverage <= 0.0 || abs(texelFetch(uNormals, at, 0).a - (uChartId + 1.0)) > 0.5) continue;
      float area = uTexel * uTexel * coverage;
      vec3 m = texelFetch(uRho, at, 0).rgb * texelFetch(uMap, at, 0).rgb;
      float y = dot(vec3(${luminance.join(', ')}), m) * area;
      vec2 uv = (vec2(i, j) + 0.5) * uTexel;
      if (uMode == 0) sum += vec4(m * area, y * y / area);
      else sum += vec4(y * uv, y * uv * uv);
    }
  }
  outColor = sum;
}
`,
  );

/**
 * The atlas's residual direct map (src/engines/bake/runBrightPatchPass.ts): the direct map with
 * the texels of one chart's bright tiles set to zero, drawn in the chart's viewport (uMasked = 1),
 * after a whole-atlas copy (uMasked = 0). The chart's first tile is at uMaskOffset of the mask.
 */
export const chartResidualPass = fragmentPass(
  { uMap: 'sampler2D', uMask: 'sampler2D', uTile: 'int', uMaskOffset: 'ivec2', uChartCorner: 'ivec2', uMasked: 'int' },
  /* glsl */ `out vec4 outColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float bright = uMasked == 1 ? texelFetch(uMask, uMaskOffset + (p - uChartCorner) / uTile, 0).r : 0.0;
  outColor = vec4(texelFetch(uMap, p, 0).rgb * (1.0 - bright), 1.0);
}
`,
);
