import type { TriangleMesh } from './triangleMesh';

/** The edges of a mesh with corners compared by exact position (orientation's adjacency). */
export interface MeshEdges {
  /** One id per distinct position: split vertices of one corner share it. */
  vertexId: Uint32Array;
  /** Undirected edge key → the triangles using it, as t + 1 where the triangle runs low id → high id, −(t + 1) the other way. */
  edges: Map<number, number[]>;
  /** The edge keys of each triangle (empty for skipped ones). */
  edgesOf: number[][];
}

/** Edges of every triangle `skip` does not exclude; a triangle with two corners at one position has fewer than three. */
export function meshEdges(mesh: TriangleMesh, skip: (triangle: number) => boolean = () => false): MeshEdges {
  const { indices } = mesh;
  const count = indices.length / 3;
  const vertexId = weldedIds(mesh.positions);
  const vertexCount = mesh.positions.length / 3;
  const edges = new Map<number, number[]>();
  const edgesOf: number[][] = Array.from({ length: count }, () => []);
  for (let t = 0; t < count; t++) {
    if (skip(t)) continue;
    for (let c = 0; c < 3; c++) {
      const a = vertexId[indices[3 * t + c]];
      const b = vertexId[indices[3 * t + ((c + 1) % 3)]];
      if (a === b) continue;
      const key = Math.min(a, b) * vertexCount + Math.max(a, b);
      const list = edges.get(key);
      const entry = a < b ? t + 1 : -(t + 1);
      if (list) list.push(entry);
      else edges.set(key, [entry]);
      edgesOf[t].push(key);
    }
  }
  return { vertexId, edges, edgesOf };
}

/** One id per distinct position (exact float equality). */
function weldedIds(positions: Float32Array): Uint32Array {
  const ids = new Uint32Array(positions.length / 3);
  const seen = new Map<string, number>();
  for (let v = 0; v < ids.length; v++) {
    const key = `${positions[3 * v]},${positions[3 * v + 1]},${positions[3 * v + 2]}`;
    let k = seen.get(key);
    if (k === undefined) {
      k = seen.size;
      seen.set(key, k);
    }
    ids[v] = k;
  }
  return ids;
}
