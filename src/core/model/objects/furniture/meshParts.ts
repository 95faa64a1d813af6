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
