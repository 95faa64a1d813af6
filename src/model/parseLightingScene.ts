/**
 * Reading a lighting scene (v1, DESIGN.md "Command-line contract") from
 * untrusted JSON: structure and types with zod, then the physical checks zod
 * cannot express (a lamp inside the room). Every error names the source and
 * the field, e.g.
 * `scene.json: luminaires[2].position[1]: 3.1 m is above the ceiling (height 2.8 m)`.
 * Limits are in SCENE_LIMITS and docs/scene-format.md.
 */
import { z } from 'zod';
import { InputError } from '../inputError';
import { SURFACE_NAMES, type LightingScene, type SurfaceName } from './lightingScene';

export class LightingSceneError extends InputError {
  override name = 'LightingSceneError';
}

export const SCENE_LIMITS = {
  /** Room edges, metres. */
  minDimension: 0.1,
  maxDimension: 500,
  maxLuminaires: 10_000,
  /** Largest colour multiplier per channel (a linear RGB gain, typically ≤ 1). */
  maxColor: 100,
} as const;

/** A value as the user wrote it (NaN stays NaN, not JSON's null). */
function show(value: unknown): string {
  return typeof value === 'number' ? String(value) : JSON.stringify(value);
}

const finite = z.number({ error: (i) => (i.input === undefined ? 'is missing' : `must be a number, got ${show(i.input)}`) }).refine(Number.isFinite, 'must be a finite number');
const dimension = finite.refine(
  (v) => v >= SCENE_LIMITS.minDimension && v <= SCENE_LIMITS.maxDimension,
  { error: (i) => `${String(i.input)} m is outside ${SCENE_LIMITS.minDimension}..${SCENE_LIMITS.maxDimension} m` },
);
const reflectanceValue = finite.refine((v) => v >= 0 && v < 1, {
  error: (i) => `reflectance ${String(i.input)} is outside [0, 1) (at 1 a closed room would never lose light)`,
});
const reflectance = z.union([reflectanceValue, z.tuple([reflectanceValue, reflectanceValue, reflectanceValue])], {
  error: (i) => (i.input === undefined ? 'is missing' : `must be a number in [0, 1) or [r, g, b], got ${show(i.input)}`),
});
const vec3 = z.tuple([finite, finite, finite], { error: (i) => `must be [x, y, z] in metres, got ${show(i.input)}` });
const angle = finite.optional();

const schema = z.object({
  version: z.literal(1, { error: (i) => `unsupported version ${show(i.input)} (this program reads version 1)` }),
  room: z.object({
    width: dimension,
    height: dimension,
    depth: dimension,
    reflectance: z.object(
      Object.fromEntries(SURFACE_NAMES.map((s) => [s, reflectance])) as Record<SurfaceName, typeof reflectance>,
      { error: (i) => (i.input === undefined ? 'is missing' : 'must be an object with floor, ceiling, north, south, west, east') },
    ),
  }, { error: (i) => (i.input === undefined ? 'is missing' : 'must be an object') }),
  luminaires: z
    .array(
      z.object({
        photometry: z.string({ error: 'must be a path to an IES or LDT file' }).min(1, 'must not be empty'),
        position: vec3,
        yaw: angle,
        pitch: angle,
        roll: angle,
        dimming: finite.refine((v) => v >= 0 && v <= 1, { error: (i) => `dimming ${String(i.input)} is outside 0..1` }).optional(),
        color: z
          .tuple([finite, finite, finite], { error: 'must be [r, g, b]' })
          .refine((c) => c.every((x) => x >= 0 && x <= SCENE_LIMITS.maxColor), `colour components must lie in 0..${SCENE_LIMITS.maxColor}`)
          .optional(),
        id: z.string().optional(),
      }, { error: 'must be an object' }),
      { error: (i) => (i.input === undefined ? 'is missing' : 'must be an array') },
    )
    .max(SCENE_LIMITS.maxLuminaires, `more than ${SCENE_LIMITS.maxLuminaires} luminaires`),
}, { error: 'a lighting scene must be a JSON object' });

function formatPath(path: PropertyKey[]): string {
  let out = '';
  for (const key of path) out += typeof key === 'number' ? `[${key}]` : `${out ? '.' : ''}${String(key)}`;
  return out;
}

/** Validate a parsed JSON value as a lighting scene; `source` (a file name) prefixes every message. */
export function parseLightingScene(json: unknown, source: string): LightingScene {
  const result = schema.safeParse(json);
  if (!result.success) {
    // Report the first problem with its field path: one line, as the CLI prints it.
    const issue = result.error.issues[0];
    const where = formatPath(issue.path);
    throw new LightingSceneError(`${source}: ${where ? `${where}: ` : ''}${issue.message}`);
  }
  const { room, luminaires } = result.data;
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
      if (v < 0) throw new LightingSceneError(`${where} ${a === 1 ? 'below the' : 'outside the'} ${names[a][0]}: luminaires must be inside the room`);
      if (v > bounds[a]) {
        const limit = names[a][1].replace('%', `${bounds[a]} m`);
        throw new LightingSceneError(`${where} ${a === 1 ? 'above the' : 'beyond the'} ${limit}: luminaires must be inside the room`);
      }
    }
  });
  return {
    version: 1,
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
  };
}
