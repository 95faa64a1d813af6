/**
 * Reading a lighting scene (versions 1 and 2, docs/scene-format.md) from
 * untrusted JSON: size and shape limits (untrustedJson.ts),
 * the version, structure and types with zod (strict: an unknown field is
 * refused, naming it, with a suggestion for a misspelling), then the physical
 * checks zod cannot express (a lamp inside the room; an object's mesh inside
 * the room is checked once loaded, by resolveBakeScene). Every error is one line
 * naming the source and the field, e.g.
 * `scene.json: luminaires[2].position[1]: 3.1 m is above the ceiling (height 2.8 m)`.
 * Limits are in SCENE_LIMITS and docs/scene-format.md.
 */
import { z } from 'zod';
import { InputError } from '../../inputError';
import { NEAR_FIELD_MODELS, SURFACE_NAMES, type LightingScene, type SurfaceName } from './lightingScene';
import { excerpt, jsonShapeProblem, oneLine } from '../../untrustedJson';
import { describeIssues, schemaFieldNames } from '../../zodIssues';

export class LightingSceneError extends InputError {
  override name = 'LightingSceneError';
  constructor(message: string) {
    super(oneLine(message));
  }
}

/** Newest lighting scene version this program reads. */
export const LIGHTING_SCENE_VERSION = 2;

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

const finite = z.number({ error: (i) => (i.input === undefined ? 'is missing' : `must be a number, got ${show(i.input)}`) }).refine(Number.isFinite, 'must be a finite number');
const dimension = finite.refine((v) => v >= SCENE_LIMITS.minDimension && v <= SCENE_LIMITS.maxDimension, { error: (i) => `${show(i.input)} m is outside ${SCENE_LIMITS.minDimension}..${SCENE_LIMITS.maxDimension} m` });
const reflectanceValue = finite.refine((v) => v >= 0 && v < 1, {
  error: (i) => `reflectance ${show(i.input)} is outside [0, 1) (at 1 a closed room would never lose light)`,
});
const reflectance = z.union([reflectanceValue, z.tuple([reflectanceValue, reflectanceValue, reflectanceValue])], {
  error: (i) => (i.input === undefined ? 'is missing' : `must be a number in [0, 1) or [r, g, b], got ${show(i.input)}`),
});
const vec3 = z.tuple([finite, finite, finite], { error: (i) => `must be [x, y, z] in metres, got ${show(i.input)}` });
const angle = finite.optional();

/** A mesh file luxbox reads, or the configurator's `object:<id>` (docs/scene-format.md, "Objects"). */
const MESH_REFERENCE = /(\.(obj|gltf|glb)$)|(^object:)/i;

const sceneObject = z.strictObject(
  {
    mesh: z
      .string({ error: 'must be a path to an OBJ, glTF or GLB file' })
      .min(1, 'must not be empty')
      .refine((p) => MESH_REFERENCE.test(p), { error: (i) => `${show(i.input)} is not an .obj, .gltf or .glb file` }),
    position: vec3,
    yaw: angle,
    scale: finite
      .refine((v) => v >= SCENE_LIMITS.minObjectScale && v <= SCENE_LIMITS.maxObjectScale, {
        error: (i) => `scale ${show(i.input)} is outside ${SCENE_LIMITS.minObjectScale}..${SCENE_LIMITS.maxObjectScale}`,
      })
      .optional(),
    reflectance: reflectance.optional(),
    id: z.string({ error: 'must be a string' }).optional(),
  },
  { error: 'must be an object' },
);

const schema = z.strictObject(
  {
    version: z.union([z.literal(1), z.literal(2)]),
    nearField: z.enum(NEAR_FIELD_MODELS, { error: (i) => `must be "split" or "point", got ${show(i.input)}` }).optional(),
    objects: z.array(sceneObject, { error: 'must be an array' }).max(SCENE_LIMITS.maxObjects, `more than ${SCENE_LIMITS.maxObjects} objects`).optional(),
    // Checked before zod (a clear "not baked yet"); only empty lists reach here.
    windows: z.array(z.never()).optional(),
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
            photometry: z.string({ error: 'must be a path to an IES or LDT file' }).min(1, 'must not be empty'),
            position: vec3,
            yaw: angle,
            pitch: angle,
            roll: angle,
            dimming: finite.refine((v) => v >= 0 && v <= 1, { error: (i) => `dimming ${show(i.input)} is outside 0..1` }).optional(),
            color: z
              .tuple([finite, finite, finite], { error: 'must be [r, g, b]' })
              .refine((c) => c.every((x) => x >= 0 && x <= SCENE_LIMITS.maxColor), `colour components must lie in 0..${SCENE_LIMITS.maxColor}`)
              .optional(),
            id: z.string({ error: 'must be a string' }).optional(),
          },
          { error: 'must be an object' },
        ),
        { error: (i) => (i.input === undefined ? 'is missing' : 'must be an array') },
      )
      .max(SCENE_LIMITS.maxLuminaires, `more than ${SCENE_LIMITS.maxLuminaires} luminaires`),
  },
  { error: 'a lighting scene must be a JSON object' },
);

/** The structure zod checks (tests walk it to reach every numeric field). */
export const lightingSceneSchema: z.ZodType = schema;

const FIELD_NAMES = new Set([...schemaFieldNames(schema), 'sky']);

/**
 * The checks before the structure: object, version, version-2 fields in a
 * version-1 file, and the version-2 features this program cannot bake yet.
 * Returns the problem as `path: message`, or null.
 */
function versionProblem(json: unknown): string | null {
  if (typeof json !== 'object' || json === null || Array.isArray(json)) return 'a lighting scene must be a JSON object';
  const doc = json as Record<string, unknown>;
  const v = doc.version;
  if (v === undefined) return 'version: is missing (1 or 2)';
  if (typeof v === 'number' && Number.isInteger(v) && v > LIGHTING_SCENE_VERSION) {
    return `version: made by a newer luxbox (version ${show(v)}; this one reads versions 1 and 2)`;
  }
  if (v !== 1 && v !== 2) return `version: unsupported version ${show(v)} (this program reads versions 1 and 2)`;
  for (const field of V2_FIELDS) {
    if (v === 1 && field in doc) return `${field}: needs "version": 2 (this file says version 1)`;
  }
  for (const field of ['windows'] as const) {
    const list = doc[field];
    if (list === undefined) continue;
    if (!Array.isArray(list)) return `${field}: must be an array`;
    if (list.length > 0) return `${field}: this luxbox does not bake ${field} yet (remove them or use a newer luxbox)`;
  }
  if ('sky' in doc) return 'sky: this luxbox does not bake a sky yet (remove it or use a newer luxbox)';
  return null;
}

/** Validate a parsed JSON value as a lighting scene; `source` (a file name) prefixes every message. */
export function parseLightingScene(json: unknown, source: string): LightingScene {
  // Depth and length first: nothing below may recurse into a hostile value.
  const problem = jsonShapeProblem(json) ?? versionProblem(json);
  if (problem) throw new LightingSceneError(`${source}: ${problem}`);
  const result = schema.safeParse(json);
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
  return {
    version,
    ...(nearField !== undefined ? { nearField } : {}),
    room: { width: room.width, height: room.height, depth: room.depth, reflectance: room.reflectance },
    luminaires: luminaires.map((l) => ({
      photometry: l.photometry,
      position: l.position,
      yaw: l.yaw ?? 0,
      pitch: l.pitch ?? 0,
      roll: l.roll ?? 0,
      ...(l.dimming !== undefined ? { dimming: l.dimming } : {}),
      ...(l.color !== undefined ? { color: l.color } : {}),
      ...(l.id !== undefined ? { id: l.id } : {}),
    })),
    // Where a placed mesh lies is known only once it is loaded: resolveBakeScene checks it against the room.
    ...(objects !== undefined
      ? {
          objects: objects.map((o) => ({
            mesh: o.mesh,
            position: o.position,
            yaw: o.yaw ?? 0,
            scale: o.scale ?? 1,
            ...(o.reflectance !== undefined ? { reflectance: o.reflectance } : {}),
            ...(o.id !== undefined ? { id: o.id } : {}),
          })),
        }
      : {}),
  };
}
