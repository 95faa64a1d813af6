/**
 * Tile sums of a direct map for the bright-patch search
 * (src/engines/bake/readTileSums.ts, docs/baker.md "Stiff scenes: bright
 * patches"). Sums over one tile of uTile × uTile texels of a direct map E
 * (lux, RGB), with exitance M = ρ·E and its photometric value y = Y(M):
 * mode 0 → (Σ E_r·a, Σ E_g·a, Σ E_b·a, Σ y²·a);
 * mode 1 → (Σ y·a·u, Σ y·a·v, Σ y·a·u², Σ y·a·v²), u, v the texel centre
 * relative to the tile's corner, metres (small numbers keep float32 exact enough).
 * Drawn into a viewport of an atlas whose corner is uOffset. `luminance`: the
 * weights of Y (the baker's LUMINANCE_WEIGHTS), compiled in as a constant.
 */
import { fragmentPass } from './fragmentPass.glsl';

export const tileSumPass = (luminance: readonly [number, number, number]) =>
  fragmentPass(
    { uMap: 'sampler2D', uOffset: 'ivec2', uTile: 'int', uMode: 'int', uTexel: 'vec2', uRho: 'vec3' },
    /* glsl */ `out vec4 outColor;
void main() {
  ivec2 tile = ivec2(gl_FragCoord.xy) - uOffset;
  ivec2 size = textureSize(uMap, 0);
  float area = uTexel.x * uTexel.y;
  vec4 sum = vec4(0.0);
  for (int j = 0; j < uTile; j++) {
    for (int i = 0; i < uTile; i++) {
      ivec2 q = tile * uTile + ivec2(i, j);
      if (q.x >= size.x || q.y >= size.y) continue;
      vec3 e = texelFetch(uMap, q, 0).rgb;
      float y = dot(vec3(${luminance.join(', ')}), uRho * e) * area;
      vec2 uv = (vec2(i, j) + 0.5) * uTexel;
      if (uMode == 0) sum += vec4(e * area, y * y / area);
      else sum += vec4(y * uv, y * uv * uv);
    }
  }
  outColor = sum;
}
`,
  );
