import { meshEdges, type MeshEdges } from './meshEdges';
import type { TriangleMesh } from './triangleMesh';

/** One edge-connected part of a mesh and how its triangles' windings relate. */
export interface ConnectedPart {
  /** Triangle indices of the part, ascending. */
  triangles: number[];
  /** Every edge of the part is shared by exactly two of its own triangles, wound consistently (watertight). */
  closed: boolean;
  /**
   * Per triangle of `triangles`: true when its winding must be reversed to agree with the part's
   * first triangle (neighbours then traverse each shared edge in opposite directions); null when
   * no consistent winding exists: an edge shared by three or more triangles, or a Möbius-like cycle.
   */
  flip: boolean[] | null;
}

/**
 * The edge-connected parts of a mesh (corners compared by exact position), each with its
 * consistent winding relative to its first triangle, found by a breadth-first walk over the edges
 * exactly two triangles share (a manifold edge). Triangles `skip` excludes (their edges absent from
 * `adjacency`) belong to no part; a triangle with two corners at one position forms a part of its own.
 */
export function connectedParts(mesh: TriangleMesh, adjacency: MeshEdges = meshEdges(mesh), skip: (triangle: number) => boolean = () => false): ConnectedPart[] {
  const count = mesh.indices.length / 3;
  const { edges, edgesOf } = adjacency;
  const partOf = new Int32Array(count).fill(-1);
  const flipOf = new Uint8Array(count);
  const parts: ConnectedPart[] = [];
  for (let seed = 0; seed < count; seed++) {
    if (partOf[seed] >= 0 || skip(seed)) continue;
    const k = parts.length;
    const triangles: number[] = [];
    let consistent = true;
    partOf[seed] = k;
    const queue = [seed];
    // The walk crosses only edges exactly two triangles share: where three or more meet (two boxes
    // touching along an edge, a fin on a sheet) no neighbour is singled out, so the parts stay apart.
    for (let q = 0; q < queue.length; q++) {
      const t = queue[q];
      triangles.push(t);
      for (const key of edgesOf[t]) {
        const list = edges.get(key)!;
        if (list.length !== 2) continue;
        const [e, f] = list;
        const mine = Math.abs(e) - 1 === t ? e : f;
        const other = mine === e ? f : e;
        const u = Math.abs(other) - 1;
        if (u === t) continue;
        // Same direction along the edge: the windings disagree, so one of the two must turn.
        const want = (flipOf[t] === 1) !== (Math.sign(other) === Math.sign(mine));
        if (partOf[u] < 0) {
          partOf[u] = k;
          flipOf[u] = want ? 1 : 0;
          queue.push(u);
        } else if ((flipOf[u] === 1) !== want) {
          consistent = false;
        }
      }
    }
    triangles.sort((a, b) => a - b);
    // Closed: every edge of the part is used by exactly two of the part's own triangles, in opposite
    // directions once turned (checked here too for edges the walk did not cross).
    const uses = new Map<number, number[]>();
    for (const t of triangles) {
      for (const key of edgesOf[t]) {
        for (const e of edges.get(key)!) {
          if (Math.abs(e) - 1 !== t) continue;
          const signed = flipOf[t] === 1 ? -Math.sign(e) : Math.sign(e);
          const list = uses.get(key);
          if (list) list.push(signed);
          else uses.set(key, [signed]);
        }
      }
    }
    let closed = true;
    for (const list of uses.values()) {
      if (list.length > 2) consistent = false;
      if (list.length !== 2) closed = false;
      else if (list[0] === list[1]) consistent = false;
    }
    parts.push({ triangles, closed: closed && consistent, flip: consistent ? triangles.map((t) => flipOf[t] === 1) : null });
  }
  return parts;
}
