/**
 * The configurator's own file format ("luxbox-configuration", versioned JSON)
 * and its URL-safe share-string form. Reading checks, in order: JSON syntax,
 * the format tag, the version (migrating older ones), the structure (zod,
 * naming the field), the catalog id, and finally validate() so a loaded
 * configuration is as valid as one built through actions.
 */
import { z } from 'zod';
import { InputError } from '../inputError';
import { DISTRIBUTIONS, formatPath, type Catalog } from './catalogSchema';
import { DEFAULT_REFLECTANCE, type Configuration } from './configuration';
import { SURFACE_NAMES, type Reflectance, type SurfaceName } from './lightingScene';
import { capReflectance } from './reflectance';
import { validate } from './validate';

export const SCENE_FILE_FORMAT = 'luxbox-configuration';
export const SCENE_FILE_VERSION = 1;
/** Share strings longer than this are refused before decoding (browsers cap URLs near 64k). */
export const MAX_SHARE_STRING = 60_000;

export class SceneFileError extends InputError {
  override name = 'SceneFileError';
}

/**
 * Read side of a reflectance: [0, 1) as version 1 files have always allowed. Channels above
 * MAX_REFLECTANCE (0.95, src/model/reflectance.ts) in files written before that cap are lowered
 * to it on load (normaliseRoom), so old files keep loading; new files never hold them.
 */
const reflectance = z.union([z.number().min(0).lt(1), z.tuple([z.number().min(0).lt(1), z.number().min(0).lt(1), z.number().min(0).lt(1)])]);
const id = z.string().regex(/^[A-Za-z0-9_-]{1,64}$/, 'must be 1-64 letters, digits, _ or -');

const configurationSchema = z.object({
  room: z.object({
    width: z.number(),
    depth: z.number(),
    height: z.number(),
    // Optional per surface and as a whole: a hand-written file may leave out the finishes, which then default.
    reflectance: z
      .object(Object.fromEntries(SURFACE_NAMES.map((s) => [s, reflectance.optional()])) as Record<(typeof SURFACE_NAMES)[number], z.ZodOptional<typeof reflectance>>)
      .optional(),
  }),
  systems: z.array(
    z.object({
      id,
      presetId: z.string().optional(),
      x: z.number(),
      z: z.number(),
      rotation: z.number(),
      suspension: z.number(),
      rails: z.array(
        z.object({
          id,
          length: z.number(),
          distribution: z.enum(DISTRIBUTIONS),
          modules: z.array(z.object({ id, type: z.string(), beam: z.string(), cct: z.number(), dimming: z.number() })),
        }),
      ),
      joints: z.array(z.object({ connector: z.string(), turn: z.number() })),
    }),
  ),
  nextId: z.number().int().positive(),
});

const fileSchema = z.object({
  format: z.literal(SCENE_FILE_FORMAT),
  version: z.literal(SCENE_FILE_VERSION),
  catalog: z.string(),
  configuration: configurationSchema,
});

export type SceneFile = z.infer<typeof fileSchema>;

/**
 * Migration hook: migrations[n] turns a version-n document into version n+1.
 * Version 1 is the first, so there is nothing to migrate yet; a future version
 * adds its step here and bumps SCENE_FILE_VERSION.
 */
export const migrations: Record<number, (doc: Record<string, unknown>) => Record<string, unknown>> = {};

export function migrateSceneFile(doc: Record<string, unknown>): Record<string, unknown> {
  let d = doc;
  while (typeof d.version === 'number' && d.version < SCENE_FILE_VERSION) {
    const step = migrations[d.version];
    if (!step) throw new SceneFileError(`scene file version ${d.version} is no longer supported`);
    d = step(d);
  }
  return d;
}

export function toSceneFile(config: Configuration, catalog: Catalog): SceneFile {
  return { format: SCENE_FILE_FORMAT, version: SCENE_FILE_VERSION, catalog: catalog.id, configuration: config as SceneFile['configuration'] };
}

/** Pretty JSON for saving to disk or the host page. */
export function serializeConfiguration(config: Configuration, catalog: Catalog, space: number | undefined = 2): string {
  return JSON.stringify(toSceneFile(config, catalog), null, space);
}

/** Reads a scene file's text; throws SceneFileError (an InputError) saying what is wrong and where. */
export function deserializeConfiguration(text: string, catalog: Catalog, source = 'scene file'): Configuration {
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch (e) {
    throw new SceneFileError(`${source} is not valid JSON (${(e as Error).message})`);
  }
  return configurationFromData(data, catalog, source);
}

/** Like deserializeConfiguration, for already parsed JSON (e.g. from a host page). */
export function configurationFromData(data: unknown, catalog: Catalog, source = 'scene file'): Configuration {
  if (typeof data !== 'object' || data === null || Array.isArray(data)) throw new SceneFileError(`${source} is not a luxbox configuration (expected a JSON object)`);
  const doc = data as Record<string, unknown>;
  if (doc.format !== SCENE_FILE_FORMAT) {
    if ('luminaires' in doc) throw new SceneFileError(`${source} is a lighting scene (input of luxbox bake), not a configuration file`);
    throw new SceneFileError(`${source} is not a luxbox configuration (format must be '${SCENE_FILE_FORMAT}')`);
  }
  if (typeof doc.version !== 'number' || !Number.isInteger(doc.version) || doc.version < 1) throw new SceneFileError(`${source}: version must be a positive integer`);
  if (doc.version > SCENE_FILE_VERSION) throw new SceneFileError(`${source} was written by a newer luxbox (version ${doc.version}; this one reads up to ${SCENE_FILE_VERSION})`);
  const r = fileSchema.safeParse(migrateSceneFile(doc));
  if (!r.success) {
    const issue = r.error.issues[0];
    throw new SceneFileError(`${source}: ${formatPath(issue.path)}: ${issue.message}`);
  }
  if (r.data.catalog !== catalog.id) throw new SceneFileError(`${source} was made for catalog '${r.data.catalog}', but this configurator uses '${catalog.id}'`);
  const config = normaliseRoom(r.data.configuration);
  const problems = validate(config, catalog);
  if (problems.length > 0) throw new SceneFileError(`${source}: configuration.${problems[0].path}: ${problems[0].message}`);
  return config;
}

/** Fills left-out reflectances with DEFAULT_REFLECTANCE and caps legacy values above MAX_REFLECTANCE. */
function normaliseRoom(data: SceneFile['configuration']): Configuration {
  const given: Partial<Record<SurfaceName, Reflectance>> = data.room.reflectance ?? {};
  const reflectance = Object.fromEntries(SURFACE_NAMES.map((s) => [s, capReflectance(given[s] ?? DEFAULT_REFLECTANCE[s])])) as Record<SurfaceName, Reflectance>;
  return { ...data, room: { ...data.room, reflectance } } as Configuration;
}

/** base64url (RFC 4648 §5, no padding) of the compact scene-file JSON, for share links. */
export function encodeShareString(config: Configuration, catalog: Catalog): string {
  const bytes = new TextEncoder().encode(serializeConfiguration(config, catalog, undefined));
  let bin = '';
  for (const b of bytes) bin += String.fromCharCode(b);
  return btoa(bin).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

export function decodeShareString(s: string, catalog: Catalog): Configuration {
  if (s.length === 0) throw new SceneFileError('share link is empty');
  if (s.length > MAX_SHARE_STRING) throw new SceneFileError(`share link is too long (${s.length} characters, at most ${MAX_SHARE_STRING})`);
  if (!/^[A-Za-z0-9_-]+$/.test(s)) throw new SceneFileError('share link is damaged (characters outside base64url)');
  if (s.length % 4 === 1) throw new SceneFileError('share link is damaged (truncated)');
  const bin = atob(s.replace(/-/g, '+').replace(/_/g, '/') + '='.repeat((4 - (s.length % 4)) % 4));
  let text: string;
  try {
    text = new TextDecoder('utf-8', { fatal: true }).decode(Uint8Array.from(bin, (c) => c.charCodeAt(0)));
  } catch {
    throw new SceneFileError('share link is damaged (not UTF-8 text)');
  }
  return deserializeConfiguration(text, catalog, 'share link');
}
