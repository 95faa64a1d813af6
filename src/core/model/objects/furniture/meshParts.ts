/**
 * Closed convex solids (boxes, vertical frusta) as the parts of library furniture, and their
 * composition into one TriangleMesh. Every part is closed (each edge shared by exactly two of its
 * triangles) and wound counterclockwise seen from outside, so the baker's front faces point out
 * and the signed volume is positive (docs/furniture.md, "Meshes").
 */
import type { MeshMaterial, TriangleMesh } from '../../../mesh/triangleMesh';

/** One closed solid of one material, in object-local metres. */
export interface MeshPart {
  /** Material (part family) name: 'top', 'legs', 'books', … */
  readonly material: string;
  /** x, y, z per vertex. */
  readonly positions: readonly number[];
  /** Three vertex indices per triangle, counterclockwise seen from outside. */
  readonly indices: readonly number[];
}

type P3 = readonly [number, number, number];

/**
 * Orients each triangle of a convex solid so its normal points away from the solid's centroid:
 * for a convex part that is exactly "counterclockwise seen from outside".
 */
function orientConvex(material: string, points: readonly P3[], triangles: readonly (readonly [number, number, number])[]): MeshPart {
  const c = points.reduce((s, p) => [s[0] + p[0] / points.length, s[1] + p[1] / points.length, s[2] + p[2] / points.length], [0, 0, 0]);
  const indices: number[] = [];
  for (const [a, b, d] of triangles) {
    const [pa, pb, pd] = [points[a], points[b], points[d]];
    const u = [pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]];
    const v = [pd[0] - pa[0], pd[1] - pa[1], pd[2] - pa[2]];
    const n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    const out = (pa[0] - c[0]) * n[0] + (pa[1] - c[1]) * n[1] + (pa[2] - c[2]) * n[2];
    indices.push(...(out >= 0 ? [a, b, d] : [a, d, b]));
  }
  return { material, positions: points.flat(), indices };
}

/** An axis-aligned box from corner `min` to corner `max` (8 vertices, 12 triangles). */
export function boxPart(material: string, min: P3, max: P3): MeshPart {
  if (!(min[0] < max[0] && min[1] < max[1] && min[2] < max[2])) throw new Error(`box '${material}' is empty: ${min} … ${max}`);
  const points: P3[] = [];
  for (let k = 0; k < 8; k++) points.push([k & 1 ? max[0] : min[0], k & 2 ? max[1] : min[1], k & 4 ? max[2] : min[2]]);
  // Vertex k has x from bit 0, y from bit 1, z from bit 2; each face is the 4 vertices sharing one bit value.
  const quads: [number, number, number, number][] = [
    [0, 2, 6, 4],
    [1, 3, 7, 5], // x = min, x = max
    [0, 1, 5, 4],
    [2, 3, 7, 6], // y
    [0, 1, 3, 2],
    [4, 5, 7, 6], // z
  ];
  return orientConvex(
    material,
    points,
    quads.flatMap(
      ([a, b, c, d]) =>
        [
          [a, b, c],
          [a, c, d],
        ] as [number, number, number][],
    ),
  );
}

/**
 * A vertical frustum (cylinder when r0 = r1) about (cx, cz) from y0 (radius r0) to y1 (radius r1).
 * `segments` is a multiple of 4 so the rim has vertices on ±x and ±z: the bounds are exactly
 * cx ± r, cz ± r.
 */
export function frustumPart(material: string, cx: number, cz: number, y0: number, y1: number, r0: number, r1: number = r0, segments = 16): MeshPart {
  if (!(y0 < y1 && r0 > 0 && r1 > 0) || segments % 4 !== 0 || segments < 4) throw new Error(`frustum '${material}' is degenerate`);
  const points: P3[] = [];
  for (const [y, r] of [
    [y0, r0],
    [y1, r1],
  ]) {
    for (let i = 0; i < segments; i++) {
      const t = (2 * Math.PI * i) / segments;
      // Exact axis points at quarter turns (cos 90° is 6e-17 in floating point, not 0).
      const [c, s] =
        i % (segments / 4) === 0
          ? [
              [1, 0],
              [0, 1],
              [-1, 0],
              [0, -1],
            ][(4 * i) / segments]
          : [Math.cos(t), Math.sin(t)];
      points.push([cx + r * c, y, cz + r * s]);
    }
  }
  const bottom = points.length;
  points.push([cx, y0, cz], [cx, y1, cz]);
  const tris: [number, number, number][] = [];
  for (let i = 0; i < segments; i++) {
    const j = (i + 1) % segments;
    tris.push([i, j, segments + j], [i, segments + j, segments + i], [bottom, i, j], [bottom + 1, segments + i, segments + j]);
  }
  return orientConvex(material, points, tris);
}

/**
 * One horizontal ring of a {@link ringedPart}: at height y, a rectangle of half-sizes hx × hz with
 * its corners rounded to radius r (0 < r ≤ min(hx, hz); r = hx = hz is a circle), its centre
 * moved by dx, dz from the part's (a shear: a cushion leaning back stays made of level rings).
 */
export type Ring = readonly [y: number, hx: number, hz: number, r: number, dz?: number, dx?: number];

/** cos, sin of a multiple of a quarter turn exactly, others from Math (bounds stay exact on the axes). */
function unitCircle(quarters: number): [number, number] {
  if (Number.isInteger(quarters))
    return (
      [
        [1, 0],
        [0, 1],
        [-1, 0],
        [0, -1],
      ] as [number, number][]
    )[((quarters % 4) + 4) % 4];
  return [Math.cos((quarters * Math.PI) / 2), Math.sin((quarters * Math.PI) / 2)];
}

/**
 * A closed solid of stacked rounded-rectangle rings (bottom to top, y increasing) joined by quads,
 * closed by a fan from (cx, yBottom, cz) and one from (cx, yTop, cz): a cushion, a rounded slab, a
 * capsule, an ellipsoid, a tapered limb. Each corner arc has `k` segments; where a ring's straight
 * side has zero length (r = hx or r = hz) its two end points are one. Convex when every ring lies
 * in the convex hull of its neighbours' (sizes concave in y), which orientConvex needs.
 */
export function ringedPart(material: string, cx: number, cz: number, rings: readonly Ring[], k = 2, yBottom = rings[0][0], yTop = rings[rings.length - 1][0]): MeshPart {
  const points: P3[] = [];
  let n = -1;
  for (const [y, hx, hz, r, dz = 0, dx = 0] of rings) {
    if (!(r > 0 && r <= hx + 1e-12 && r <= hz + 1e-12)) throw new Error(`ring of '${material}' at y ${y} has corner radius ${r} outside (0, ${Math.min(hx, hz)}]`);
    const ox = hx - r > 1e-12 ? hx - r : 0;
    const oz = hz - r > 1e-12 ? hz - r : 0;
    const start = points.length;
    for (let q = 0; q < 4; q++) {
      const sx = q === 0 || q === 3 ? ox : -ox;
      const sz = q < 2 ? oz : -oz;
      // The arc's first point repeats the previous arc's last where the side between them has no length.
      for (let j = (q % 2 ? ox : oz) === 0 ? 1 : 0; j <= k; j++) {
        const [c, s] = unitCircle(q + j / k);
        points.push([cx + dx + sx + r * c, y, cz + dz + sz + r * s]);
      }
    }
    if (n >= 0 && points.length - start !== n) throw new Error(`rings of '${material}' differ in shape`);
    n = points.length - start;
  }
  const bottom = points.length;
  points.push([cx + (rings[0][5] ?? 0), yBottom, cz + (rings[0][4] ?? 0)]);
  const last = rings[rings.length - 1];
  points.push([cx + (last[5] ?? 0), yTop, cz + (last[4] ?? 0)]);
  const tris: [number, number, number][] = [];
  const top = (rings.length - 1) * n;
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    tris.push([bottom, i, j], [bottom + 1, top + i, top + j]);
    for (let ring = 0; ring + 1 < rings.length; ring++) {
      const a = ring * n;
      tris.push([a + i, a + j, a + n + j], [a + i, a + n + j, a + n + i]);
    }
  }
  return orientConvex(material, points, tris);
}

/**
 * Rings of a slab from y0 to y1 with plan half-sizes hx × hz and plan corner radius rc, its top edge
 * bevelled by eTop and its bottom edge by eBottom (0: square, for a face that rests on something),
 * the whole slab sheared by dz from bottom to top (a back cushion leaning back). With ringedPart's
 * k = 1 every face is a flat facet: each side and bevel one quad, so the baker's planar light-map
 * charts (docs/baker.md, "Objects: geometry") stay few — a bevelled cushion is 18 to 26 charts, a
 * smoothly rounded one over 70.
 */
export function slabRings(y0: number, y1: number, hx: number, hz: number, rc: number, eTop: number, eBottom = 0, dz = 0): Ring[] {
  const at = (y: number, inset: number): Ring => [y, hx - inset, hz - inset, rc - inset, (dz * (y - y0)) / (y1 - y0)];
  return [...(eBottom > 0 ? [at(y0, eBottom), at(y0 + eBottom, 0)] : [at(y0, 0)]), at(y1 - eTop, 0), at(y1, eTop)];
}

/**
 * Rings of an ellipsoid centred at height yc with semi-axes hx, hz, ay (k rings a hemisphere,
 * apexes at yc ± ay closing it): a head, a leaf cluster. Pass the apexes as the part's ends.
 */
export function ellipsoidRings(yc: number, ay: number, hx: number, hz: number, k = 3): Ring[] {
  const rings: Ring[] = [];
  for (let i = 1 - k; i < k; i++) {
    const [c, s] = unitCircle(i / k);
    rings.push([yc + ay * s, hx * c, hz * c, Math.min(hx, hz) * c]);
  }
  return rings;
}

/**
 * The parts as one mesh: vertices concatenated, one material per distinct part material in
 * order of first use, each with its reflectance from `reflectanceOf`.
 */
export function composeParts(parts: readonly MeshPart[], reflectanceOf: (material: string) => MeshMaterial['reflectance']): TriangleMesh {
  const names: string[] = [];
  let vertexCount = 0;
  let triangleCount = 0;
  for (const p of parts) {
    vertexCount += p.positions.length / 3;
    triangleCount += p.indices.length / 3;
    if (!names.includes(p.material)) names.push(p.material);
  }
  const positions = new Float32Array(vertexCount * 3);
  const indices = new Uint32Array(triangleCount * 3);
  const materialOfTriangle = new Uint16Array(triangleCount);
  let v = 0;
  let t = 0;
  for (const p of parts) {
    positions.set(p.positions, v * 3);
    for (let i = 0; i < p.indices.length; i++) indices[t * 3 + i] = p.indices[i] + v;
    materialOfTriangle.fill(names.indexOf(p.material), t, t + p.indices.length / 3);
    v += p.positions.length / 3;
    t += p.indices.length / 3;
  }
  return { positions, indices, materialOfTriangle, materials: names.map((name) => ({ name, reflectance: reflectanceOf(name) })) };
}
