/**
 * Meshes for the object-geometry tests: axis-aligned boxes (outward counterclockwise faces, shared
 * corners) and a seeded soup of random triangles.
 */
import type { TriangleMesh } from '../../../../src/core/mesh/triangleMesh';
import type { BakeObject } from '../../../../src/engines/bake/bakeScene';
import { createRng } from '../../../fuzz/mutate';

/** A w × h × d box with its base centred on the origin (y from 0 to h): 8 corners, 12 triangles. */
export function boxMesh(w: number, h: number, d: number, reflectance = 0.5): TriangleMesh {
  const positions: number[] = [];
  for (let i = 0; i < 8; i++) positions.push(((i & 1) - 0.5) * w, ((i >> 1) & 1) * h, (((i >> 2) & 1) - 0.5) * d);
  // Corner i = x bit 0, y bit 1, z bit 2; each quad listed counterclockwise seen from outside.
  const quads = [
    [0, 4, 6, 2], // −x
    [1, 3, 7, 5], // +x
    [0, 1, 5, 4], // −y
    [2, 6, 7, 3], // +y
    [0, 2, 3, 1], // −z
    [4, 5, 7, 6], // +z
  ];
  const indices = quads.flatMap(([a, b, c, e]) => [a, b, c, a, c, e]);
  return {
    positions: new Float32Array(positions),
    indices: new Uint32Array(indices),
    materialOfTriangle: new Uint16Array(12),
    materials: [{ name: 'box', reflectance: [reflectance, reflectance, reflectance] }],
  };
}

/** `count` random triangles with corners in [lo, hi]³ (edges up to `size` m), seeded. */
export function triangleSoup(seed: number, count: number, lo: number, hi: number, size: number): TriangleMesh {
  const rng = createRng(seed);
  const positions = new Float32Array(count * 9);
  for (let t = 0; t < count; t++) {
    const c = [0, 1, 2].map(() => lo + size + rng.next() * (hi - lo - 2 * size));
    for (let k = 0; k < 3; k++) for (let a = 0; a < 3; a++) positions[9 * t + 3 * k + a] = c[a] + (rng.next() - 0.5) * 2 * size;
  }
  const indices = new Uint32Array(count * 3).map((_, i) => i);
  const materialOfTriangle = new Uint16Array(count).map((_, i) => i % 2);
  return {
    positions,
    indices,
    materialOfTriangle,
    materials: [
      { name: 'a', reflectance: [0.2, 0.4, 0.6] },
      { name: 'b', reflectance: [0.7, 0.7, 0.7] },
    ],
  };
}

export function placed(id: string, mesh: TriangleMesh, position: [number, number, number], yaw = 0, scale = 1): BakeObject {
  return { id, mesh, position, yaw, scale };
}

/** A few boxes (one rotated, one scaled) and a 2000-triangle soup in a 4 × 3 × 5 m room. */
export function testScene(): BakeObject[] {
  return [
    placed('table', boxMesh(1.2, 0.75, 0.8), [1, 0, 1.5]),
    placed('cabinet', boxMesh(0.6, 1.8, 0.4), [3, 0, 3.5], 30),
    placed('cube', boxMesh(1, 1, 1), [2, 1.6, 2.5], 45, 0.5),
    placed('soup', triangleSoup(7, 2000, 0.5, 2.5, 0.15), [0.5, 0.2, 1.5]),
  ];
}
