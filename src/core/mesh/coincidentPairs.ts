import type { TriangleMesh } from './triangleMesh';

/**
 * Pairs of triangles on the same three corners (welded ids, any order): the faces where two solids
 * are glued together (two boxes sharing a face), or a sheet a file makes two-sided by repeating
 * each triangle the other way round. In index order; a third copy of a triangle stays unpaired.
 */
export function coincidentPairs(mesh: TriangleMesh, vertexId: Uint32Array): Array<[number, number]> {
  const { indices } = mesh;
  const open = new Map<string, number>();
  const pairs: Array<[number, number]> = [];
  for (let t = 0; t < indices.length / 3; t++) {
    const ids = [vertexId[indices[3 * t]], vertexId[indices[3 * t + 1]], vertexId[indices[3 * t + 2]]].sort((a, b) => a - b);
    if (ids[0] === ids[1] || ids[1] === ids[2]) continue;
    const key = ids.join(',');
    const first = open.get(key);
    if (first === undefined) {
      open.set(key, t);
    } else {
      pairs.push([first, t]);
      open.delete(key);
    }
  }
  return pairs;
}
