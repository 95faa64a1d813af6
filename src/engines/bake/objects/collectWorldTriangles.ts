/**
 * Every triangle of every bake object in world space (docs/baker.md, "Objects: geometry"): placed
 * with `placedPositions` (world = T·Ry·S·local), degenerate triangles dropped, each with its front
 * normal (counterclockwise winding, right-hand rule), its area, its diffuse reflectance and its
 * object. Vertices keep the float32 values of the placed mesh (the BVH stores those same values).
 */
import { InputError } from '../../../core/inputError';
import type { Rgb } from '../../../core/model/lightingScene/lightingScene';
import { placedPositions } from '../../../core/mesh/placeMesh';
import type { Bounds3 } from '../../../core/mesh/triangleMesh';
import { toRgb, type BakeObject } from '../bakeScene';

/** Triangles below this area (m²) carry no light and have no usable normal: dropped. */
export const MIN_TRIANGLE_AREA = 1e-10;

/** Reflectance is clamped to [0, MAX_REFLECTANCE] so that no surface reflects all it receives. */
export const MAX_REFLECTANCE = 0.999;

export interface WorldTriangles {
  count: number;
  /** x, y, z of vertex 0, 1, 2 per triangle (9 numbers), metres. */
  positions: Float64Array;
  /** Unit front normal per triangle (3 numbers). */
  normals: Float64Array;
  /** m² per triangle. */
  areas: Float64Array;
  /** Diffuse reflectance ρ per triangle (3 numbers, linear RGB, clamped to [0, 0.999]). */
  reflectance: Float32Array;
  /** Index into the input objects per triangle. */
  objectOfTriangle: Uint32Array;
  /** Welded vertex id per triangle corner (3 per triangle): equal ids ⇔ identical world position in one object. */
  vertexIds: Uint32Array;
  objects: WorldObject[];
}

export interface WorldObject {
  id: string;
  /** This object's triangles are [firstTriangle, firstTriangle + triangleCount). */
  firstTriangle: number;
  triangleCount: number;
  area: number;
  bounds: Bounds3;
}

function clampRgb(rgb: Rgb): Rgb {
  return rgb.map((c) => Math.min(MAX_REFLECTANCE, Math.max(0, c))) as Rgb;
}

function checkObject(object: BakeObject, k: number): string {
  const name = `object ${k + 1} ("${object.id}")`;
  const { mesh } = object;
  if (!(Number.isFinite(object.scale) && object.scale > 0)) throw new InputError(`${name}: scale must be a positive number (got ${object.scale})`);
  if (!object.position.every(Number.isFinite) || !Number.isFinite(object.yaw)) throw new InputError(`${name}: position and yaw must be finite numbers`);
  if (mesh.indices.length % 3 !== 0) throw new InputError(`${name}: the mesh has ${mesh.indices.length} indices, not a multiple of 3`);
  if (mesh.materialOfTriangle.length !== mesh.indices.length / 3) {
    throw new InputError(`${name}: the mesh names ${mesh.materialOfTriangle.length} triangle materials for ${mesh.indices.length / 3} triangles`);
  }
  if (object.reflectance !== undefined && !toRgb(object.reflectance).every(Number.isFinite)) throw new InputError(`${name}: reflectance must be finite`);
  return name;
}

/** Collect, place and check the triangles of all objects; the objects keep their input order. */
export function collectWorldTriangles(objects: readonly BakeObject[]): WorldTriangles {
  let capacity = 0;
  for (const o of objects) capacity += Math.floor(o.mesh.indices.length / 3);
  const positions = new Float64Array(capacity * 9);
  const normals = new Float64Array(capacity * 3);
  const areas = new Float64Array(capacity);
  const reflectance = new Float32Array(capacity * 3);
  const objectOfTriangle = new Uint32Array(capacity);
  const vertexIds = new Uint32Array(capacity * 3);
  const out: WorldObject[] = [];
  let n = 0;
  let nextVertexId = 0;
  objects.forEach((object, k) => {
    const name = checkObject(object, k);
    const { mesh } = object;
    const world = placedPositions(mesh, object);
    const vertexCount = world.length / 3;
    for (let i = 0; i < world.length; i++) {
      if (!Number.isFinite(world[i])) throw new InputError(`${name}: vertex ${Math.floor(i / 3)} is not a finite point`);
    }
    const override = object.reflectance === undefined ? null : clampRgb(toRgb(object.reflectance));
    const materialRgb = mesh.materials.map((m) => clampRgb(toRgb(m.reflectance)));
    // Weld by exact world position: a mesh that repeats a corner per face (split normals) still
    // has edge-connected faces for the chart builder. Sorting the vertices by position puts equal
    // ones next to each other.
    const order = Array.from({ length: vertexCount }, (_, v) => v).sort((a, b) => world[3 * a] - world[3 * b] || world[3 * a + 1] - world[3 * b + 1] || world[3 * a + 2] - world[3 * b + 2]);
    const idOfVertex = new Uint32Array(vertexCount);
    order.forEach((v, i) => {
      const u = order[i - 1];
      const same = i > 0 && world[3 * u] === world[3 * v] && world[3 * u + 1] === world[3 * v + 1] && world[3 * u + 2] === world[3 * v + 2];
      idOfVertex[v] = same ? idOfVertex[u] : nextVertexId++;
    });
    const first = n;
    let area = 0;
    const min: [number, number, number] = [Infinity, Infinity, Infinity];
    const max: [number, number, number] = [-Infinity, -Infinity, -Infinity];
    for (let t = 0; t < mesh.indices.length / 3; t++) {
      const ia = mesh.indices[3 * t];
      const ib = mesh.indices[3 * t + 1];
      const ic = mesh.indices[3 * t + 2];
      if (ia >= vertexCount || ib >= vertexCount || ic >= vertexCount) {
        throw new InputError(`${name}: triangle ${t} uses vertex ${Math.max(ia, ib, ic)}, but the mesh has ${vertexCount} vertices`);
      }
      let rgb = override;
      if (!rgb) {
        const m = mesh.materialOfTriangle[t];
        if (m >= materialRgb.length) throw new InputError(`${name}: triangle ${t} names material ${m}, but the mesh has ${materialRgb.length} materials`);
        rgb = materialRgb[m];
      }
      const ax = world[3 * ia],
        ay = world[3 * ia + 1],
        az = world[3 * ia + 2];
      const e1x = world[3 * ib] - ax,
        e1y = world[3 * ib + 1] - ay,
        e1z = world[3 * ib + 2] - az;
      const e2x = world[3 * ic] - ax,
        e2y = world[3 * ic + 1] - ay,
        e2z = world[3 * ic + 2] - az;
      const cx = e1y * e2z - e1z * e2y;
      const cy = e1z * e2x - e1x * e2z;
      const cz = e1x * e2y - e1y * e2x;
      const len = Math.hypot(cx, cy, cz);
      if (len / 2 < MIN_TRIANGLE_AREA) continue;
      for (let c = 0; c < 3; c++) {
        const v = c === 0 ? ia : c === 1 ? ib : ic;
        for (let a = 0; a < 3; a++) {
          const x = world[3 * v + a];
          positions[9 * n + 3 * c + a] = x;
          if (x < min[a]) min[a] = x;
          if (x > max[a]) max[a] = x;
        }
        vertexIds[3 * n + c] = idOfVertex[v];
      }
      normals[3 * n] = cx / len;
      normals[3 * n + 1] = cy / len;
      normals[3 * n + 2] = cz / len;
      areas[n] = len / 2;
      area += len / 2;
      reflectance.set(rgb, 3 * n);
      objectOfTriangle[n] = k;
      n++;
    }
    if (n === first) throw new InputError(`${name}: the mesh has no triangle with an area of at least ${MIN_TRIANGLE_AREA} m²`);
    out.push({ id: object.id, firstTriangle: first, triangleCount: n - first, area, bounds: { min, max } });
  });
  return {
    count: n,
    positions: positions.slice(0, 9 * n),
    normals: normals.slice(0, 3 * n),
    areas: areas.slice(0, n),
    reflectance: reflectance.slice(0, 3 * n),
    objectOfTriangle: objectOfTriangle.slice(0, n),
    vertexIds: vertexIds.slice(0, 3 * n),
    objects: out,
  };
}
