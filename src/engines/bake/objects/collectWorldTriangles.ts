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

/** The growing output: the arrays of WorldTriangles sized for every input triangle, `n` of them filled so far. */
interface TriangleSink extends Omit<WorldTriangles, 'count' | 'objects'> {
  n: number;
  nextVertexId: number;
}

/** Collect, place and check the triangles of all objects; the objects keep their input order. */
export function collectWorldTriangles(objects: readonly BakeObject[]): WorldTriangles {
  let capacity = 0;
  for (const o of objects) capacity += Math.floor(o.mesh.indices.length / 3);
  const sink: TriangleSink = {
    positions: new Float64Array(capacity * 9),
    normals: new Float64Array(capacity * 3),
    areas: new Float64Array(capacity),
    reflectance: new Float32Array(capacity * 3),
    objectOfTriangle: new Uint32Array(capacity),
    vertexIds: new Uint32Array(capacity * 3),
    n: 0,
    nextVertexId: 0,
  };
  const out = objects.map((object, k) => appendObject(object, k, sink));
  const { n } = sink;
  return {
    count: n,
    positions: sink.positions.slice(0, 9 * n),
    normals: sink.normals.slice(0, 3 * n),
    areas: sink.areas.slice(0, n),
    reflectance: sink.reflectance.slice(0, 3 * n),
    objectOfTriangle: sink.objectOfTriangle.slice(0, n),
    vertexIds: sink.vertexIds.slice(0, 3 * n),
    objects: out,
  };
}

/** One object on its way into the sink: its index and name (for messages), its placed vertices and their welded ids. */
interface PlacedObject {
  k: number;
  name: string;
  indices: ArrayLike<number>;
  world: Float32Array;
  idOfVertex: Uint32Array;
  rgbOfTriangle: (t: number) => Rgb;
  /** Grows with every kept triangle. */
  bounds: Bounds3;
}

/** One object's triangles into the sink: placed, welded, checked; degenerate ones dropped. */
function appendObject(object: BakeObject, k: number, sink: TriangleSink): WorldObject {
  const name = checkObject(object, k);
  const { mesh } = object;
  const world = placedPositions(mesh, object);
  for (let i = 0; i < world.length; i++) {
    if (!Number.isFinite(world[i])) throw new InputError(`${name}: vertex ${Math.floor(i / 3)} is not a finite point`);
  }
  const placed: PlacedObject = {
    k,
    name,
    indices: mesh.indices,
    world,
    idOfVertex: weldVertices(world, sink),
    rgbOfTriangle: triangleReflectance(object, name),
    bounds: { min: [Infinity, Infinity, Infinity], max: [-Infinity, -Infinity, -Infinity] },
  };
  const first = sink.n;
  let area = 0;
  for (let t = 0; t < mesh.indices.length / 3; t++) area += appendTriangle(placed, t, sink);
  if (sink.n === first) throw new InputError(`${name}: the mesh has no triangle with an area of at least ${MIN_TRIANGLE_AREA} m²`);
  return { id: object.id, firstTriangle: first, triangleCount: sink.n - first, area, bounds: placed.bounds };
}

/**
 * Weld by exact world position: a mesh that repeats a corner per face (split normals) still has
 * edge-connected faces for the chart builder. Sorting the vertices by position puts equal ones
 * next to each other. Ids continue from the sink's, so they are unique across objects.
 */
function weldVertices(world: Float32Array, sink: TriangleSink): Uint32Array {
  const vertexCount = world.length / 3;
  const order = Array.from({ length: vertexCount }, (_, v) => v).sort((a, b) => world[3 * a] - world[3 * b] || world[3 * a + 1] - world[3 * b + 1] || world[3 * a + 2] - world[3 * b + 2]);
  const idOfVertex = new Uint32Array(vertexCount);
  order.forEach((v, i) => {
    const u = order[i - 1];
    const same = i > 0 && world[3 * u] === world[3 * v] && world[3 * u + 1] === world[3 * v + 1] && world[3 * u + 2] === world[3 * v + 2];
    idOfVertex[v] = same ? idOfVertex[u] : sink.nextVertexId++;
  });
  return idOfVertex;
}

/** Triangle t's reflectance: the object's override, else its material's (both clamped). */
function triangleReflectance(object: BakeObject, name: string): (t: number) => Rgb {
  const { mesh } = object;
  const override = object.reflectance === undefined ? null : clampRgb(toRgb(object.reflectance));
  const materialRgb = mesh.materials.map((m) => clampRgb(toRgb(m.reflectance)));
  return (t) => {
    if (override) return override;
    const m = mesh.materialOfTriangle[t];
    if (m >= materialRgb.length) throw new InputError(`${name}: triangle ${t} names material ${m}, but the mesh has ${materialRgb.length} materials`);
    return materialRgb[m];
  };
}

/** Mesh triangle t into the sink unless it is degenerate; returns the area it adds (m², 0 when dropped) and grows the bounds. */
function appendTriangle(placed: PlacedObject, t: number, sink: TriangleSink): number {
  const { indices, world, name, idOfVertex, bounds } = placed;
  const vertexCount = world.length / 3;
  const ia = indices[3 * t];
  const ib = indices[3 * t + 1];
  const ic = indices[3 * t + 2];
  if (ia >= vertexCount || ib >= vertexCount || ic >= vertexCount) {
    throw new InputError(`${name}: triangle ${t} uses vertex ${Math.max(ia, ib, ic)}, but the mesh has ${vertexCount} vertices`);
  }
  const rgb = placed.rgbOfTriangle(t);
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
  if (len / 2 < MIN_TRIANGLE_AREA) return 0;
  const { n } = sink;
  const { min, max } = bounds;
  for (let c = 0; c < 3; c++) {
    const v = c === 0 ? ia : c === 1 ? ib : ic;
    for (let a = 0; a < 3; a++) {
      const x = world[3 * v + a];
      sink.positions[9 * n + 3 * c + a] = x;
      if (x < min[a]) min[a] = x;
      if (x > max[a]) max[a] = x;
    }
    sink.vertexIds[3 * n + c] = idOfVertex[v];
  }
  sink.normals[3 * n] = cx / len;
  sink.normals[3 * n + 1] = cy / len;
  sink.normals[3 * n + 2] = cz / len;
  sink.areas[n] = len / 2;
  sink.reflectance.set(rgb, 3 * n);
  sink.objectOfTriangle[n] = placed.k;
  sink.n++;
  return len / 2;
}
