/**
 * Ray casts against the objects' triangles through their bounding volume hierarchy (built and
 * flattened by src/engines/bake/objects/buildBvhTextures.ts; docs/baker.md, "Objects: geometry").
 * Self-contained: the two RGBA32F samplers come in as the names the caller declares, and `width`
 * (texels per row of both textures, ObjectBvhTextures.width) is compiled in.
 *
 * Texel layout (texel k lies at (k mod width, k div width), row 0 first; indices are floats, exact
 * below 2^24):
 *   nodes, 2 texels per node n, depth-first order, root = node 0:
 *     texel 2n     = (min.x, min.y, min.z, a)    box (already widened by a small margin)
 *     texel 2n + 1 = (max.x, max.y, max.z, b)
 *     interior node: a = left child, b = right child (node numbers, both > n)
 *     leaf:          a = −(triangle count) (< 0), b = its first triangle
 *   triangles, 4 texels per triangle k (leaf order):
 *     texel 4k     = (v0.xyz, uv0.x)    v0 = first corner, world metres
 *     texel 4k + 1 = (e1.xyz, uv0.y)    e1 = v1 − v0
 *     texel 4k + 2 = (e2.xyz, chart)    e2 = v2 − v0; chart = index of its atlas chart
 *     texel 4k + 3 = (uv1.xy, uv2.xy)   atlas uv of the corners, normalised (texel centres at (i + 0.5)/width)
 *   The front (lit) side is the one from which v0, v1, v2 run counterclockwise: n = e1 × e2.
 *
 * Traversal: a fixed stack (BVH_STACK_SIZE entries; the builder limits the tree depth below it),
 * nearer child first, popped entries skipped when their box starts beyond the closest hit so far.
 * Boxes: the slab test (Kay & Kajiya 1986) with a safe inverse direction (no 0 · ∞). Triangles:
 * Möller & Trumbore 1997, "Fast, minimum storage ray–triangle intersection", both faces (objects
 * occlude from either side); the sign of the determinant says which face the ray met.
 */

/** Entries of the traversal stack: the BVH may be at most this deep (buildBvhTextures keeps it 2 below). */
export const BVH_STACK_SIZE = 32;

export const bvhTraversal = ({ nodes, triangles, width }: { nodes: string; triangles: string; width: number }): string => /* glsl */ `
vec4 bvhNodeTexel(int k) {
  return texelFetch(${nodes}, ivec2(k % ${width}, k / ${width}), 0);
}

vec4 bvhTriangleTexel(int k) {
  return texelFetch(${triangles}, ivec2(k % ${width}, k / ${width}), 0);
}

// Entry distance of the ray into the box within [0, tMax], or -1 when it misses.
float bvhBoxEntry(int node, vec3 origin, vec3 inv, float tMax) {
  vec3 t0 = (bvhNodeTexel(2 * node).xyz - origin) * inv;
  vec3 t1 = (bvhNodeTexel(2 * node + 1).xyz - origin) * inv;
  vec3 tn = min(t0, t1);
  vec3 tf = max(t0, t1);
  float entry = max(max(tn.x, tn.y), max(tn.z, 0.0));
  float leave = min(min(tf.x, tf.y), min(tf.z, tMax));
  return entry <= leave ? entry : -1.0;
}

// Möller–Trumbore: hit for t in (0, tMax); bary = weights of v1 and v2; det > 0 on the front face.
bool bvhTriangleHit(vec3 origin, vec3 dir, vec3 v0, vec3 e1, vec3 e2, float tMax, out float t, out vec2 bary, out float det) {
  t = 0.0;
  bary = vec2(0.0);
  vec3 p = cross(dir, e2);
  det = dot(e1, p);
  if (det == 0.0) return false;
  float invDet = 1.0 / det;
  vec3 s = origin - v0;
  float u = dot(s, p) * invDet;
  if (u < 0.0 || u > 1.0) return false;
  vec3 q = cross(s, e1);
  float v = dot(dir, q) * invDet;
  if (v < 0.0 || u + v > 1.0) return false;
  t = dot(e2, q) * invDet;
  bary = vec2(u, v);
  return t > 0.0 && t < tMax;
}

// Walk the tree; anyHit stops at the first hit. triangle = -1 when nothing was hit.
void bvhTraverse(vec3 origin, vec3 dir, float tMax, bool anyHit, out float tHit, out int triangle, out vec2 bary, out float det) {
  tHit = tMax;
  triangle = -1;
  bary = vec2(0.0);
  det = 0.0;
  vec3 safeDir = sign(dir) * max(abs(dir), vec3(1e-20));
  safeDir = mix(safeDir, vec3(1e-20), equal(dir, vec3(0.0)));
  vec3 inv = 1.0 / safeDir;
  if (bvhBoxEntry(0, origin, inv, tMax) < 0.0) return;
  int stack[${BVH_STACK_SIZE}];
  float stackEntry[${BVH_STACK_SIZE}];
  int sp = 0;
  int node = 0;
  while (true) {
    vec4 a = bvhNodeTexel(2 * node);
    vec4 b = bvhNodeTexel(2 * node + 1);
    if (a.w < 0.0) {
      int count = int(-a.w + 0.5);
      int first = int(b.w + 0.5);
      for (int i = 0; i < count; i++) {
        int k = 4 * (first + i);
        float t;
        vec2 w;
        float d;
        if (bvhTriangleHit(origin, dir, bvhTriangleTexel(k).xyz, bvhTriangleTexel(k + 1).xyz, bvhTriangleTexel(k + 2).xyz, tHit, t, w, d)) {
          tHit = t;
          triangle = first + i;
          bary = w;
          det = d;
          if (anyHit) return;
        }
      }
    } else {
      int left = int(a.w + 0.5);
      int right = int(b.w + 0.5);
      float tLeft = bvhBoxEntry(left, origin, inv, tHit);
      float tRight = bvhBoxEntry(right, origin, inv, tHit);
      if (tLeft >= 0.0 && tRight >= 0.0) {
        bool leftFirst = tLeft <= tRight;
        stack[sp] = leftFirst ? right : left;
        stackEntry[sp] = leftFirst ? tRight : tLeft;
        sp++;
        node = leftFirst ? left : right;
        continue;
      }
      if (tLeft >= 0.0) {
        node = left;
        continue;
      }
      if (tRight >= 0.0) {
        node = right;
        continue;
      }
    }
    // Pop the next subtree that can still hold a closer hit.
    node = -1;
    while (sp > 0) {
      sp--;
      if (stackEntry[sp] <= tHit) {
        node = stack[sp];
        break;
      }
    }
    if (node < 0) break;
  }
}

// Shadow rays: true when a triangle lies at some t in (0, tMax) along origin + t·dir (dir need not be unit).
bool bvhAnyHit(vec3 origin, vec3 dir, float tMax) {
  float t;
  int triangle;
  vec2 bary;
  float det;
  bvhTraverse(origin, dir, tMax, true, t, triangle, bary, det);
  return triangle >= 0;
}

// Nearest triangle at t in (0, tMax): its distance, the atlas uv of the hit point and whether the
// ray met the front (lit) side. On a miss t = tMax, atlasUv = 0, frontFace = false.
bool bvhClosestHit(vec3 origin, vec3 dir, float tMax, out float t, out vec2 atlasUv, out bool frontFace) {
  int triangle;
  vec2 bary;
  float det;
  bvhTraverse(origin, dir, tMax, false, t, triangle, bary, det);
  atlasUv = vec2(0.0);
  frontFace = false;
  if (triangle < 0) return false;
  int k = 4 * triangle;
  vec2 uv0 = vec2(bvhTriangleTexel(k).w, bvhTriangleTexel(k + 1).w);
  vec4 uv12 = bvhTriangleTexel(k + 3);
  atlasUv = (1.0 - bary.x - bary.y) * uv0 + bary.x * uv12.xy + bary.y * uv12.zw;
  frontFace = det > 0.0;
  return true;
}
`;
