/**
 * The bounding volume hierarchy over all object triangles, flattened into RGBA32F textures for the
 * GLSL traversal (shaders/bvhTraversal.glsl.ts documents the texel layout; docs/baker.md, "Objects:
 * geometry"). The tree comes from three-mesh-bvh (surface area heuristic), read through its public
 * API only: `traverse` (depth-first, with each node's depth, and each leaf's triangle offset and
 * count) and the geometry's index, which MeshBVH reorders in place (documented), so no upgrade can
 * change a private buffer layout under us; the tree is re-laid in depth-first order. Node boxes are recomputed from the stored float32 triangles and
 * widened by a small margin, so a triangle lying in a box face (every face of an axis-aligned
 * cube) is inside its box despite GPU rounding.
 */
import { BufferAttribute, BufferGeometry } from 'three';
import { MeshBVH, SAH } from 'three-mesh-bvh';
import { BVH_STACK_SIZE } from '../../../../shaders/bvhTraversal.glsl';
import { InputError } from '../../../core/inputError';
import type { ObjectBvhTextures } from './preparedObjects';
import type { WorldTriangles } from './collectWorldTriangles';

/** Texels per row of both BVH textures. */
export const BVH_TEXTURE_WIDTH = 1024;
/** Deepest leaf three-mesh-bvh may build: the GLSL traversal stack holds at most one entry per level. */
export const BVH_MAX_DEPTH = BVH_STACK_SIZE - 2;
/** Triangles per leaf three-mesh-bvh aims at. */
export const BVH_LEAF_SIZE = 6;
/** Texels per node (min + left/leaf count, max + right/offset) and per triangle (v0, e1, e2, uvs). */
export const TEXELS_PER_NODE = 2;
export const TEXELS_PER_TRIANGLE = 4;
/** Triangle indices travel as floats (exact below 2^24) and triangle texels as ints: at most 2^22 triangles. */
export const MAX_BVH_TRIANGLES = 1 << 22;

export interface BvhTexturesResult extends ObjectBvhTextures {
  /** World triangle index of each texture triangle (texture order = leaf order). */
  triangleOrder: Uint32Array;
  nodeCount: number;
  depth: number;
}

/** Bound pad: 10 µm plus a few float32 ulps of the coordinate, so a box never clips its own triangles. */
function pad(x: number): number {
  return 1e-5 + Math.abs(x) * 2 ** -20;
}

/** A node of the flattened tree: interior (a, b = child node numbers) or leaf (a = count, b = first texture triangle). */
interface FlatNode {
  leaf: boolean;
  a: number;
  b: number;
  min: [number, number, number];
  max: [number, number, number];
}

/**
 * The tree of `bvh` in depth-first order (a node, its left subtree, its right subtree), through
 * three-mesh-bvh's public `traverse`, which visits the nodes in exactly that order with their depth
 * (BVH.traverse in three-mesh-bvh/src/core/BVH.js): a node's parent is the last interior node seen
 * one level up, its first child the left one. Leaves give their triangle offset and count (in
 * triangles of the reordered index). Boxes are recomputed from the stored float32 triangles.
 */
function flattenTree(bvh: MeshBVH, triangleOrder: Uint32Array, positions: Float64Array | Float32Array): { flat: FlatNode[]; depth: number } {
  const flat: FlatNode[] = [];
  /** Interior nodes on the current path, by depth. */
  const path: number[] = [];
  let depth = 0;
  bvh.traverse((level, isLeaf, _bounds, offset, count) => {
    const me = flat.length;
    const node: FlatNode = { leaf: isLeaf, a: 0, b: 0, min: [Infinity, Infinity, Infinity], max: [-Infinity, -Infinity, -Infinity] };
    flat.push(node);
    depth = Math.max(depth, level);
    if (level > 0) {
      const parent = flat[path[level - 1]];
      if (parent.a === 0) parent.a = me;
      else parent.b = me;
    }
    if (isLeaf) {
      node.a = count;
      node.b = offset;
      for (let k = node.b; k < node.b + node.a; k++) {
        const t = triangleOrder[k];
        for (let v = 0; v < 9; v++) {
          const x = Math.fround(positions[9 * t + v]);
          const axis = v % 3;
          node.min[axis] = Math.min(node.min[axis], x);
          node.max[axis] = Math.max(node.max[axis], x);
        }
      }
    } else path[level] = me;
  });
  // Children come after their parent: boxes bottom-up in reverse order.
  for (let k = flat.length - 1; k >= 0; k--) {
    const node = flat[k];
    if (node.leaf) continue;
    if (node.a === 0 || node.b === 0) throw new Error(`three-mesh-bvh: interior node ${k} has not two children (did its traverse order change?)`);
    for (const child of [flat[node.a], flat[node.b]]) {
      for (let axis = 0; axis < 3; axis++) {
        node.min[axis] = Math.min(node.min[axis], child.min[axis]);
        node.max[axis] = Math.max(node.max[axis], child.max[axis]);
      }
    }
  }
  const covered = flat.reduce((n, node) => n + (node.leaf ? node.a : 0), 0);
  if (covered !== triangleOrder.length) throw new Error(`three-mesh-bvh: the leaves hold ${covered} triangles, the geometry ${triangleOrder.length}`);
  return { flat, depth };
}

/**
 * Build the BVH of the world triangles and flatten it. `uvOfTriangle` (6 per world triangle) and
 * `chartOfTriangle` go into each triangle's texels.
 */
export function buildBvhTextures(tris: WorldTriangles, uvOfTriangle: Float64Array, chartOfTriangle: Uint32Array): BvhTexturesResult {
  if (tris.count > MAX_BVH_TRIANGLES) throw new InputError(`objects: ${tris.count} triangles in all; the baker's BVH holds at most ${MAX_BVH_TRIANGLES}`);
  const width = BVH_TEXTURE_WIDTH;
  if (tris.count === 0) {
    // One leaf with one all-zero triangle (determinant 0: never hit) under an inverted box.
    const nodes = new Float32Array(width * 4);
    nodes.set([1, 1, 1, -1, -1, -1, -1, 0]);
    return { width, nodes, nodesHeight: 1, triangles: new Float32Array(width * 4), trianglesHeight: 1, triangleOrder: new Uint32Array(0), nodeCount: 1, depth: 0 };
  }
  // Each triangle gets its own three vertices, so the reordered index names the world triangle.
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(new Float32Array(tris.positions), 3));
  const index = new Uint32Array(tris.count * 3);
  for (let i = 0; i < index.length; i++) index[i] = i;
  geometry.setIndex(new BufferAttribute(index, 1));
  const bvh = new MeshBVH(geometry, { strategy: SAH, targetLeafSize: BVH_LEAF_SIZE, maxDepth: BVH_MAX_DEPTH, setBoundingBox: false, verbose: false });
  // One root (traverse walks root 0 only): a geometry without groups has one.
  const roots = MeshBVH.serialize(bvh, { cloneBuffers: false }).roots.length;
  if (roots !== 1) throw new Error(`three-mesh-bvh built ${roots} roots for one geometry without groups`);
  const reordered = geometry.index!.array as Uint32Array;
  const triangleOrder = new Uint32Array(tris.count);
  for (let k = 0; k < tris.count; k++) triangleOrder[k] = reordered[3 * k] / 3;
  const { flat, depth } = flattenTree(bvh, triangleOrder, tris.positions);
  const nodesHeight = Math.ceil((flat.length * TEXELS_PER_NODE) / width);
  const nodes = new Float32Array(width * nodesHeight * 4);
  flat.forEach((node, k) => {
    const o = k * TEXELS_PER_NODE * 4;
    for (let axis = 0; axis < 3; axis++) {
      nodes[o + axis] = node.min[axis] - pad(node.min[axis]);
      nodes[o + 4 + axis] = node.max[axis] + pad(node.max[axis]);
    }
    // Interior: left and right child node numbers (both > 0). Leaf: −count and the first texture triangle.
    nodes[o + 3] = node.leaf ? -node.a : node.a;
    nodes[o + 7] = node.b;
  });

  const trianglesHeight = Math.ceil((tris.count * TEXELS_PER_TRIANGLE) / width);
  const triangles = new Float32Array(width * trianglesHeight * 4);
  const P = tris.positions;
  for (let k = 0; k < tris.count; k++) {
    const t = triangleOrder[k];
    const o = k * TEXELS_PER_TRIANGLE * 4;
    for (let axis = 0; axis < 3; axis++) {
      const v0 = Math.fround(P[9 * t + axis]);
      triangles[o + axis] = v0;
      triangles[o + 4 + axis] = Math.fround(P[9 * t + 3 + axis]) - v0;
      triangles[o + 8 + axis] = Math.fround(P[9 * t + 6 + axis]) - v0;
    }
    const uv = uvOfTriangle.subarray(6 * t, 6 * t + 6);
    triangles[o + 3] = uv[0];
    triangles[o + 7] = uv[1];
    triangles[o + 11] = chartOfTriangle[t];
    triangles.set([uv[2], uv[3], uv[4], uv[5]], o + 12);
  }
  return { width, nodes, nodesHeight, triangles, trianglesHeight, triangleOrder, nodeCount: flat.length, depth };
}
