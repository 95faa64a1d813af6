/**
 * validate()'s rules for objects and imported meshes (docs/model.md, "Objects"). An object is
 * valid when its source exists and suits its mount (library wall items on a wall, floor items on
 * the floor), yaw and scale are in range, its finishes name materials of its mesh with known
 * finishes or RGB in [0, 0.95], and every placed vertex lies inside the room box — on or above
 * the floor, at or below the ceiling, never through a wall. Overlapping objects are allowed (the
 * user's business). An imported mesh is well formed and used by at least one object.
 */
import { keyed } from '../configuration/coding';
import type { TriangleMesh } from '../../mesh/triangleMesh';
import { OBJECT_SCALE_LIMITS, WALL_NAMES, type Configuration, type ImportedMesh, type ObjectSource } from '../configuration/configuration';
import { findFurnitureItem } from './furniture/furnitureLibrary';
import { findObjectFinish } from './furniture/objectFinishes';
import { fmt, OBJECT_EPS, objectPlacement, placedBounds, sourceMesh, sourceName } from './objectGeometry';
import { reflectanceProblem } from '../lightingScene/reflectance';
import type { Problem } from '../configuration/problem';
import { requireRoomShapeSupport } from '../configuration/roomShapeSupport';

/** Most triangles one imported mesh may have (the importer simplifies to fewer; the baker's BVH stays small). */
export const MAX_MESH_TRIANGLES = 200_000;

const meshChecked = new WeakMap<TriangleMesh, string | null>();

/** Why a triangle mesh is malformed (lengths, index ranges, non-finite vertices, reflectances), or null. Cached per mesh. */
export function meshDataProblem(mesh: TriangleMesh): string | null {
  const known = meshChecked.get(mesh);
  if (known !== undefined) return known;
  const problem = computeMeshProblem(mesh);
  meshChecked.set(mesh, problem);
  return problem;
}

function computeMeshProblem(mesh: TriangleMesh): string | null {
  if (!(mesh.positions instanceof Float32Array) || !(mesh.indices instanceof Uint32Array) || !(mesh.materialOfTriangle instanceof Uint16Array) || !Array.isArray(mesh.materials)) {
    return 'mesh arrays must be Float32Array positions, Uint32Array indices, Uint16Array materialOfTriangle and a materials list';
  }
  const vertices = mesh.positions.length / 3;
  const triangles = mesh.indices.length / 3;
  if (!Number.isInteger(vertices)) return `positions hold ${mesh.positions.length} numbers, not three per vertex`;
  if (!Number.isInteger(triangles)) return `indices hold ${mesh.indices.length} numbers, not three per triangle`;
  if (triangles === 0) return 'the mesh has no triangles';
  if (triangles > MAX_MESH_TRIANGLES) return `the mesh has ${triangles} triangles (at most ${MAX_MESH_TRIANGLES})`;
  if (mesh.materialOfTriangle.length !== triangles) return `materialOfTriangle has ${mesh.materialOfTriangle.length} entries for ${triangles} triangles`;
  if (mesh.materials.length === 0) return 'the mesh has no materials';
  for (let i = 0; i < mesh.positions.length; i++) if (!Number.isFinite(mesh.positions[i])) return `positions[${i}] is not finite`;
  for (let i = 0; i < mesh.indices.length; i++) if (mesh.indices[i] >= vertices) return `indices[${i}] = ${mesh.indices[i]} is past the last vertex (${vertices - 1})`;
  for (let i = 0; i < triangles; i++) if (mesh.materialOfTriangle[i] >= mesh.materials.length) return `materialOfTriangle[${i}] = ${mesh.materialOfTriangle[i]} names no material (${mesh.materials.length} materials)`;
  for (let i = 0; i < mesh.materials.length; i++) {
    const m = mesh.materials[i];
    if (typeof m?.name !== 'string') return `materials[${i}].name must be a string`;
    const r = m.reflectance;
    if (!Array.isArray(r) || r.length !== 3 || !r.every((c) => typeof c === 'number' && c >= 0 && c < 1)) return `materials[${i}].reflectance must be linear RGB, each channel in [0, 1)`;
  }
  return null;
}

/** A library object's furniture id as a parameter (a UI names it from its own messages); nothing for an imported model. */
function furnitureOf(source: ObjectSource): { furnitureId: string } | Record<string, never> {
  return source.kind === 'library' ? { furnitureId: source.item } : {};
}

/** Problems of one object (its own rules, then whether it lies inside the room). */
export function objectProblems(config: Configuration, index: number): Problem[] {
  const o = config.objects[index];
  const at = `objects[${index}]`;
  const out: Problem[] = [];
  // `key` and `params`: the sentence's own code and values, non-enumerable (docs/i18n.md).
  const p = (code: string, path: string, message: string, key?: string, params?: Record<string, string | number>) => out.push(key ? keyed({ code, path: `${at}${path}`, message }, key, params) : { code, path: `${at}${path}`, message });
  const mesh = sourceMesh(config, o.source);
  if (!mesh) {
    if (o.source.kind === 'library') p('unknown-furniture', '.source.item', `object ${o.id}: no furniture item '${o.source.item}' in the library`, 'objectUnknownFurniture', { id: o.id, item: o.source.item });
    else p('unknown-mesh', '.source.mesh', `object ${o.id}: no imported mesh '${o.source.mesh}'`, 'objectUnknownMesh', { id: o.id, mesh: o.source.mesh });
    return out;
  }
  const item = o.source.kind === 'library' ? findFurnitureItem(o.source.item) : undefined;
  if (item && item.mount !== o.placement.on)
    p('object-mount', '.placement.on', `a ${item.name} goes on ${item.mount === 'wall' ? 'a wall' : 'the floor'}`, item.mount === 'wall' ? 'objectGoesOnWall' : 'objectGoesOnFloor', { name: item.name, furnitureId: item.id });
  const limits = OBJECT_SCALE_LIMITS[o.source.kind];
  if (!Number.isFinite(o.scale) || o.scale < limits.min || o.scale > limits.max) {
    p(
      'object-scale',
      '.scale',
      `scale must be between ${limits.min} and ${limits.max} for ${o.source.kind === 'library' ? 'library furniture' : 'imported models'} (got ${o.scale})`,
      o.source.kind === 'library' ? 'objectScaleFurniture' : 'objectScaleImported',
      { min: limits.min, max: limits.max, value: o.scale },
    );
  }
  if (!Number.isFinite(o.yaw) || o.yaw < 0 || o.yaw >= 360) p('object-yaw', '.yaw', `yaw must be in [0, 360) degrees (got ${o.yaw})`, 'objectYawRange', { value: o.yaw });
  else if (o.placement.on === 'wall' && o.yaw !== 0) p('object-yaw', '.yaw', `an object on a wall faces into the room and does not turn (yaw must be 0, got ${o.yaw})`, 'objectYawOnWall', { value: o.yaw });
  const pl = o.placement;
  if (pl.on === 'floor' ? ![pl.x, pl.z].every(Number.isFinite) : !(WALL_NAMES as readonly string[]).includes(pl.wall) || ![pl.u, pl.y].every(Number.isFinite)) {
    p('object-position', '.placement', `object ${o.id} has a non-finite position or an unknown wall`, 'objectPosition', { id: o.id });
  }
  const materials = new Set(mesh.materials.map((m) => m.name));
  for (const [material, finish] of Object.entries(o.finishes)) {
    if (!materials.has(material)) {
      p('unknown-material', `.finishes.${material}`, `${sourceName(config, o.source)} has no material '${material}' (it has: ${[...materials].join(', ')})`, 'unknownMaterial', {
        name: sourceName(config, o.source),
        ...furnitureOf(o.source),
        material,
        materials: [...materials].join(', '),
      });
    } else if (typeof finish === 'string') {
      if (!findObjectFinish(finish)) p('unknown-finish', `.finishes.${material}`, `unknown finish '${finish}'`, 'unknownFinish', { id: finish });
    } else {
      const problem = Array.isArray(finish) ? reflectanceProblem(finish) : 'a finish is a finish id or linear RGB [r, g, b]';
      if (problem) p('object-finish', `.finishes.${material}`, problem);
    }
  }
  if (out.length > 0) return out; // geometry needs sound numbers
  const b = placedBounds(o, mesh, config.room);
  const { width: W, depth: D, height: H } = config.room;
  // Named as a shopper knows it (the piece or file, never the internal id): the problem's path says which entry.
  const name = sourceName(config, o.source);
  // The object as parameters: its name (a UI names library furniture in its language), id and item.
  const named = { name: sourceName(config, o.source), id: o.id, ...furnitureOf(o.source) };
  // A placement near the double range overflows the Float32 vertices: name it before any bounds test (issue 32).
  if (![...b.min, ...b.max].every(Number.isFinite)) {
    p('object-position', '.placement', `object ${o.id} has a non-finite position or an unknown wall`, 'objectPosition', { id: o.id });
    return out;
  }
  // Each test written so that NaN fails it (a comparison with NaN is false).
  const walls: string[] = [];
  if (!(b.min[0] >= -OBJECT_EPS)) walls.push('west');
  if (!(b.max[0] <= W + OBJECT_EPS)) walls.push('east');
  if (!(b.min[2] >= -OBJECT_EPS)) walls.push('north');
  if (!(b.max[2] <= D + OBJECT_EPS)) walls.push('south');
  const through = walls.map((w) => `the ${w} wall`);
  if (through.length > 0) {
    const message = `${name} passes through ${through.join(' and ')} (${fmt(W)} × ${fmt(D)} m room)`;
    const params = { ...named, wall: walls[0], width: Number(fmt(W)), depth: Number(fmt(D)) };
    // An object passes at most two walls (one in x, one in z): one sentence each way.
    p('object-outside', '.placement', message, walls.length > 1 ? 'objectThroughWalls' : 'objectThroughWall', walls.length > 1 ? { ...params, wall2: walls[1] } : params);
  }
  if (!(b.max[1] <= H + OBJECT_EPS)) p('object-outside', '.placement', `${name} reaches ${fmt(b.max[1])} m, above the ${fmt(H)} m ceiling`, 'objectAboveCeiling', { ...named, top: Number(fmt(b.max[1])), height: Number(fmt(H)) });
  if (!(b.min[1] >= -OBJECT_EPS)) p('object-outside', '.placement', `${name} reaches ${fmt(-b.min[1])} m below the floor`, 'objectBelowFloor', { ...named, depth: Number(fmt(-b.min[1])) });
  // A room with a shape (issue 29): inside its outline and under every slope too (the room-shape chunk judges it).
  const misfit = out.length === 0 && config.room.shape ? requireRoomShapeSupport().objectMisfit(config.room, mesh, objectPlacement(o, config.room), named) : null;
  if (misfit) p('object-outside', '.placement', misfit.message, misfit.key, misfit.params);
  return out;
}

/** Problems of the imported meshes: malformed data, or a mesh no object uses. */
export function importedMeshProblems(config: Configuration): Problem[] {
  const out: Problem[] = [];
  const used = new Set(config.objects.flatMap((o) => (o.source.kind === 'imported' ? [o.source.mesh] : [])));
  for (const [id, entry] of Object.entries(config.importedMeshes) as [string, ImportedMesh][]) {
    const problem = meshDataProblem(entry.mesh);
    if (problem) out.push(keyed({ code: 'mesh-data', path: `importedMeshes.${id}.mesh`, message: `imported model '${entry.name}': ${problem}` }, 'importedModelBroken', { name: entry.name, problem }));
    else if (!used.has(id)) out.push(keyed({ code: 'unused-mesh', path: `importedMeshes.${id}`, message: `imported model '${entry.name}' (${id}) is used by no object` }, 'unusedMesh', { name: entry.name, id }));
  }
  return out;
}

/** Every object problem: the imported meshes first (objects read them), then each object in order. */
export function allObjectProblems(config: Configuration, firstOnly: boolean): Problem[] {
  const out = importedMeshProblems(config);
  if (firstOnly && out.length > 0) return out;
  const badMesh = new Set(out.filter((p) => p.code === 'mesh-data').map((p) => p.path.split('.')[1]));
  for (let i = 0; i < config.objects.length; i++) {
    const o = config.objects[i];
    if (o.source.kind === 'imported' && badMesh.has(o.source.mesh)) continue;
    out.push(...objectProblems(config, i));
    if (firstOnly && out.length > 0) return out;
  }
  return out;
}

/** For a changed state: the meshes, and the objects that are not the same objects as before. */
export function changedObjectProblems(before: Configuration, after: Configuration): Problem[] {
  if (before.objects === after.objects && before.importedMeshes === after.importedMeshes) return [];
  const meshes = importedMeshProblems(after);
  if (meshes.length > 0) return meshes;
  const untouched = new Set(before.objects);
  const sameMeshes = before.importedMeshes === after.importedMeshes;
  for (let i = 0; i < after.objects.length; i++) {
    const o = after.objects[i];
    // An imported object whose mesh entry changed must be rechecked even if the object is the same.
    if (untouched.has(o) && (sameMeshes || o.source.kind === 'library' || before.importedMeshes[o.source.mesh] === after.importedMeshes[o.source.mesh])) continue;
    const problems = objectProblems(after, i);
    if (problems.length > 0) return problems;
  }
  return [];
}
