/**
 * A triangle mesh as the product passes it around: pure data, no three.js. Object-local
 * coordinates in metres, y up (docs/scene-format.md, "Units and frames"). Every triangle names
 * its material; a material carries the diffuse reflectance the baker uses (linear RGB, each
 * component in [0, 1)). Library furniture (src/core/catalog), imported OBJ/glTF files
 * (src/engines/meshImport) and the baker (src/engines/bake/objects) all speak this type.
 */

/** Linear RGB; the same tuple as core/model's Rgb (not imported: core/model imports core/mesh, and folders may not import each other, docs/architecture.md). */
type Rgb = [number, number, number];

export interface MeshMaterial {
  /** Name from the file (MTL `newmtl`, glTF material name) or the library item's part ("top", "legs"). */
  readonly name: string;
  /** Diffuse reflectance ρ, linear RGB, each in [0, 1). */
  readonly reflectance: Rgb;
}

export interface TriangleMesh {
  /** x, y, z per vertex, metres, object-local, y up. */
  readonly positions: Float32Array;
  /** Three vertex indices per triangle, counterclockwise seen from the lit (front) side. */
  readonly indices: Uint32Array;
  /** Index into `materials` per triangle. */
  readonly materialOfTriangle: Uint16Array;
  readonly materials: readonly MeshMaterial[];
}

export function triangleCount(mesh: TriangleMesh): number {
  return mesh.indices.length / 3;
}

export interface Bounds3 {
  readonly min: [number, number, number];
  readonly max: [number, number, number];
}

/** Axis-aligned bounds of a position array (x, y, z per vertex); empty input gives min = +∞, max = −∞; a NaN coordinate makes that axis NaN. */
export function positionBounds(positions: ArrayLike<number>): Bounds3 {
  const min: [number, number, number] = [Infinity, Infinity, Infinity];
  const max: [number, number, number] = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i += 3) {
    for (let a = 0; a < 3; a++) {
      const v = positions[i + a];
      // NaN is kept (sticky): a comparison would skip it and the bounds would pass a room check (issue 32).
      if (Number.isNaN(v) || Number.isNaN(min[a])) {
        min[a] = max[a] = NaN;
        continue;
      }
      if (v < min[a]) min[a] = v;
      if (v > max[a]) max[a] = v;
    }
  }
  return { min, max };
}
