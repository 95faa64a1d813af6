/**
 * The configurator's own file format ("luxbox-configuration", versioned JSON)
 * and its URL-safe share-string form. Reading checks, in order: size, JSON
 * syntax, duplicate keys, nesting depth and array lengths (untrustedJson.ts),
 * the format tag, the version (migrating older ones), the structure (strict
 * zod: unknown fields refused, naming the field), the catalog id, and finally
 * validate() (first problem, cheap checks before pair checks) so a loaded
 * configuration is as valid as one built through actions. Every message is
 * one line of at most 200 characters.
 */
import { z } from 'zod';
import { InputError } from '../inputError';
import { DISTRIBUTIONS, type Catalog } from './catalogSchema';
import { DEFAULT_REFLECTANCE, type Configuration } from './configuration';
import { SURFACE_NAMES, type Reflectance, type SurfaceName } from './lightingScene';
import { capReflectance } from './reflectance';
import { describeIssues, excerpt, INPUT_LIMITS, jsonShapeProblem, oneLine, parseUntrustedJson, schemaFieldNames } from './untrustedJson';
import { validate } from './validate';

export const SCENE_FILE_FORMAT = 'luxbox-configuration';
/** 2: modules may carry a DMX patch (`dmx`, docs/live-control.md); version 1 files are migrated on reading. */
export const SCENE_FILE_VERSION = 2;
/** Share strings longer than this are refused before decoding (browsers cap URLs near 64k). */
export const MAX_SHARE_STRING = 60_000;

/** Largest scene file text (characters), as for lighting scenes. */
export const MAX_SCENE_FILE_TEXT = INPUT_LIMITS.maxTextLength;

export class SceneFileError extends InputError {
  override name = 'SceneFileError';
  constructor(message: string) {
    super(oneLine(message));
  }
}

/**
 * Read side of a reflectance: [0, 1) as version 1 files have always allowed. Channels above
 * MAX_REFLECTANCE (0.95, src/core/model/reflectance.ts) in files written before that cap are lowered
 * to it on load (normaliseRoom), so old files keep loading; new files never hold them.
 */
const reflectance = z.union([z.number().min(0).lt(1), z.tuple([z.number().min(0).lt(1), z.number().min(0).lt(1), z.number().min(0).lt(1)])]);
const id = z.string().regex(/^[A-Za-z0-9_-]{1,64}$/, 'must be 1-64 letters, digits, _ or -');
/** A catalog reference (module type, beam, connector, preset id); validate() checks it exists. */
const ref = z.string().max(200);

// Strict objects: an unknown (misspelt, or newer) field is refused, never dropped.
const configurationSchema = z.strictObject({
  room: z.strictObject({
    width: z.number(),
    depth: z.number(),
    height: z.number(),
    // Optional per surface and as a whole: a hand-written file may leave out the finishes, which then default.
    reflectance: z
      .strictObject(Object.fromEntries(SURFACE_NAMES.map((s) => [s, reflectance.optional()])) as Record<(typeof SURFACE_NAMES)[number], z.ZodOptional<typeof reflectance>>)
      .optional(),
  }),
  systems: z.array(
    z.strictObject({
      id,
      presetId: ref.optional(),
      x: z.number(),
      z: z.number(),
      rotation: z.number(),
      suspension: z.number(),
      rails: z.array(
        z.strictObject({
          id,
          length: z.number(),
          distribution: z.enum(DISTRIBUTIONS),
          modules: z.array(
            z.strictObject({
              id,
              type: ref,
              beam: ref,
              cct: z.number(),
              dimming: z.number(),
              // Ranges, the CCT channel's type and overlaps are validate()'s rules (dmx-range, dmx-overlap).
              dmx: z.strictObject({ universe: z.number(), address: z.number(), resolution: z.union([z.literal(8), z.literal(16)]), cct: z.boolean() }).optional(),
            }),
          ),
        }),
      ),
      joints: z.array(z.strictObject({ connector: ref, turn: z.number() })),
    }),
  ),
  nextId: z.number().int().positive(),
});

const fileSchema = z.strictObject({
  format: z.literal(SCENE_FILE_FORMAT),
  version: z.literal(SCENE_FILE_VERSION),
  catalog: z.string(),
  configuration: configurationSchema,
});

const FIELD_NAMES = schemaFieldNames(fileSchema);

export type SceneFile = z.infer<typeof fileSchema>;

/**
 * Migration hook: migrations[n] turns a version-n document into version n+1.
 * A future version adds its step here and bumps SCENE_FILE_VERSION.
 */
export const migrations: Record<number, (doc: Record<string, unknown>) => Record<string, unknown>> = {
  // 1 → 2: version 2 added the optional DMX patch per module; a version 1 module has none, so its
  // content reads as is. A `dmx` field in a version 1 file was never written by luxbox: refused.
  1(doc) {
    const at = v1PatchField(doc.configuration);
    if (at) throw new SceneFileError(`configuration.${at}: needs "version": 2 (this file says version 1)`);
    return { ...doc, version: 2 };
  },
};

/** Path of the first module carrying `dmx` in a version 1 configuration (its shape is checked later, so every step looks before it leaps). */
function v1PatchField(configuration: unknown): string | null {
  const list = (o: unknown, key: string): unknown[] => (typeof o === 'object' && o !== null && Array.isArray((o as Record<string, unknown>)[key]) ? ((o as Record<string, unknown>)[key] as unknown[]) : []);
  const systems = list(configuration, 'systems');
  for (let i = 0; i < systems.length; i++) {
    const rails = list(systems[i], 'rails');
    for (let k = 0; k < rails.length; k++) {
      const modules = list(rails[k], 'modules');
      for (let n = 0; n < modules.length; n++) {
        const m = modules[n];
        if (typeof m === 'object' && m !== null && 'dmx' in m) return `systems[${i}].rails[${k}].modules[${n}].dmx`;
      }
    }
  }
  return null;
}

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
  if (config.objects.length > 0) throw new SceneFileError('objects cannot be saved by this scene file version yet');
  const { room, systems, nextId } = config;
  return { format: SCENE_FILE_FORMAT, version: SCENE_FILE_VERSION, catalog: catalog.id, configuration: { room, systems, nextId } as unknown as SceneFile['configuration'] };
}

/** Pretty JSON for saving to disk or the host page; `space` 0 for compact JSON (share links). */
export function serializeConfiguration(config: Configuration, catalog: Catalog, space = 2): string {
  return JSON.stringify(toSceneFile(config, catalog), null, space || undefined);
}

/** Reads a scene file's text; throws SceneFileError (an InputError) saying what is wrong and where. */
export function deserializeConfiguration(text: string, catalog: Catalog, source = 'scene file'): Configuration {
  const data = parseUntrustedJson(text, source, (m) => new SceneFileError(m), {
    tooLarge: (size) => `${source} is too large to be a luxbox configuration (${size}; at most ${MAX_SCENE_FILE_TEXT / 1e6} MB)`,
    invalidJson: (where, reason) => `${source} is not valid JSON (${where}${reason})`,
  });
  return configurationFromData(data, catalog, source);
}

/** Like deserializeConfiguration, for already parsed JSON (e.g. from a host page). */
export function configurationFromData(data: unknown, catalog: Catalog, source = 'scene file'): Configuration {
  if (typeof data !== 'object' || data === null || Array.isArray(data)) throw new SceneFileError(`${source} is not a luxbox configuration (expected a JSON object)`);
  // Depth and length first (a host page may hand over anything): nothing below may recurse into a hostile value.
  const shape = jsonShapeProblem(data);
  if (shape) throw new SceneFileError(`${source}: ${shape}`);
  const doc = data as Record<string, unknown>;
  if (doc.format !== SCENE_FILE_FORMAT) {
    if ('luminaires' in doc) throw new SceneFileError(`${source} is a lighting scene (input of luxbox bake), not a configuration file`);
    throw new SceneFileError(`${source} is not a luxbox configuration (format must be '${SCENE_FILE_FORMAT}')`);
  }
  if (typeof doc.version !== 'number' || !Number.isInteger(doc.version) || doc.version < 1) throw new SceneFileError(`${source}: version must be a positive integer`);
  if (doc.version > SCENE_FILE_VERSION) throw new SceneFileError(`${source} was made by a newer luxbox (version ${doc.version}; this one reads up to ${SCENE_FILE_VERSION})`);
  let migrated: Record<string, unknown>;
  try {
    migrated = migrateSceneFile(doc);
  } catch (e) {
    if (e instanceof SceneFileError) throw new SceneFileError(`${source}: ${e.message}`);
    throw e;
  }
  const r = fileSchema.safeParse(migrated);
  if (!r.success) throw new SceneFileError(`${source}: ${describeIssues(r.error.issues, FIELD_NAMES)}`);
  if (r.data.catalog !== catalog.id) throw new SceneFileError(`${source} was made for catalog ${excerpt(r.data.catalog).replace(/^"|"$/g, "'")}, but this configurator uses '${catalog.id}'`);
  const config = normaliseRoom(r.data.configuration);
  const problems = validate(config, catalog, { firstOnly: true });
  if (problems.length > 0) throw new SceneFileError(`${source}: configuration.${problems[0].path}: ${problems[0].message}`);
  return config;
}

/** Fills left-out reflectances with DEFAULT_REFLECTANCE and caps legacy values above MAX_REFLECTANCE. */
function normaliseRoom(data: SceneFile['configuration']): Configuration {
  const given: Partial<Record<SurfaceName, Reflectance>> = data.room.reflectance ?? {};
  const reflectance = Object.fromEntries(SURFACE_NAMES.map((s) => [s, capReflectance(given[s] ?? DEFAULT_REFLECTANCE[s])])) as Record<SurfaceName, Reflectance>;
  return { ...data, room: { ...data.room, reflectance }, objects: [], importedMeshes: {} } as Configuration;
}

/**
 * base64url (RFC 4648 §5, no padding) of the compact scene-file JSON (no indentation), for
 * share links. Links written with indented JSON (before issue 18) decode all the same.
 */
export function encodeShareString(config: Configuration, catalog: Catalog): string {
  const bytes = new TextEncoder().encode(serializeConfiguration(config, catalog, 0));
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
