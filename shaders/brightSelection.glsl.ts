/**
 * The bright-patch selection on the GPU (src/engines/bake/selectBrightPatchesOnGpu.ts,
 * docs/baker.md "Bright patches selected on the GPU"): the same rule as
 * src/engines/bake/selectBrightPatches.ts, on the tile-sum atlas (tileSumPass.glsl.ts) without
 * reading it back.
 *
 * The surface table `uSurfaces` has one row per reflecting surface, in the CPU selection's order,
 * seven texels: 0 (atlas column of its first tile, tiles along u, tiles along v, texels per tile
 * edge), 1 (width, height in texels, texel edge du, dv in metres), 2 (length u, length v, global
 * index of its first tile, source index), 3 (ρ.rgb, index of the u axis), 4 (origin.xyz, index of
 * the v axis), 5 (unit u axis, vSign), 6 (unit v axis, 0); texels 5 and 6 are read only where the
 * objects' atlas charts are candidates (src/engines/bake/tileFrame.ts). A tile's global index g = first + iv·tilesU + iu is the CPU's candidate order
 * (surfaces in order, tiles row by row), so ranking by (score descending, g ascending) is
 * JavaScript's stable sort by score.
 *
 * Keys (score, g) are compared, never summed, so the ranking of the float32 scores is the CPU's to
 * the bit; the sentinel (−1, −1) is "no tile".
 */
import { fragmentPass } from './fragmentPass.glsl';

/** Keys gathered per iteration of the top-k search (two per RGBA texel). */
export const KEYS_PER_ROUND = 8;

function weights(luminance: readonly [number, number, number]): string {
  return luminance.map((w) => (Number.isInteger(w) ? `${w}.0` : String(w))).join(', ');
}

/** Surface-table lookups, the tile's luminous flux y and area as selectBrightPatches.ts computes them. */
const surfaceTable = (luminance: readonly [number, number, number]) => /* glsl */ `const vec3 LUMINANCE = vec3(${weights(luminance)});
vec4 surfaceRow(int s, int t) { return texelFetch(uSurfaces, ivec2(t, s), 0); }
// The surface whose tiles fill atlas column x (−1: none).
int surfaceAtColumn(int x) {
  for (int s = 0; s < uSurfaceCount; s++) {
    vec4 a = surfaceRow(s, 0);
    if (x >= int(a.x) && x < int(a.x) + int(a.y)) return s;
  }
  return -1;
}
// The surface that holds the tile of global index g.
int surfaceOfTile(float g) {
  int found = 0;
  for (int s = 0; s < uSurfaceCount; s++) if (g >= surfaceRow(s, 2).z) found = s;
  return found;
}
// y = Y(ρ·Σ E·a), in the CPU's order of operations.
float tileY(vec4 sums, vec3 rho) {
  return LUMINANCE.x * max(0.0, sums.x) * rho.x + LUMINANCE.y * max(0.0, sums.y) * rho.y + LUMINANCE.z * max(0.0, sums.z) * rho.z;
}
// Extent of tile (iu, iv) of surface s in metres from the surface corner: (u0, v0, u1, v1); the last row and column may be partial.
vec4 tileExtent(int s, int iu, int iv) {
  vec4 a = surfaceRow(s, 0);
  vec4 b = surfaceRow(s, 1);
  vec4 c = surfaceRow(s, 2);
  float tile = a.w;
  return vec4(float(iu) * tile * b.z, float(iv) * tile * b.w, min(c.x, float(iu + 1) * tile * b.z), min(c.y, float(iv + 1) * tile * b.w));
}
// The tile's own area as the candidate test computes it (texel counts times texel edges).
float tileArea(int s, int iu, int iv) {
  vec4 a = surfaceRow(s, 0);
  vec4 b = surfaceRow(s, 1);
  float tile = a.w;
  return (min(b.x, float(iu + 1) * tile) - float(iu) * tile) * b.z * (min(b.y, float(iv + 1) * tile) - float(iv) * tile) * b.w;
}
`;

/**
 * The CPU's loop over the ranked list (selectBrightPatches.ts), as a GLSL function over the keys
 * 0 … n − 1 of uList: `takeStep(i)` is −1 where the loop stops at key i, 0 where it skips it (under
 * the contrast), 1 where it takes it; `loopState` carries the count taken and the score left. Both
 * the patch table and the early stop of the top-k rounds use it.
 */
const selectionLoop = /* glsl */ `float yAll;
float peak(float score) { return yAll > 0.0 ? uArea * score / (yAll * yAll) : 1.0; }
int loopCount;
float loopScore;
float loopMean;
vec2 loopKey;
void startLoop() {
  vec4 totals = texelFetch(uTotals, ivec2(0), 0);
  yAll = totals.x;
  loopMean = yAll / uArea;
  loopScore = totals.y;
  loopCount = 0;
}
int takeStep(int i) {
  if (!(yAll > 0.0) || loopCount >= uMaxPatches || peak(loopScore) <= uTargetPeakedness) return -1;
  vec4 pairs = texelFetch(uList, ivec2(i / 2, 0), 0);
  loopKey = i % 2 == 0 ? pairs.xy : pairs.zw;
  if (loopKey.x < 0.0) return -1;
  int s = surfaceOfTile(loopKey.y);
  vec4 a = surfaceRow(s, 0);
  int k = int(loopKey.y) - int(surfaceRow(s, 2).z);
  int iu = k % int(a.y);
  int iv = k / int(a.y);
  float y = tileY(texelFetch(uSums, ivec2(int(a.x) + iu, iv), 0), surfaceRow(s, 3).rgb);
  vec4 e = tileExtent(s, iu, iv);
  if (y / ((e.z - e.x) * (e.w - e.y)) < uMinContrast * loopMean) return 0;
  return 1;
}
// After a taken step.
void took() {
  loopCount++;
  loopScore -= loopKey.x;
}
`;

/** Ranking: a comes before b (higher score; equal scores: lower global index). */
const ranking = /* glsl */ `bool before(vec2 a, vec2 b) { return a.x > b.x || (a.x == b.x && a.y < b.y); }
vec2 top[${KEYS_PER_ROUND}];
void clearTop() { for (int i = 0; i < ${KEYS_PER_ROUND}; i++) top[i] = vec2(-1.0); }
// Insert a key into the sorted list top (a sentinel or a key ranked after the last is dropped).
void insertKey(vec2 k) {
  if (k.x < 0.0 || !before(k, top[${KEYS_PER_ROUND - 1}])) return;
  int i = ${KEYS_PER_ROUND - 1};
  while (i > 0 && before(k, top[i - 1])) {
    top[i] = top[i - 1];
    i--;
  }
  top[i] = k;
}
`;

/** Per tile of the atlas (the sums half): (y, score, g, area); y = score = 0 where the CPU skips the tile, g = −1 outside every surface's tiles. */
export const tileKeyPass = (luminance: readonly [number, number, number]) =>
  fragmentPass(
    { uSums: 'sampler2D', uSurfaces: 'sampler2D', uSurfaceCount: 'int' },
    /* glsl */ `${surfaceTable(luminance)}out vec4 outColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  outColor = vec4(0.0, 0.0, -1.0, 0.0);
  int s = surfaceAtColumn(p.x);
  if (s < 0) return;
  vec4 a = surfaceRow(s, 0);
  int iu = p.x - int(a.x);
  int iv = p.y;
  if (iv >= int(a.z)) return;
  vec4 sums = texelFetch(uSums, p, 0);
  float y = tileY(sums, surfaceRow(s, 3).rgb);
  float score = max(0.0, sums.w);
  float g = surfaceRow(s, 2).z + float(iv * int(a.y) + iu);
  bool valid = y > 0.0 && !isinf(y) && !isinf(score) && !isnan(score);
  outColor = valid ? vec4(y, score, g, tileArea(s, iu, iv)) : vec4(0.0, 0.0, g, 0.0);
}
`,
  );

/** Sums of uMap's x and y over blocks of uBlock × uBlock texels (the totals Σ y, Σ score). */
export const blockSumPass = fragmentPass(
  { uMap: 'sampler2D', uBlock: 'int' },
  /* glsl */ `out vec4 outColor;
void main() {
  ivec2 base = ivec2(gl_FragCoord.xy) * uBlock;
  ivec2 size = textureSize(uMap, 0);
  vec2 sum = vec2(0.0);
  for (int j = 0; j < uBlock; j++) {
    for (int i = 0; i < uBlock; i++) {
      ivec2 q = base + ivec2(i, j);
      if (q.x < size.x && q.y < size.y) sum += texelFetch(uMap, q, 0).xy;
    }
  }
  outColor = vec4(sum, 0.0, 0.0);
}
`,
);

/**
 * Round uRound of the top-k search, per block of uBlock × uBlock tiles: the block's first
 * KEYS_PER_ROUND candidates (in ranking order) ranked after the last key found so far (uList's
 * texel 4·uRound − 1). A candidate is a tile the CPU makes one: y ≥ minContrast · mean · area. The
 * output has KEYS_PER_ROUND/2 rows per block (pairs of keys).
 */
export const topBlockPass = (luminance: readonly [number, number, number]) =>
  fragmentPass(
    {
      uKeys: 'sampler2D',
      uTotals: 'sampler2D',
      uList: 'sampler2D',
      uSums: 'sampler2D',
      uSurfaces: 'sampler2D',
      uSurfaceCount: 'int',
      uRound: 'int',
      uBlock: 'int',
      uArea: 'float',
      uMinContrast: 'float',
      uMaxPatches: 'int',
      uTargetPeakedness: 'float',
    },
    /* glsl */ `${surfaceTable(luminance)}${selectionLoop}${ranking}out vec4 outColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  const int PAIRS = ${KEYS_PER_ROUND / 2};
  clearTop();
  int pair = p.y % PAIRS;
  vec2 bound = vec2(0.0);
  if (uRound > 0) {
    bound = texelFetch(uList, ivec2(PAIRS * uRound - 1, 0), 0).zw;
    // The previous round ran out of candidates: none are left.
    if (bound.x < 0.0) {
      outColor = vec4(-1.0);
      return;
    }
    // The CPU's loop already stops inside the keys found: no more are read (the table pass stops there too).
    startLoop();
    for (int i = 0; i < 2 * PAIRS * uRound; i++) {
      int taken = takeStep(i);
      if (taken < 0) {
        outColor = vec4(-1.0);
        return;
      }
      if (taken > 0) took();
    }
  }
  float mean = texelFetch(uTotals, ivec2(0), 0).x / uArea;
  ivec2 base = ivec2(p.x, p.y / PAIRS) * uBlock;
  ivec2 size = textureSize(uKeys, 0);
  for (int j = 0; j < uBlock; j++) {
    for (int i = 0; i < uBlock; i++) {
      ivec2 q = base + ivec2(i, j);
      if (q.x >= size.x || q.y >= size.y) continue;
      vec4 k = texelFetch(uKeys, q, 0);
      if (!(k.x > 0.0) || !(k.x >= uMinContrast * mean * k.w)) continue;
      vec2 key = k.yz;
      if (uRound > 0 && !before(bound, key)) continue;
      insertKey(key);
    }
  }
  outColor = vec4(top[2 * pair], top[2 * pair + 1]);
}
`,
  );

/** Round uRound, the merge: texels 4·uRound … of the list (pairs of keys) from every block's keys; the other texels copied from the last list. */
export const topMergePass = fragmentPass(
  { uBlocks: 'sampler2D', uList: 'sampler2D', uRound: 'int' },
  /* glsl */ `${ranking}out vec4 outColor;
void main() {
  const int PAIRS = ${KEYS_PER_ROUND / 2};
  int t = int(gl_FragCoord.x);
  if (t / PAIRS != uRound) {
    outColor = texelFetch(uList, ivec2(t, 0), 0);
    return;
  }
  clearTop();
  ivec2 size = textureSize(uBlocks, 0);
  for (int j = 0; j < size.y; j++) {
    for (int i = 0; i < size.x; i++) {
      vec4 v = texelFetch(uBlocks, ivec2(i, j), 0);
      insertKey(v.xy);
      insertKey(v.zw);
    }
  }
  int pair = t % PAIRS;
  outColor = vec4(top[2 * pair], top[2 * pair + 1]);
}
`,
);

/** The rectangle of a patch on a room surface of the box: the surface's axes are world axes (texels 3 and 4's w). */
const boxFrameRectangle = /* glsl */ `      int uAxis = int(rhoU.w);
      int vAxis = int(originV.w);
      vec3 centre = originV.xyz;
      centre[uAxis] = cu;
      centre[vAxis] = cv;
      vec3 hu = vec3(0.0);
      hu[uAxis] = halfU;
      vec3 hv = vec3(0.0);
      hv[vAxis] = halfV;
`;

/**
 * The same with any frame (a scene whose atlas charts are candidates: docs/baker.md "Rooms of any
 * shape"): texel 5 = (unit u axis, vSign), texel 6 = (unit v axis, 0); hv along vSign·v so that
 * cross(hu, hv) is a chart's front normal. On a box surface's row it gives the box's numbers.
 */
const chartFrameRectangle = /* glsl */ `      vec4 axisU = surfaceRow(s, 5);
      vec3 axisV = surfaceRow(s, 6).xyz;
      vec3 centre = originV.xyz + cu * axisU.xyz + cv * axisV;
      vec3 hu = halfU * axisU.xyz;
      vec3 hv = (halfV * axisU.w) * axisV;
`;

/**
 * The patch table (src/engines/bake/patchTable.ts layout; row k = patch k, texel 1's w = the tile's
 * global index) from the ranked candidate list, by the CPU's loop: take candidates in order while
 * fewer than uMaxPatches are taken and the peakedness area·score/y² of what is left is above
 * uTargetPeakedness, skip one whose mean exitance is under uMinContrast × the room's. Each texel
 * runs the loop up to its own row (the compaction: patch k is the k-th candidate taken). Rows after
 * the last patch hold the sentinel (surface index −1); row uRows holds (count, peakedness,
 * residual peakedness, 0) for the report.
 */
export const patchTablePass = (luminance: readonly [number, number, number], charts = false) =>
  fragmentPass(
    {
      uList: 'sampler2D',
      uSums: 'sampler2D',
      uTotals: 'sampler2D',
      uSurfaces: 'sampler2D',
      uSurfaceCount: 'int',
      uListLength: 'int',
      uRowsPerMode: 'int',
      uRows: 'int',
      uMaxPatches: 'int',
      uArea: 'float',
      uTargetPeakedness: 'float',
      uMinContrast: 'float',
    },
    /* glsl */ `${surfaceTable(luminance)}${selectionLoop}out vec4 outColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  startLoop();
  vec4 texel = p.x == 0 ? vec4(0.0, 0.0, 0.0, -1.0) : vec4(0.0);
  for (int i = 0; i < uListLength && loopCount <= p.y; i++) {
    int taken = takeStep(i);
    if (taken < 0) break;
    if (taken == 0) continue;
    vec2 key = loopKey;
    int s = surfaceOfTile(key.y);
    vec4 a = surfaceRow(s, 0);
    int k = int(key.y) - int(surfaceRow(s, 2).z);
    int iu = k % int(a.y);
    int iv = k / int(a.y);
    ivec2 at = ivec2(int(a.x) + iu, iv);
    vec4 sums = texelFetch(uSums, at, 0);
    vec4 rhoU = surfaceRow(s, 3);
    float y = tileY(sums, rhoU.rgb);
    vec4 e = tileExtent(s, iu, iv);
    if (loopCount == p.y) {
      vec4 b = surfaceRow(s, 1);
      vec4 originV = surfaceRow(s, 4);
      vec4 m = texelFetch(uSums, at + ivec2(0, uRowsPerMode), 0);
      // Flux centroid and spread of the tile's exitance (plus the spread inside a texel).
      float mu = m.x / y;
      float mv = m.y / y;
      float varU = max(0.0, m.z / y - mu * mu) + b.z * b.z / 12.0;
      float varV = max(0.0, m.w / y - mv * mv) + b.w * b.w / 12.0;
      float cu = e.x + min(max(mu, 0.0), e.z - e.x);
      float cv = e.y + min(max(mv, 0.0), e.w - e.y);
      // A uniform rectangle with the same mean and variance has half edge √3·σ; kept in the tile.
      float halfU = max(1e-4, min(min(sqrt(3.0 * varU), cu - e.x), e.z - cu));
      float halfV = max(1e-4, min(min(sqrt(3.0 * varV), cv - e.y), e.w - cv));
${charts ? chartFrameRectangle : boxFrameRectangle}      vec3 flux = max(vec3(0.0), sums.rgb) * rhoU.rgb;
      float rectArea = 4.0 * halfU * halfV;
      if (p.x == 0) texel = vec4(centre, surfaceRow(s, 2).w);
      else if (p.x == 1) texel = vec4(hu, key.y);
      else if (p.x == 2) texel = vec4(hv, 0.0);
      else texel = vec4(flux / rectArea, 0.0);
    }
    took();
  }
  if (p.y == uRows) texel = p.x == 0 ? vec4(float(loopCount), peak(texelFetch(uTotals, ivec2(0), 0).y), peak(max(0.0, loopScore)), 0.0) : vec4(0.0);
  outColor = texel;
}
`,
  );

/** The residual mask per tile of the atlas: 1 where the tile's global index is a patch of uPatches (texel 1's w), else 0. */
export const patchMaskPass = fragmentPass(
  { uKeys: 'sampler2D', uPatches: 'sampler2D', uRows: 'int' },
  /* glsl */ `out vec4 outColor;
void main() {
  float g = texelFetch(uKeys, ivec2(gl_FragCoord.xy), 0).z;
  float bright = 0.0;
  for (int k = 0; g >= 0.0 && k < uRows; k++) {
    if (texelFetch(uPatches, ivec2(0, k), 0).w < -0.5) break;
    if (texelFetch(uPatches, ivec2(1, k), 0).w == g) {
      bright = 1.0;
      break;
    }
  }
  outColor = vec4(bright, 0.0, 0.0, 1.0);
}
`,
);
