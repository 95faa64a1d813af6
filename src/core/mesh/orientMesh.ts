import type { TriangleMesh } from './triangleMesh';
import { coincidentPairs } from './coincidentPairs';
import { connectedParts, type ConnectedPart } from './connectedParts';
import { meshEdges, type MeshEdges } from './meshEdges';
import { partSelfIntersects } from './partSelfIntersects';
import { boxVolume, canonicalFacing, canonicalTurn, crossOf, dot, signedVolume, unit } from './partGeometry';

/**
 * How far apart the two sides of a two-sided surface lie (m). The baker treats a triangle as lit
 * and reflecting on its counterclockwise side only (docs/baker.md, "Objects: passes"); a two-sided
 * surface therefore gets a second, reversed copy. Coincident copies would tie in the ray caster's
 * closest hit (which side a ray meets would depend on rounding and on the BVH's order), so the
 * front moves 0.5 mm forward off the back: 5× the 0.1 mm every ray starts off its surface (SURFACE_OFFSET in
 * shaders/objectTracing.glsl.ts), far above float32 rounding at room scale (~0.3 µm at 5 m) and far
 * below anything a light map resolves (texels are centimetres). It also stays apart in a 24-bit depth
 * buffer at viewing distance, so the view never z-fights the two sides.
 */
export const BACK_SIDE_OFFSET = 5e-4;

/** A closed part whose |signed volume| is below this fraction of its bounding box's volume has no inside to speak of. */
const FLAT_VOLUME_FRACTION = 1e-6;

/** What the orientation did, per mesh (the import summary shows it). */
export interface OrientationSummary {
  /** Edge-connected parts. */
  parts: number;
  /** Watertight, consistently orientable parts (each now wound outward: positive signed volume). */
  closed: number;
  /** Closed parts that had to be turned (some or all of their triangles faced inward). */
  turnedOutward: number;
  /** Triangles whose winding was reversed (in closed parts, and in open two-sided parts made consistent). */
  trianglesReversed: number;
  /** Open parts given a back side (lit and reflecting on both sides). */
  twoSided: number;
  /** Open parts kept one-sided as the file says (glTF materials without `doubleSided`). */
  oneSided: number;
  /** Parts whose inside and outside cannot be told (non-manifold edges, a Möbius-like winding, no volume, a closed part crossing itself): two-sided. */
  undecided: number;
  /** Triangles where two parts are glued face to face (coincident pairs inside a solid), wound one canonical way. */
  enclosedFaces: number;
  /** Second copies of triangles a file repeated the other way round to make a sheet two-sided, dropped (the sheet gets its own back side). */
  droppedCopies: number;
  /** Back-side triangles added. */
  backTriangles: number;
}

export interface OrientedMesh {
  mesh: TriangleMesh;
  summary: OrientationSummary;
}

/**
 * Orient what a file gives so that the light does not depend on its winding (issue #35,
 * docs/furniture.md "Which side of a face is lit"):
 * - a **closed** part (every edge shared by exactly two of its triangles) is made consistent across
 *   its shared edges (neighbours traverse an edge in opposite directions) and then turned so that
 *   its signed volume (divergence theorem, Σ v0·(v1 × v2)/6) is positive: counterclockwise seen
 *   from outside;
 * - an **open** part is two-sided when `twoSided` says so for any of its triangles (OBJ has no
 *   notion of sides; glTF's `doubleSided`): made consistent, turned so that its area-weighted normal
 *   points along + of its largest axis (the same answer for a file and its inside-out copy), and
 *   given a reversed back copy at the file's corners, the front moved BACK_SIDE_OFFSET forward along
 *   the part's vertex normals;
 *   otherwise it is left exactly as the file winds it (glTF: counterclockwise is the front,
 *   spec §3.7.2.1, and a one-sided material is not seen from behind);
 * - a part that cannot be oriented (an edge three or more of its own triangles share, a winding
 *   that cannot be made consistent, a closed part without volume or one that passes through
 *   itself, partSelfIntersects) is two-sided, each triangle's copy moved along its own normal;
 * - **coincident triangles** (two on the same three corners) are left out of the parts: where two
 *   solids are glued face to face (a cushion against its neighbour), the rest of both is one closed
 *   surface and the glued faces lie inside it, where no light reaches (each pair is wound one
 *   canonical way and its partner the other); a sheet a file makes two-sided by repeating its
 *   triangles the other way round keeps one copy of each, made two-sided as above.
 * Vertices are compared by exact position (importers weld identical corners). Triangles keep their
 * order and materials (less the dropped copies); back sides follow them, with new vertices after
 * the existing ones.
 */
export function orientMesh(mesh: TriangleMesh, twoSided: (triangle: number) => boolean): OrientedMesh {
  const { indices } = mesh;
  const count = indices.length / 3;
  const all = meshEdges(mesh);
  const pairs = coincidentPairs(mesh, all.vertexId);
  const glued = new Uint8Array(count);
  for (const [a, b] of pairs) glued[a] = glued[b] = 1;
  const isGlued = (t: number) => glued[t] === 1;
  const adjacency = pairs.length > 0 ? meshEdges(mesh, isGlued) : all;
  const parts = connectedParts(mesh, adjacency, isGlued);
  const state: OrientState = { mesh, vertexId: all.vertexId, out: Uint32Array.from(indices), summary: emptySummary(parts.length), back: [], inClosed: new Uint8Array(count) };
  for (const part of parts) orientPart(state, part, twoSided);
  const drop = new Uint8Array(count);
  if (pairs.length > 0) orientSheets(state, orientCoincidentPairs(mesh, state.out, pairs, all, state.inClosed, drop, state.summary));
  const { summary } = state;
  const result = assemble(mesh, state.out, drop, state.back);
  summary.backTriangles = result.indices.length / 3 - (count - summary.droppedCopies);
  return { mesh: result, summary };
}

/** What the steps share: the mesh, its welded vertex ids, the indices being rewound, the summary, the parts to give back sides, and which triangles are in closed parts. */
interface OrientState {
  mesh: TriangleMesh;
  vertexId: MeshEdges['vertexId'];
  out: Uint32Array;
  summary: OrientationSummary;
  back: BackPart[];
  inClosed: Uint8Array;
}

function emptySummary(parts: number): OrientationSummary {
  return { parts, closed: 0, turnedOutward: 0, trianglesReversed: 0, twoSided: 0, oneSided: 0, undecided: 0, enclosedFaces: 0, droppedCopies: 0, backTriangles: 0 };
}

/** Make a part's winding consistent (flip[k] is relative to its first triangle), turned as a whole when `turn`; returns the triangles reversed. */
function turnPart(state: OrientState, part: ConnectedPart, turn: boolean): number {
  let reversed = 0;
  part.triangles.forEach((t, k) => {
    if (part.flip![k] !== turn) {
      reverse(state.out, t);
      reversed++;
    }
  });
  return reversed;
}

/** One edge-connected part: undecided (two-sided, per-triangle back), closed (turned outward), open two-sided (canonical turn, smooth back) or open one-sided (as the file winds it). */
function orientPart(state: OrientState, part: ConnectedPart, twoSided: (triangle: number) => boolean): void {
  const { summary, back } = state;
  const { positions, indices } = state.mesh;
  if (part.flip === null) {
    summary.undecided++;
    back.push({ part, smooth: false });
    return;
  }
  if (part.closed) {
    const volume = signedVolume(positions, indices, part);
    if (!(Math.abs(volume) > FLAT_VOLUME_FRACTION * boxVolume(positions, indices, part)) || partSelfIntersects(positions, indices, state.vertexId, part)) {
      summary.undecided++;
      back.push({ part, smooth: false });
      return;
    }
    // flip[k] is relative to the part's first triangle; turn the whole part when that orientation encloses negative volume.
    const reversed = turnPart(state, part, volume < 0);
    for (const t of part.triangles) state.inClosed[t] = 1;
    summary.closed++;
    if (reversed > 0) summary.turnedOutward++;
    summary.trianglesReversed += reversed;
    return;
  }
  if (!part.triangles.some((t) => twoSided(t))) {
    summary.oneSided++;
    return;
  }
  summary.trianglesReversed += turnPart(state, part, canonicalTurn(positions, indices, part));
  summary.twoSided++;
  back.push({ part, smooth: true });
}

/** The sheets a file made two-sided by repeating triangles (one copy each left): their own parts, each two-sided like an open part, or undecided. */
function orientSheets(state: OrientState, sheets: Set<number>): void {
  const { mesh, summary, back } = state;
  const notSheet = (t: number) => !sheets.has(t);
  for (const part of connectedParts(mesh, meshEdges(mesh, notSheet), notSheet)) {
    summary.parts++;
    if (part.flip === null) {
      summary.undecided++;
      back.push({ part, smooth: false });
    } else {
      summary.trianglesReversed += turnPart(state, part, canonicalTurn(mesh.positions, mesh.indices, part));
      summary.twoSided++;
      back.push({ part, smooth: true });
    }
  }
}

/**
 * The coincident pairs: a group of them (connected over shared edges) whose every edge is an edge
 * of a closed part or of the group itself lies inside the solids it separates: each pair wound one
 * canonical way (normal along + of its largest axis) and its partner the other. Any other group is
 * a sheet the file made two-sided: the partners are dropped (marked in `drop`) and the first
 * triangles returned, to be given back sides like an open two-sided part.
 */
function orientCoincidentPairs(mesh: TriangleMesh, out: Uint32Array, pairs: ReadonlyArray<[number, number]>, all: MeshEdges, inClosed: Uint8Array, drop: Uint8Array, summary: OrientationSummary): Set<number> {
  const { positions } = mesh;
  const partner = new Map<number, number>();
  for (const [a, b] of pairs) {
    partner.set(a, b);
    partner.set(b, a);
  }
  const group = new Map<number, number>();
  const sheets = new Set<number>();
  for (const [seed] of pairs) {
    if (group.has(seed)) continue;
    const members = [seed];
    group.set(seed, seed);
    let enclosed = true;
    let touchesSolid = false;
    for (let q = 0; q < members.length; q++) {
      for (const key of all.edgesOf[members[q]]) {
        for (const e of all.edges.get(key)!) {
          const u = Math.abs(e) - 1;
          if (partner.has(u)) {
            if (!group.has(u)) {
              group.set(u, seed);
              members.push(u);
            }
          } else if (inClosed[u] === 1) {
            touchesSolid = true;
          } else {
            enclosed = false;
          }
        }
      }
    }
    for (const t of members) {
      const p = partner.get(t)!;
      if (p < t) continue;
      if (enclosed && touchesSolid) {
        if (!canonicalFacing(crossOf(positions, out, t))) reverse(out, t);
        if (dot(crossOf(positions, out, t), crossOf(positions, out, p)) > 0) reverse(out, p);
        summary.enclosedFaces += 2;
      } else {
        drop[p] = 1;
        summary.droppedCopies++;
        sheets.add(t);
      }
    }
  }
  return sheets;
}

interface BackPart {
  part: ConnectedPart;
  /** Front moved along area-weighted vertex normals (a consistently wound part: it stays connected) or per triangle. */
  smooth: boolean;
}

function reverse(indices: Uint32Array, t: number): void {
  const b = indices[3 * t + 1];
  indices[3 * t + 1] = indices[3 * t + 2];
  indices[3 * t + 2] = b;
}

/**
 * The oriented mesh: the kept triangles (`drop` left out) in their order, then a reversed copy of
 * every triangle of the two-sided parts. The copy keeps the file's corners and the front moves
 * BACK_SIDE_OFFSET forward, so the back side never reaches past the model where it faces: a rug's
 * underside stays on the floor, a canvas's back against its wall (open parts face + of their
 * largest axis, step 3 of orientMesh). Smooth parts move each vertex along its area-weighted
 * normal (the front keeps its shared edges, so the baker's charts grow over it as before); a
 * vertex whose normals cancel, and every vertex of a per-triangle part, moves along its own
 * triangle's normal.
 */
function assemble(mesh: TriangleMesh, indices: Uint32Array, drop: Uint8Array, back: readonly BackPart[]): TriangleMesh {
  const p = mesh.positions;
  const added: number[] = [];
  const front = Uint32Array.from(indices);
  const backIndices: number[] = [];
  const backMaterials: number[] = [];
  let next = p.length / 3;
  const moved = (v: number, n: [number, number, number]): number => {
    added.push(p[3 * v] + n[0] * BACK_SIDE_OFFSET, p[3 * v + 1] + n[1] * BACK_SIDE_OFFSET, p[3 * v + 2] + n[2] * BACK_SIDE_OFFSET);
    return next++;
  };
  for (const { part, smooth } of back) {
    const vertexNormal = new Map<number, [number, number, number]>();
    if (smooth) {
      for (const t of part.triangles) {
        const n = crossOf(p, indices, t);
        for (let c = 0; c < 3; c++) {
          const v = indices[3 * t + c];
          const sum = vertexNormal.get(v) ?? [0, 0, 0];
          vertexNormal.set(v, [sum[0] + n[0], sum[1] + n[1], sum[2] + n[2]]);
        }
      }
    }
    const movedOf = new Map<number, number>();
    for (const t of part.triangles) {
      const own = unit(crossOf(p, indices, t));
      if (!own) continue; // No area: nothing to light on either side.
      for (let c = 0; c < 3; c++) {
        const v = indices[3 * t + c];
        const shared = smooth ? unit(vertexNormal.get(v)!) : null;
        if (shared) {
          let k = movedOf.get(v);
          if (k === undefined) {
            k = moved(v, shared);
            movedOf.set(v, k);
          }
          front[3 * t + c] = k;
        } else {
          front[3 * t + c] = moved(v, own);
        }
      }
      backIndices.push(indices[3 * t], indices[3 * t + 2], indices[3 * t + 1]);
      backMaterials.push(mesh.materialOfTriangle[t]);
    }
  }
  const kept = drop.length - drop.reduce((n, d) => n + d, 0);
  if (added.length === 0 && kept === drop.length && backMaterials.length === 0) return { ...mesh, indices };
  const outIndices = new Uint32Array(3 * (kept + backMaterials.length));
  const outMaterials = new Uint16Array(kept + backMaterials.length);
  let k = 0;
  for (let t = 0; t < drop.length; t++) {
    if (drop[t] === 1) continue;
    outIndices.set(front.subarray(3 * t, 3 * t + 3), 3 * k);
    outMaterials[k++] = mesh.materialOfTriangle[t];
  }
  outIndices.set(backIndices, 3 * k);
  outMaterials.set(backMaterials, k);
  const positions = new Float32Array(p.length + added.length);
  positions.set(p);
  positions.set(added, p.length);
  return { positions, indices: outIndices, materialOfTriangle: outMaterials, materials: mesh.materials };
}
