/** Hand-built triangle meshes for the furnished-room tests: boxes, tables, plates (object-local metres, y up). */
import type { Rgb, Vec3 } from '../../src/core/model/lightingScene/lightingScene';
import type { TriangleMesh } from '../../src/core/mesh/triangleMesh';

/** A closed axis-aligned box from min to max: 12 triangles, counterclockwise seen from outside. */
export function boxMesh(min: Vec3, max: Vec3, reflectance: Rgb = [0.5, 0.5, 0.5]): TriangleMesh {
  return mergeMeshes([{ min, max }], reflectance);
}

/** Several closed boxes as one mesh with one material. */
export function mergeMeshes(boxes: { min: Vec3; max: Vec3 }[], reflectance: Rgb = [0.5, 0.5, 0.5]): TriangleMesh {
  const positions: number[] = [];
  const indices: number[] = [];
  for (const { min, max } of boxes) {
    const base = positions.length / 3;
    for (let k = 0; k < 8; k++) positions.push(k & 1 ? max[0] : min[0], k & 2 ? max[1] : min[1], k & 4 ? max[2] : min[2]);
    // Faces as corner-index quads (bit 0 = x, 1 = y, 2 = z), each counterclockwise seen from outside.
    const quads = [
      [0, 4, 6, 2], // −x
      [1, 3, 7, 5], // +x
      [0, 1, 5, 4], // −y
      [2, 6, 7, 3], // +y
      [0, 2, 3, 1], // −z
      [4, 5, 7, 6], // +z
    ];
    for (const [a, b, c, d] of quads) indices.push(base + a, base + b, base + c, base + a, base + c, base + d);
  }
  return {
    positions: Float32Array.from(positions),
    indices: Uint32Array.from(indices),
    materialOfTriangle: new Uint16Array(indices.length / 3),
    materials: [{ name: 'box', reflectance }],
  };
}

/** A table: a top of w × d × thickness whose upper face is at `height`, on four square legs of side `leg`, centred on the origin. */
export function tableMesh(w: number, d: number, height: number, thickness = 0.04, leg = 0.05, reflectance: Rgb = [0.5, 0.5, 0.5]): TriangleMesh {
  const hw = w / 2;
  const hd = d / 2;
  const boxes = [{ min: [-hw, height - thickness, -hd] as Vec3, max: [hw, height, hd] as Vec3 }];
  for (const sx of [-1, 1]) {
    for (const sz of [-1, 1]) {
      const x = sx * (hw - leg);
      const z = sz * (hd - leg);
      boxes.push({ min: [x - leg / 2, 0, z - leg / 2], max: [x + leg / 2, height - thickness, z + leg / 2] });
    }
  }
  return mergeMeshes(boxes, reflectance);
}

/** A single-sided w × d rectangle in the plane y = 0 centred on the origin, facing +y (two triangles). */
export function rectangleMesh(w: number, d: number, reflectance: Rgb = [0, 0, 0]): TriangleMesh {
  const hw = w / 2;
  const hd = d / 2;
  return {
    positions: Float32Array.from([-hw, 0, -hd, hw, 0, -hd, hw, 0, hd, -hw, 0, hd]),
    // Counterclockwise seen from +y: (−w,−d) → (−w,+d) → (+w,+d) in (x, z).
    indices: Uint32Array.from([0, 3, 2, 0, 2, 1]),
    materialOfTriangle: new Uint16Array(2),
    materials: [{ name: 'plate', reflectance }],
  };
}

/** A single-sided square of side s (see rectangleMesh). */
export function squareMesh(s: number, reflectance: Rgb = [0, 0, 0]): TriangleMesh {
  return rectangleMesh(s, s, reflectance);
}
