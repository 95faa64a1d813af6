import type { Reflectance, Rgb, Vec3 } from '../core/model/lightingScene/lightingScene';
import { placementTransform, type MeshPlacement } from '../core/mesh/placeMesh';
import type { MeshMaterial, TriangleMesh } from '../core/mesh/triangleMesh';
import { ReferenceInputError } from './referenceInputError';

/**
 * One object in the room as the reference takes it: a mesh, its placement
 * (world = T(position)·Ry(yaw)·S(scale)·local, src/core/mesh/placeMesh.ts) and an optional
 * reflectance that overrides every material. The baker's BakeObject has this shape, so a
 * bake scene's objects can be passed as they are.
 */
export interface ReferenceObject extends MeshPlacement {
  mesh: TriangleMesh;
  reflectance?: Reflectance;
  id?: string;
}

/** The objects' triangles in world space, as the reference uses them. */
export interface PlacedTriangles {
  /** 9 numbers per triangle: world corners a, b, c (counterclockwise seen from the front). */
  corners: Float64Array;
  /** Unit front normal per triangle (3 numbers). */
  normals: Float64Array;
  /** Area per triangle, m². */
  areas: Float64Array;
  /** Diffuse reflectance per triangle, linear RGB (3 numbers). */
  reflectance: Float64Array;
  /** Index of the object each triangle belongs to. */
  object: Int32Array;
  count: number;
  /** World bounds of each object: [min x, y, z, max x, y, z]. */
  objectBounds: Float64Array[];
}

/** How far a vertex may stick out of the room (rounding of placed meshes), metres. */
const ROOM_SLACK = 1e-3;

function reflectanceRgb(r: Reflectance, where: string): Rgb {
  const rgb: Rgb = typeof r === 'number' ? [r, r, r] : Array.isArray(r) && r.length === 3 ? [r[0], r[1], r[2]] : [NaN, NaN, NaN];
  if (!rgb.every((c) => Number.isFinite(c) && c >= 0 && c < 1)) {
    throw new ReferenceInputError(`${where}: reflectance must be a number or [r, g, b], each in [0, 1)`);
  }
  return rgb;
}

/**
 * Places every object's mesh in the room and checks what the reference relies on:
 * finite placement, valid indices and materials, every vertex inside the room (a
 * mesh poking through a wall would leak light out of the closed box). Triangles of
 * zero area are dropped (they neither block nor reflect).
 */
export function placeReferenceObjects(objects: readonly ReferenceObject[], extent: Vec3): PlacedTriangles {
  if (!Array.isArray(objects)) throw new ReferenceInputError('objects: expected an array');
  const corners: number[] = [];
  const normals: number[] = [];
  const areas: number[] = [];
  const reflectance: number[] = [];
  const owner: number[] = [];
  const objectBounds: Float64Array[] = [];
  objects.forEach((obj, index) => {
    const where = `objects[${index}]${obj?.id ? ` (${obj.id})` : ''}`;
    if (!obj || typeof obj !== 'object' || !obj.mesh) throw new ReferenceInputError(`${where}: expected an object with a mesh`);
    if (!Array.isArray(obj.position) || obj.position.length !== 3 || !obj.position.every(Number.isFinite)) {
      throw new ReferenceInputError(`${where}.position: expected three finite numbers`);
    }
    if (!Number.isFinite(obj.yaw)) throw new ReferenceInputError(`${where}.yaw: expected a finite angle in degrees`);
    if (!(Number.isFinite(obj.scale) && obj.scale > 0)) throw new ReferenceInputError(`${where}.scale: expected a finite number > 0, got ${obj.scale}`);
    const { positions, indices, materialOfTriangle, materials } = obj.mesh;
    if (!(positions instanceof Float32Array) || positions.length % 3 !== 0) throw new ReferenceInputError(`${where}.mesh.positions: expected a Float32Array of x, y, z triples`);
    if (!(indices instanceof Uint32Array) || indices.length % 3 !== 0) throw new ReferenceInputError(`${where}.mesh.indices: expected a Uint32Array of index triples`);
    const triangles = indices.length / 3;
    if (materialOfTriangle.length !== triangles) {
      throw new ReferenceInputError(`${where}.mesh.materialOfTriangle: ${materialOfTriangle.length} entries for ${triangles} triangles`);
    }
    const override = obj.reflectance === undefined ? null : reflectanceRgb(obj.reflectance, `${where}.reflectance`);
    const materialRgb = materials.map((m: MeshMaterial, k: number) => reflectanceRgb(m.reflectance, `${where}.mesh.materials[${k}] (${m.name})`));
    const toWorld = placementTransform(obj);
    const vertexCount = positions.length / 3;
    const world: Vec3[] = [];
    const box = new Float64Array([Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity]);
    for (let v = 0; v < vertexCount; v++) {
      const local = [positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]];
      if (!local.every(Number.isFinite)) throw new ReferenceInputError(`${where}.mesh.positions: vertex ${v} is not finite`);
      const w = toWorld(local[0], local[1], local[2]);
      for (let a = 0; a < 3; a++) {
        if (w[a] < -ROOM_SLACK || w[a] > extent[a] + ROOM_SLACK) {
          throw new ReferenceInputError(`${where}: vertex ${v} at [${w.map((c) => c.toFixed(3)).join(', ')}] lies outside the room (0..${extent[a]} m along ${'xyz'[a]})`);
        }
        w[a] = Math.min(Math.max(w[a], 0), extent[a]);
      }
      world.push(w);
    }
    for (let t = 0; t < triangles; t++) {
      const ids = [indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]];
      const bad = ids.find((i) => i >= vertexCount);
      if (bad !== undefined) throw new ReferenceInputError(`${where}.mesh.indices: triangle ${t} names vertex ${bad}, the mesh has ${vertexCount}`);
      const mat = materialOfTriangle[t];
      if (mat >= materials.length && !override) throw new ReferenceInputError(`${where}.mesh.materialOfTriangle: triangle ${t} names material ${mat}, the mesh has ${materials.length}`);
      const [a, b, c] = ids.map((i) => world[i]);
      const e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
      const e2 = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
      const n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
      const len = Math.hypot(n[0], n[1], n[2]);
      if (!(len > 1e-14)) continue;
      corners.push(...a, ...b, ...c);
      normals.push(n[0] / len, n[1] / len, n[2] / len);
      areas.push(0.5 * len);
      reflectance.push(...(override ?? materialRgb[mat]));
      owner.push(index);
      for (const p of [a, b, c]) {
        for (let k = 0; k < 3; k++) {
          box[k] = Math.min(box[k], p[k]);
          box[3 + k] = Math.max(box[3 + k], p[k]);
        }
      }
    }
    objectBounds.push(box);
  });
  return {
    corners: Float64Array.from(corners),
    normals: Float64Array.from(normals),
    areas: Float64Array.from(areas),
    reflectance: Float64Array.from(reflectance),
    object: Int32Array.from(owner),
    count: areas.length,
    objectBounds,
  };
}
