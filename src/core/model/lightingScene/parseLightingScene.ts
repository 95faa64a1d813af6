/**
 * Reading a lighting scene (versions 1, 2 and 3, docs/scene-format.md) from
 * untrusted JSON: size and shape limits (untrustedJson.ts),
 * the version, structure and types with zod (strict: an unknown field is
 * refused, naming it, with a suggestion for a misspelling), then the physical
 * checks zod cannot express (a lamp inside the room; an object's mesh inside
 * the room is checked once loaded, by resolveBakeScene). Every error is one line
 * naming the source and the field, e.g.
 * `scene.json: luminaires[2].position[1]: 3.1 m is above the ceiling (height 2.8 m)`.
 * Limits are in SCENE_LIMITS and docs/scene-format.md.
 */
import { z } from 'zod/mini';
import { NEAR_FIELD_MODELS, SURFACE_NAMES, type LightingRoom, type LightingScene, type SurfaceName } from './lightingScene';
import { normaliseRoom, type Room as ShapedRoom } from '../../room/normaliseRoom';
import { pointInsideRoom } from '../../room/ceilingHeightAt';
import type { RoomInput } from '../../room/roomInput';
import { roomSchema } from '../../room/roomSchema';
import { boxReflectanceOf } from './boxWallFacing';
import { boxRoomInput } from '../../room/boxRoom';
import { boxWindowsAsOpenings } from './daylightConditions';
import { parseDaylight, parseOpeningTransmittance, parseSky, type SceneDaylight, type SceneWindow, type TransmittanceValue } from './parseDaylight';
import { excerpt, jsonShapeProblem } from '../../untrustedJson';
import { LightingSceneError } from './lightingSceneError';
import { describeIssues, schemaFieldNames } from '../../zodIssues';
import { safeParseInEnglish } from '../../zodEnglish';

export { LightingSceneError };

/** Newest lighting scene version this program reads. */
export const LIGHTING_SCENE_VERSION = 3;

/** Version-2 fields: a version-1 file that uses one is told to say "version": 2. */
const V2_FIELDS = ['nearField', 'objects', 'windows', 'sky'] as const;

export const SCENE_LIMITS = {
  /** Room edges, metres. */
  minDimension: 0.1,
  maxDimension: 500,
  maxLuminaires: 10_000,
  /** Largest colour multiplier per channel (a linear RGB gain, typically ≤ 1). */
  maxColor: 100,
  maxObjects: 1_000,
  /** Uniform scale of an object's mesh (1 = the file's own metres). */
  minObjectScale: 0.01,
  maxObjectScale: 100,
} as const;

/** How far (metres) a placed mesh may reach beyond a room surface: a model resting on the floor may dip a few millimetres through it. */
export const OBJECT_ROOM_TOLERANCE = 0.01;

/** A value as the user wrote it (NaN stays NaN, not JSON's null), bounded in length. */
const show = (value: unknown): string => excerpt(value);

const finite = z.number({ error: (i) => (i.input === undefined ? 'is missing' : `must be a number, got ${show(i.input)}`) }).check(z.refine(Number.isFinite, 'must be a finite number'));
const dimension = finite.check(z.refine((v) => v >= SCENE_LIMITS.minDimension && v <= SCENE_LIMITS.maxDimension, { error: (i) => `${show(i.input)} m is outside ${SCENE_LIMITS.minDimension}..${SCENE_LIMITS.maxDimension} m` }));
const reflectanceValue = finite.check(
  z.refine((v) => v >= 0 && v < 1, {
    error: (i) => `reflectance ${show(i.input)} is outside [0, 1) (at 1 a closed room would never lose light)`,
  }),
);
const reflectance = z.union([reflectanceValue, z.tuple([reflectanceValue, reflectanceValue, reflectanceValue])], {
  error: (i) => (i.input === undefined ? 'is missing' : `must be a number in [0, 1) or [r, g, b], got ${show(i.input)}`),
});
const vec3 = z.tuple([finite, finite, finite], { error: (i) => `must be [x, y, z] in metres, got ${show(i.input)}` });
const angle = z.optional(finite);

/** A mesh file luxbox reads, or the configurator's `object:<id>` (docs/scene-format.md, "Objects"). */
const MESH_REFERENCE = /(\.(obj|gltf|glb)$)|(^object:)/i;

const sceneObject = z.strictObject(
  {
    mesh: z.string({ error: 'must be a path to an OBJ, glTF or GLB file' }).check(
      z.minLength(1, 'must not be empty'),
      z.refine((p) => MESH_REFERENCE.test(p), { error: (i) => `${show(i.input)} is not an .obj, .gltf or .glb file` }),
    ),
    position: vec3,
    yaw: angle,
    scale: z.optional(
      finite.check(
        z.refine((v) => v >= SCENE_LIMITS.minObjectScale && v <= SCENE_LIMITS.maxObjectScale, {
          error: (i) => `scale ${show(i.input)} is outside ${SCENE_LIMITS.minObjectScale}..${SCENE_LIMITS.maxObjectScale}`,
        }),
      ),
    ),
    reflectance: z.optional(reflectance),
    id: z.optional(z.string({ error: 'must be a string' })),
  },
  { error: 'must be an object' },
);

const schema = z.strictObject(
  {
    version: z.union([z.literal(1), z.literal(2)]),
    nearField: z.optional(z.enum(NEAR_FIELD_MODELS, { error: (i) => `must be "split" or "point", got ${show(i.input)}` })),
    objects: z.optional(z.array(sceneObject, { error: 'must be an array' }).check(z.maxLength(SCENE_LIMITS.maxObjects, `more than ${SCENE_LIMITS.maxObjects} objects`))),
    // Read by parseDaylight (parseDaylight.ts), which names every field's problem itself.
    windows: z.optional(z.custom<unknown>()),
    sky: z.optional(z.custom<unknown>()),
    room: z.strictObject(
      {
        width: dimension,
        height: dimension,
        depth: dimension,
        reflectance: z.strictObject(Object.fromEntries(SURFACE_NAMES.map((s) => [s, reflectance])) as Record<SurfaceName, typeof reflectance>, {
          error: (i) => (i.input === undefined ? 'is missing' : 'must be an object with floor, ceiling, north, south, west, east'),
        }),
      },
      { error: (i) => (i.input === undefined ? 'is missing' : 'must be an object') },
    ),
    luminaires: z
      .array(
        z.strictObject(
          {
            photometry: z.string({ error: 'must be a path to an IES or LDT file' }).check(z.minLength(1, 'must not be empty')),
            position: vec3,
            yaw: angle,
            pitch: angle,
            roll: angle,
            dimming: z.optional(finite.check(z.refine((v) => v >= 0 && v <= 1, { error: (i) => `dimming ${show(i.input)} is outside 0..1` }))),
            color: z.optional(z.tuple([finite, finite, finite], { error: 'must be [r, g, b]' }).check(z.refine((c) => c.every((x) => x >= 0 && x <= SCENE_LIMITS.maxColor), `colour components must lie in 0..${SCENE_LIMITS.maxColor}`))),
            id: z.optional(z.string({ error: 'must be a string' })),
          },
          { error: 'must be an object' },
        ),
        { error: (i) => (i.input === undefined ? 'is missing' : 'must be an array') },
      )
      .check(z.maxLength(SCENE_LIMITS.maxLuminaires, `more than ${SCENE_LIMITS.maxLuminaires} luminaires`)),
  },
  { error: 'a lighting scene must be a JSON object' },
);

/** Version 3 (issue 29): a version-2 scene whose room is any shape (roomSchema: outline, height, slopes, openings, reflectance). */
const schemaV3 = z.extend(schema, { version: z.literal(3), room: roomSchema });

/** The structure zod checks (tests walk it to reach every numeric field). */
export const lightingSceneSchema: z.ZodMiniType = schema;
/** The version-3 structure. */
export const lightingSceneSchemaV3: z.ZodMiniType = schemaV3;

// `transmittance` is read off a version-3 opening before roomSchema sees it (withoutGlazing): named here so a misspelling gets its suggestion.
const FIELD_NAMES = new Set([...schemaFieldNames(schema), ...schemaFieldNames(schemaV3), 'transmittance']);

/** Fields of a box room (versions 1 and 2) and of a version-3 room: a file that mixes them is told which version means what. */
const BOX_ROOM_FIELDS = ['width', 'depth'] as const;
const SHAPED_ROOM_FIELDS = ['outline', 'slopes', 'openings'] as const;

/**
 * The checks before the structure: object, version, version-2 fields in a
 * version-1 file, and the version-2 features this program cannot bake yet.
 * Returns the problem as `path: message`, or null.
 */
function versionProblem(json: unknown): string | null {
  if (typeof json !== 'object' || json === null || Array.isArray(json)) return 'a lighting scene must be a JSON object';
  const doc = json as Record<string, unknown>;
  const v = doc.version;
  if (v === undefined) return 'version: is missing (1, 2 or 3)';
  if (typeof v === 'number' && Number.isInteger(v) && v > LIGHTING_SCENE_VERSION) {
    return `version: made by a newer luxbox (version ${show(v)}; this one reads versions 1 to ${LIGHTING_SCENE_VERSION})`;
  }
  if (v !== 1 && v !== 2 && v !== 3) return `version: unsupported version ${show(v)} (this program reads versions 1 to ${LIGHTING_SCENE_VERSION})`;
  for (const field of V2_FIELDS) {
    if (v === 1 && field in doc) return `${field}: needs "version": 2 (this file says version 1)`;
  }
  const room = doc.room;
  if (typeof room === 'object' && room !== null && !Array.isArray(room)) {
    if (v === 3) {
      const box = BOX_ROOM_FIELDS.find((f) => f in room);
      if (box) return `room.${box}: a version-3 room has an outline instead of width and depth (or say "version": 2 for a box)`;
    } else {
      const shaped = SHAPED_ROOM_FIELDS.find((f) => f in room);
      if (shaped) return `room.${shaped}: needs "version": 3 (this file says version ${v})`;
    }
  }
  if (v === 3 && 'windows' in doc) return 'windows: a version-3 room has its windows in room.openings (kind "window", with "transmittance")';
  return null;
}

/** Validate a parsed JSON value as a lighting scene; `source` (a file name) prefixes every message. */
export function parseLightingScene(json: unknown, source: string): LightingScene {
  // Depth and length first: nothing below may recurse into a hostile value.
  const problem = jsonShapeProblem(json) ?? versionProblem(json);
  if (problem) throw new LightingSceneError(`${source}: ${problem}`);
  if ((json as { version: unknown }).version === 3) return parseVersion3(json, source);
  const result = safeParseInEnglish(schema, json);
  if (!result.success) {
    // Report the first problem with its field path: one line, as the CLI prints it.
    const described = describeIssues(result.error.issues, FIELD_NAMES);
    throw new LightingSceneError(`${source}: ${described.replace(/^\(root\): /, '')}`);
  }
  const { version, nearField, room, luminaires, objects } = result.data;
  const bounds = [room.width, room.height, room.depth];
  const names = [
    ['west wall (x = 0)', 'east wall (x = width %)'],
    ['floor (y = 0)', 'ceiling (height %)'],
    ['north wall (z = 0)', 'south wall (z = depth %)'],
  ];
  luminaires.forEach((l, i) => {
    for (let a = 0; a < 3; a++) {
      const v = l.position[a];
      const where = `${source}: luminaires[${i}].position[${a}]: ${v} m is`;
      // Written so that NaN fails (zod refuses it already; a bounds check must never pass it): issue 32.
      if (!(v >= 0)) throw new LightingSceneError(`${where} ${a === 1 ? 'below the' : 'outside the'} ${names[a][0]}: luminaires must be inside the room`);
      if (!(v <= bounds[a])) {
        const limit = names[a][1].replace('%', `${bounds[a]} m`);
        throw new LightingSceneError(`${where} ${a === 1 ? 'above the' : 'beyond the'} ${limit}: luminaires must be inside the room`);
      }
    }
  });
  const daylight = parseDaylight(json as { windows?: unknown; sky?: unknown; room?: unknown }, source);
  return {
    version,
    ...(nearField !== undefined ? { nearField } : {}),
    room: boxWithWindows({ width: room.width, height: room.height, depth: room.depth, reflectance: room.reflectance }, daylight.windows, source),
    luminaires: readLuminaires(luminaires),
    ...readObjects(objects),
    ...boxDaylight(daylight),
  };
}

/**
 * A version-2 box with windows becomes the room of any shape that means the same (boxRoomInput,
 * boxWindowsAsOpenings): the windows are openings of kind "window" in its walls, baked as the
 * issue-29 rooms are. A window in the ceiling (a skylight) has no version-3 form yet and is refused.
 */
function boxWithWindows(room: LightingRoom, windows: readonly SceneWindow[], source: string): LightingRoom {
  if (windows.length === 0) return room;
  const { openings, skylights } = boxWindowsAsOpenings(windows, room);
  if (skylights.length > 0) throw new LightingSceneError(`${source}: windows[${skylights[0]}].wall: a window in the ceiling (a skylight) is not baked yet; put it in a wall`);
  const input = boxRoomInput({ width: room.width, height: room.height, depth: room.depth, reflectance: room.reflectance });
  return { ...room, shape: normaliseRoom({ ...input, openings: openings.map(({ window: _, ...o }) => o) }) };
}

/** The daylight of a version-2 scene: its sky, its windows and their glazing by opening index (the windows in order, as boxWithWindows makes them openings). */
function boxDaylight(daylight: SceneDaylight): Pick<LightingScene, 'daylight'> {
  if (daylight.windows.length === 0 && !daylight.sky) return {};
  return { daylight: { ...(daylight.sky ? { sky: daylight.sky } : {}), windows: daylight.windows, transmittance: Object.fromEntries(daylight.windows.map((w, i) => [i, w.transmittance])) } };
}

type ParsedLuminaire = z.infer<typeof schema>['luminaires'][number];
type ParsedObject = NonNullable<z.infer<typeof schema>['objects']>[number];

function readLuminaires(luminaires: readonly ParsedLuminaire[]): LightingScene['luminaires'] {
  return luminaires.map((l) => ({
    photometry: l.photometry,
    position: l.position,
    yaw: l.yaw ?? 0,
    pitch: l.pitch ?? 0,
    roll: l.roll ?? 0,
    ...(l.dimming !== undefined ? { dimming: l.dimming } : {}),
    ...(l.color !== undefined ? { color: l.color } : {}),
    ...(l.id !== undefined ? { id: l.id } : {}),
  }));
}

/** Where a placed mesh lies is known only once it is loaded: resolveBakeScene checks it against the room. */
function readObjects(objects: readonly ParsedObject[] | undefined): Pick<LightingScene, 'objects'> {
  if (objects === undefined) return {};
  return {
    objects: objects.map((o) => ({
      mesh: o.mesh,
      position: o.position,
      yaw: o.yaw ?? 0,
      scale: o.scale ?? 1,
      ...(o.reflectance !== undefined ? { reflectance: o.reflectance } : {}),
      ...(o.id !== undefined ? { id: o.id } : {}),
    })),
  };
}

/** How far (metres) a luminaire's photometric centre may lie outside a version-3 room's surfaces: float noise of a lamp written on a wall or under a slope. */
const SHAPED_ROOM_TOLERANCE = 1e-6;

/** Why a point is not inside a room of any shape (outside the outline, below the floor, above the ceiling or a slope), or null. */
function outsideShapedRoom(room: ShapedRoom, p: readonly [number, number, number], tolerance: number): string | null {
  if (pointInsideRoom(room, p, tolerance)) return null;
  if (!pointInsideRoom(room, [p[0], 0, p[2]], tolerance)) return `(${p[0]}, ${p[2]}) in plan is outside the room's outline`;
  if (!(p[1] >= -tolerance)) return `${p[1]} m is below the floor`;
  const ceiling = Math.min(...room.ceilingPlanes.map((c) => c.c + c.gx * p[0] + c.gz * p[2]));
  const under = room.ceilingPlanes.findIndex((c) => c.c + c.gx * p[0] + c.gz * p[2] === ceiling);
  const what = under <= 0 ? `the ceiling (${round3(ceiling)} m)` : `slope ${room.slopes[under - 1].inputIndex} (${round3(ceiling)} m there)`;
  return `${p[1]} m is above ${what}`;
}

const round3 = (v: number): number => Math.round(v * 1000) / 1000;

/**
 * Version 3: the room by roomSchema (structure, then the room's own rules at their paths), then
 * every luminaire's photometric centre and every object's origin inside it (the outline, under
 * the ceiling and every slope); an object's whole mesh is checked once loaded (resolveBakeScene).
 */
function parseVersion3(json: unknown, source: string): LightingScene {
  const doc = json as { room?: { openings?: unknown }; sky?: unknown };
  // Glazing first (its own messages), then the room's schema on openings without it.
  const written = [...parseOpeningTransmittance(doc.room?.openings, source)].filter((e): e is [number, TransmittanceValue] => e[1] !== undefined);
  const sky = doc.sky === undefined ? undefined : parseSky(doc.sky, source);
  const result = safeParseInEnglish(schemaV3, withoutGlazing(json));
  if (!result.success) throw new LightingSceneError(`${source}: ${describeIssues(result.error.issues, FIELD_NAMES).replace(/^\(root\): /, '')}`);
  const { nearField, room: input, luminaires, objects } = result.data;
  // roomSchema has checked every rule normaliseRoom enforces, so this never throws here.
  const shape = normaliseRoom(input as RoomInput);
  luminaires.forEach((l, i) => {
    const why = outsideShapedRoom(shape, l.position, SHAPED_ROOM_TOLERANCE);
    if (why) throw new LightingSceneError(`${source}: luminaires[${i}].position: ${why}: luminaires must be inside the room`);
  });
  (objects ?? []).forEach((o, i) => {
    const why = outsideShapedRoom(shape, o.position, OBJECT_ROOM_TOLERANCE);
    if (why) throw new LightingSceneError(`${source}: objects[${i}].position: ${why}: objects must be inside the room`);
  });
  const xs = shape.corners.map((c) => c[0]);
  const zs = shape.corners.map((c) => c[1]);
  const room: LightingRoom = { width: Math.max(...xs) - Math.min(...xs), height: shape.height, depth: Math.max(...zs) - Math.min(...zs), reflectance: boxReflectanceOf(shape), shape };
  return {
    version: 3,
    ...(nearField !== undefined ? { nearField } : {}),
    room,
    luminaires: readLuminaires(luminaires),
    ...readObjects(objects),
    ...(sky || written.length > 0 ? { daylight: { ...(sky ? { sky } : {}), windows: [], transmittance: Object.fromEntries(written) } } : {}),
  };
}

/** The document with `transmittance` taken off the room's openings (parseOpeningGlazing has read it; roomSchema, shared with configurations, does not know it). */
function withoutGlazing(json: unknown): unknown {
  const doc = json as { room?: unknown };
  const room = doc.room as { openings?: unknown } | undefined;
  if (typeof room !== 'object' || room === null || !Array.isArray(room.openings)) return json;
  const openings = room.openings.map((o: unknown) => {
    if (typeof o !== 'object' || o === null || !('transmittance' in o)) return o;
    const { transmittance: _, ...rest } = o as Record<string, unknown>;
    return rest;
  });
  return { ...doc, room: { ...room, openings } };
}
