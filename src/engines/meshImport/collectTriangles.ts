import { Matrix4, Vector3, type BufferAttribute, type InterleavedBufferAttribute, type Material, type Mesh, type Object3D } from 'three';
import { InputError } from '../../core/inputError';
import type { MeshMaterial, TriangleMesh } from '../../core/mesh/triangleMesh';
import { checkTriangleBudget } from './triangleBudget';

/** A material as the file gives it: name, ρ, and whether its surfaces are lit and seen from both sides. */
export interface ImportMaterial extends MeshMaterial {
  /** OBJ: always (the format has no sides); glTF: the material's `doubleSided` (spec §3.9.5). */
  readonly twoSided: boolean;
}

/** What a loader's material becomes. */
export type MaterialOf = (material: Material | undefined) => ImportMaterial;

/** The triangles in the file's units and, per triangle, whether its material is two-sided (1) or not (0). */
export interface CollectedTriangles {
  mesh: TriangleMesh;
  twoSided: Uint8Array;
}

/**
 * Every triangle of the meshes under `root` (three.js objects as OBJLoader or GLTFLoader build
 * them) as one TriangleMesh in the file's own units: node transforms applied (`matrixWorld`,
 * instances of an InstancedMesh expanded), geometry groups mapped to materials, vertices at
 * exactly the same position welded into one (loaders de-index faces; the baker's charts grow
 * over shared edges), triangles whose corners weld together dropped. A transform with a negative
 * determinant (a mirror) reverses the winding back to counterclockwise-from-the-front.
 */
export function collectTriangles(root: Object3D, file: string, materialOf: MaterialOf, warnings: string[]): CollectedTriangles {
  root.updateMatrixWorld(true);
  const col: TriangleCollector = { file, materialOf, positions: [], indices: [], materialOfTriangle: [], materials: [], twoSidedOfMaterial: [], materialIndex: new Map(), weld: new Map(), collapsed: 0, triangleTotal: 0 };
  const meshes: Mesh[] = [];
  root.traverse((o) => {
    // Points and lines carry no surface; skinned meshes are read in their bind pose.
    if ((o as Mesh).isMesh) meshes.push(o as Mesh);
  });
  for (const mesh of meshes) collectMesh(col, mesh);
  const { collapsed, indices, materialOfTriangle, twoSidedOfMaterial } = col;
  if (collapsed > 0) warnings.push(`${file}: ${collapsed} triangle${collapsed === 1 ? '' : 's'} with coinciding corners dropped`);
  if (indices.length === 0) throw new InputError(`${file}: no triangles (luxbox needs a surface model)`);
  return {
    mesh: {
      positions: new Float32Array(col.positions),
      indices: new Uint32Array(indices),
      materialOfTriangle: new Uint16Array(materialOfTriangle),
      materials: col.materials,
    },
    twoSided: Uint8Array.from(materialOfTriangle, (m) => (twoSidedOfMaterial[m] ? 1 : 0)),
  };
}

/** What the walk collects: welded vertices, triangles and their material slots, and what it counts. */
interface TriangleCollector {
  file: string;
  materialOf: MaterialOf;
  positions: number[];
  indices: number[];
  materialOfTriangle: number[];
  materials: MeshMaterial[];
  twoSidedOfMaterial: boolean[];
  /** Material slot by [name, ρ, two-sided]: equal materials share a slot. */
  materialIndex: Map<string, number>;
  /** Vertex by its float32 position. */
  weld: Map<string, number>;
  collapsed: number;
  triangleTotal: number;
}

/** One mesh's triangles, per instance and per geometry group, within the triangle budget. */
function collectMesh(col: TriangleCollector, mesh: Mesh): void {
  const geometry = mesh.geometry;
  const position = geometry.getAttribute('position') as BufferAttribute | InterleavedBufferAttribute | undefined;
  if (!position || position.itemSize < 3) return;
  const index = geometry.index;
  const vertexCount = index ? index.count : position.count;
  const instances = instanceMatrices(mesh);
  col.triangleTotal += Math.floor(vertexCount / 3) * instances.length;
  checkTriangleBudget(col.file, col.triangleTotal);
  const groups = geometry.groups.length > 0 ? geometry.groups : [{ start: 0, count: vertexCount, materialIndex: 0 }];
  for (const matrix of instances) {
    for (const group of groups) {
      const material = Array.isArray(mesh.material) ? mesh.material[group.materialIndex ?? 0] : mesh.material;
      const end = Math.min(vertexCount, group.start + (Number.isFinite(group.count) ? group.count : vertexCount));
      collectGroup(col, { position, index, matrix, slot: materialSlot(col, material), start: group.start, end });
    }
  }
}

/** One geometry group of one instance: its vertices, the transform, its material slot and its range of vertex indices. */
interface GroupRun {
  position: BufferAttribute | InterleavedBufferAttribute;
  index: BufferAttribute | null;
  matrix: Matrix4;
  slot: number;
  start: number;
  end: number;
}

/** The group's triangles, placed and welded; a mirroring transform reverses their winding, coinciding corners drop them. */
function collectGroup(col: TriangleCollector, run: GroupRun): void {
  const { position, index, matrix } = run;
  const mirrored = matrix.determinant() < 0;
  const v = new Vector3();
  const corner = [0, 0, 0];
  for (let t = Math.max(0, run.start); t + 3 <= run.end; t += 3) {
    for (let c = 0; c < 3; c++) {
      const idx = index ? index.getX(t + c) : t + c;
      if (!(idx >= 0 && idx < position.count)) {
        throw new InputError(`${col.file}: a triangle refers to vertex ${idx} of a mesh with ${position.count} vertices`);
      }
      v.fromBufferAttribute(position, idx).applyMatrix4(matrix);
      corner[c] = vertexOf(col, v);
    }
    if (corner[0] === corner[1] || corner[1] === corner[2] || corner[0] === corner[2]) {
      col.collapsed++;
      continue;
    }
    if (mirrored) col.indices.push(corner[0], corner[2], corner[1]);
    else col.indices.push(corner[0], corner[1], corner[2]);
    col.materialOfTriangle.push(run.slot);
  }
}

/** The welded vertex at p's float32 position (a new one the first time). */
function vertexOf(col: TriangleCollector, p: Vector3): number {
  const x = Math.fround(p.x);
  const y = Math.fround(p.y);
  const z = Math.fround(p.z);
  if (!Number.isFinite(x) || !Number.isFinite(y) || !Number.isFinite(z)) {
    throw new InputError(`${col.file}: a vertex has a coordinate that is not a finite number (${p.x}, ${p.y}, ${p.z})`);
  }
  const key = `${x},${y},${z}`;
  let k = col.weld.get(key);
  if (k === undefined) {
    k = col.positions.length / 3;
    col.positions.push(x, y, z);
    col.weld.set(key, k);
  }
  return k;
}

/** The slot of a loader's material: equal name, ρ and sides share one; at most 65 535 (Uint16 per triangle). */
function materialSlot(col: TriangleCollector, material: Material | undefined): number {
  const m = col.materialOf(material);
  const key = JSON.stringify([m.name, m.reflectance, m.twoSided]);
  let k = col.materialIndex.get(key);
  if (k === undefined) {
    if (col.materials.length >= 65535) throw new InputError(`${col.file}: more than 65 535 materials`);
    k = col.materials.length;
    col.materials.push({ name: m.name, reflectance: m.reflectance });
    col.twoSidedOfMaterial.push(m.twoSided);
    col.materialIndex.set(key, k);
  }
  return k;
}

/** The world matrix of a mesh, or one per instance of an InstancedMesh (glTF EXT_mesh_gpu_instancing). */
function instanceMatrices(mesh: Mesh): Matrix4[] {
  const instanced = mesh as Mesh & { isInstancedMesh?: boolean; count?: number; getMatrixAt?: (i: number, m: Matrix4) => void };
  if (!instanced.isInstancedMesh || !instanced.getMatrixAt) return [mesh.matrixWorld];
  const out: Matrix4[] = [];
  for (let i = 0; i < (instanced.count ?? 0); i++) {
    const m = new Matrix4();
    instanced.getMatrixAt(i, m);
    out.push(new Matrix4().multiplyMatrices(mesh.matrixWorld, m));
  }
  return out;
}
