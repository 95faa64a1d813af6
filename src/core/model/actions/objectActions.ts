/**
 * Furniture and imported models: add, move, turn, resize, refinish, remove (docs/model.md,
 * "Objects"). Like every action, each is refused exactly when validate() rejects its result
 * (bindDefinition.ts); addObject alone moves the object to the nearest spot where it fits
 * (fitPlacement), so a sofa dropped half through a wall lands against it.
 */
import { MAX_STORED_MESH_CHARS, storedMeshChars } from '../files/storedMeshSize';
import { z } from 'zod/mini';
import { InputError } from '../../inputError';
import type { TriangleMesh } from '../../mesh/triangleMesh';
import { refuse, type ActionDefinition } from './action';
import { quoting } from '../configuration/coding';
import { MESH_UNITS, OBJECT_SCALE_LIMITS, WALL_NAMES, type Configuration, type ImportedMesh, type ObjectFinish, type ObjectPlacement, type ObjectSource, type RoomObject } from '../configuration/configuration';
import { findFurnitureItem } from '../objects/furniture/furnitureLibrary';
import { normaliseDegrees } from '../rails/geometry';
import { fitPlacement, sourceMesh, sourceName } from '../objects/objectGeometry';
import { meshDataProblem } from '../objects/objectProblems';
import { takeId } from './lookup';

const placementSchema = z.discriminatedUnion('on', [z.strictObject({ on: z.literal('floor'), x: z.number(), z: z.number() }), z.strictObject({ on: z.literal('wall'), wall: z.enum(WALL_NAMES), u: z.number(), y: z.number() })]);

/** A TriangleMesh handed over by the importer; its contents are validate()'s business (meshDataProblem). */
const meshSchema = z.custom<TriangleMesh>((v) => typeof v === 'object' && v !== null && 'positions' in v && 'indices' in v && 'materialOfTriangle' in v && 'materials' in v, 'must be a TriangleMesh');

const sourceSchema = z.discriminatedUnion('kind', [
  z.strictObject({ kind: z.literal('library'), item: z.string() }),
  z.strictObject({ kind: z.literal('imported'), mesh: z.string() }),
  /** A freshly imported file: the mesh is stored once in importedMeshes and shared by every object made from it. */
  z.strictObject({ kind: z.literal('import'), name: z.string().check(z.minLength(1), z.maxLength(200)), mesh: meshSchema, units: z.enum(MESH_UNITS) }),
]);

const finishSchema = z.union([z.string(), z.tuple([z.number(), z.number(), z.number()])]);

const addParams = z.strictObject({
  source: sourceSchema,
  /** Where to put it; default: the room centre (floor) or the middle of the north wall at the item's hanging height. */
  placement: z.optional(placementSchema),
  yaw: z.optional(z.number()),
  scale: z.optional(z.number()),
});

export function findObject(config: Configuration, objectId: string): { index: number; object: RoomObject } {
  const index = config.objects.findIndex((o) => o.id === objectId);
  if (index < 0) throw new InputError(`no object with id '${objectId}'`, { code: 'unknownObject', params: { id: objectId } });
  return { index, object: config.objects[index] };
}

function replaceObject(config: Configuration, index: number, object: RoomObject): Configuration {
  return { ...config, objects: config.objects.map((o, i) => (i === index ? object : o)) };
}

function updateObject(config: Configuration, objectId: string, patch: Partial<RoomObject>): Configuration {
  const { index, object } = findObject(config, objectId);
  return replaceObject(config, index, { ...object, ...patch });
}

/** Where a new object goes when the caller does not say: floor items at the room centre, wall items mid north wall. */
function defaultPlacement(config: Configuration, source: ObjectSource): ObjectPlacement {
  const item = source.kind === 'library' ? findFurnitureItem(source.item) : undefined;
  const { width, depth, height } = config.room;
  if (item?.mount === 'wall') return { on: 'wall', wall: 'north', u: width / 2, y: Math.min(item.hangHeight ?? height / 2, height - item.height / 2) };
  return { on: 'floor', x: width / 2, z: depth / 2 };
}

export const addObject: ActionDefinition<z.infer<typeof addParams>> = {
  name: 'addObject',
  label: 'Add object',
  params: addParams,
  perform(state, p) {
    let next = state;
    let source: ObjectSource;
    if (p.source.kind === 'import') {
      const problem = meshDataProblem(p.source.mesh);
      if (problem) throw new InputError(`imported model '${p.source.name}': ${problem}`, { code: 'importedModelBroken', params: { name: p.source.name, problem } });
      const [meshId, withMesh] = takeId(state, 'i');
      const entry: ImportedMesh = { name: p.source.name, mesh: p.source.mesh, units: p.source.units };
      next = { ...withMesh, importedMeshes: { ...state.importedMeshes, [meshId]: entry } };
      // Every model together must fit in a file that reopens (1 MB, issue 32); the importer checks each alone.
      const stored = Object.values(next.importedMeshes).reduce((sum, m) => sum + storedMeshChars(m.name, m.mesh), 0);
      if (stored > MAX_STORED_MESH_CHARS) {
        const problem = `the imported models would take ${(stored / 1e6).toFixed(2)} MB of a saved configuration; at most ${(MAX_STORED_MESH_CHARS / 1e6).toFixed(2)} MB fit`;
        throw new InputError(`imported model '${p.source.name}': ${problem}`, { code: 'importedModelBroken', params: { name: p.source.name, problem } });
      }
      source = { kind: 'imported', mesh: meshId };
    } else if (p.source.kind === 'library') {
      if (!findFurnitureItem(p.source.item)) throw new InputError(`no furniture item '${p.source.item}' in the library`, { code: 'unknownFurniture', params: { item: p.source.item } });
      source = { kind: 'library', item: p.source.item };
    } else {
      source = { kind: 'imported', mesh: p.source.mesh };
    }
    const mesh = sourceMesh(next, source);
    if (!mesh) throw new InputError(`no imported mesh '${(source as { mesh: string }).mesh}'`, { code: 'unknownMesh', params: { mesh: (source as { mesh: string }).mesh } });
    const [id, withId] = takeId(next, 'o');
    const placement = p.placement ?? defaultPlacement(state, source);
    const object: RoomObject = { id, source, placement, yaw: placement.on === 'wall' ? 0 : normaliseDegrees(p.yaw ?? 0), scale: p.scale ?? 1, finishes: {} };
    // Only a placeable object is moved to a free spot; a bad scale or mount is validate()'s to report.
    const limits = OBJECT_SCALE_LIMITS[source.kind];
    const placeable = Number.isFinite(object.scale) && object.scale >= limits.min && object.scale <= limits.max;
    const fitted = placeable ? fitPlacement(object, mesh, state.room, sourceName(next, source)) : object;
    return { ...withId, objects: [...state.objects, fitted] };
  },
};

const moveParams = z.strictObject({ objectId: z.string(), placement: placementSchema });

/** Moves an object (on the floor, or onto a wall); refused where it would pass through a wall, floor or ceiling. */
export const moveObject: ActionDefinition<z.infer<typeof moveParams>> = {
  name: 'moveObject',
  label: 'Move object',
  params: moveParams,
  perform(state, p) {
    const { object } = findObject(state, p.objectId);
    return updateObject(state, p.objectId, { placement: p.placement, yaw: p.placement.on === 'wall' ? 0 : object.yaw });
  },
  explain(problem) {
    return problem.code === 'object-outside' ? quoting(`cannot move it there: ${problem.message}`, 'objectCannotMove', problem) : problem.message;
  },
};

const rotateParams = z.strictObject({
  objectId: z.string(),
  /** Degrees, + = counterclockwise seen from above, about the object's origin (a library item's footprint centre). */
  by: z.optional(z.number()),
  /** Absolute yaw in degrees; wins over `by`. */
  yaw: z.optional(z.number()),
});

export const rotateObject: ActionDefinition<z.infer<typeof rotateParams>> = {
  name: 'rotateObject',
  label: 'Turn object',
  params: rotateParams,
  isEnabled(_state, p) {
    return p.by === undefined && p.yaw === undefined ? refuse('say how far to turn (by) or to which yaw', { code: 'turnHowFar' }) : true;
  },
  perform(state, p) {
    const { object } = findObject(state, p.objectId);
    return updateObject(state, p.objectId, { yaw: normaliseDegrees(p.yaw ?? object.yaw + (p.by ?? 0)) });
  },
  explain(problem) {
    return problem.code === 'object-outside' ? quoting(`cannot turn it here: ${problem.message}`, 'objectCannotTurn', problem) : problem.message;
  },
};

const resizeParams = z.strictObject({ objectId: z.string(), scale: z.number() });

export const resizeObject: ActionDefinition<z.infer<typeof resizeParams>> = {
  name: 'resizeObject',
  label: 'Resize object',
  params: resizeParams,
  perform(state, p) {
    return updateObject(state, p.objectId, { scale: p.scale });
  },
  explain(problem) {
    return problem.code === 'object-outside' ? quoting(`cannot grow it here: ${problem.message}`, 'objectCannotGrow', problem) : problem.message;
  },
};

const refinishParams = z.strictObject({
  objectId: z.string(),
  /** A material of the object's mesh ('top', 'legs', or the file's material name). */
  material: z.string(),
  /** A finish id (furniture/objectFinishes.ts), linear RGB, or null for the default. */
  finish: z.nullable(finishSchema),
});

export const refinishObject: ActionDefinition<z.infer<typeof refinishParams>> = {
  name: 'refinishObject',
  label: 'Object finish',
  params: refinishParams,
  perform(state, p) {
    const { object } = findObject(state, p.objectId);
    const finishes: Record<string, ObjectFinish> = { ...object.finishes };
    if (p.finish === null) delete finishes[p.material];
    else finishes[p.material] = typeof p.finish === 'string' ? p.finish : [p.finish[0], p.finish[1], p.finish[2]];
    return updateObject(state, p.objectId, { finishes });
  },
};

const removeParams = z.strictObject({ objectId: z.string() });

/** Removes an object; an imported mesh no other object uses goes with it. */
export const removeObject: ActionDefinition<z.infer<typeof removeParams>> = {
  name: 'removeObject',
  label: 'Remove object',
  params: removeParams,
  perform(state, p) {
    const { object } = findObject(state, p.objectId);
    const objects = state.objects.filter((o) => o !== object);
    if (object.source.kind !== 'imported') return { ...state, objects };
    const meshId = object.source.mesh;
    if (objects.some((o) => o.source.kind === 'imported' && o.source.mesh === meshId)) return { ...state, objects };
    const importedMeshes = { ...state.importedMeshes };
    delete importedMeshes[meshId];
    return { ...state, objects, importedMeshes };
  },
};
