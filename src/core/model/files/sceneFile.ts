/**
 * The configurator's own file format ("luxbox-configuration", versioned JSON): its reader and
 * writer. Its structure is sceneFileSchema.ts, its version steps migrations/, its URL-safe
 * share-string form shareLink.ts. Reading checks, in order: size, JSON
 * syntax, duplicate keys, nesting depth and array lengths (untrustedJson.ts),
 * the format tag, the version (migrating older ones), the structure (strict
 * zod: unknown fields refused, naming the field), the catalog id, and finally
 * validate() (first problem, cheap checks before pair checks) so a loaded
 * configuration is as valid as one built through actions. Every message is
 * one line of at most 200 characters.
 */
import { codedText, type CodedText } from '../../inputError';
import type { Catalog } from '../catalogSchema/catalogSchema';
import { DEFAULT_REFLECTANCE, type Configuration, type ImportedMesh, type RoomObject } from '../configuration/configuration';
import { decodeMesh, encodeMesh } from './meshCodec';
import { SURFACE_NAMES, type Reflectance, type SurfaceName } from '../lightingScene/lightingScene';
import { capReflectance } from '../lightingScene/reflectance';
import { excerpt, INPUT_LIMITS, jsonShapeIssue, parseUntrustedJson, unquoted } from '../../untrustedJson';
import { describeIssueCoded, schemaFieldNames } from '../../zodIssues';
import { problemText } from '../configuration/coding';
import { validate } from '../validation/validate';
import { migrateSceneFile } from './migrations/migrateSceneFile';
import { SceneFileError } from './sceneFileError';
import { roomShapeSupport, RoomShapeSupportMissing } from '../configuration/roomShapeSupport';
import { fileSchema, SCENE_FILE_FORMAT, SCENE_FILE_VERSION, type SceneFile } from './sceneFileSchema';
import { safeParseInEnglish } from '../../zodEnglish';

/** Largest scene file text (characters), as for lighting scenes. */
export const MAX_SCENE_FILE_TEXT = INPUT_LIMITS.maxTextLength;

/** An error of the file named `source`, quoting a coded sentence (the problem found at a path). */
function fileProblem(source: string, detail: CodedText): SceneFileError {
  return new SceneFileError(`${source}: ${detail.text}`, { code: 'fileProblem', params: { name: unquoted(source) }, detail });
}

const FIELD_NAMES = schemaFieldNames(fileSchema);

export function toSceneFile(config: Configuration, catalog: Catalog): SceneFile {
  const importedMeshes = Object.fromEntries(Object.entries(config.importedMeshes).map(([key, m]) => [key, { name: m.name, units: m.units, ...encodeMesh(m.mesh) }]));
  // Left out when empty, so a configuration without objects reads the same as it did in version 2.
  const configuration = {
    room: config.room,
    systems: config.systems,
    ...(config.objects.length > 0 ? { objects: config.objects } : {}),
    ...(Object.keys(importedMeshes).length > 0 ? { importedMeshes } : {}),
    ...(config.lightScenes && config.lightScenes.length > 0 ? { lightScenes: config.lightScenes } : {}),
    ...(config.daylight ? { daylight: config.daylight } : {}),
    nextId: config.nextId,
  };
  return { format: SCENE_FILE_FORMAT, version: SCENE_FILE_VERSION, catalog: catalog.id, configuration: configuration as SceneFile['configuration'] };
}

/** Pretty JSON for saving to disk or the host page; `space` 0 for compact JSON (share links). */
export function serializeConfiguration(config: Configuration, catalog: Catalog, space = 2): string {
  return JSON.stringify(toSceneFile(config, catalog), null, space || undefined);
}

/** Reads a scene file's text; throws SceneFileError (an InputError) saying what is wrong and where. */
export function deserializeConfiguration(text: string, catalog: Catalog, source = 'scene file'): Configuration {
  const data = parseUntrustedJson(text, source, (m, coding) => new SceneFileError(m, coding), {
    tooLarge: (size) => `${source} is too large to be a luxbox configuration (${size}; at most ${MAX_SCENE_FILE_TEXT / 1e6} MB)`,
    invalidJson: (where, reason) => `${source} is not valid JSON (${where}${reason})`,
  });
  return configurationFromData(data, catalog, source);
}

/** Like deserializeConfiguration, for already parsed JSON (e.g. from a host page). */
export function configurationFromData(data: unknown, catalog: Catalog, source = 'scene file'): Configuration {
  // Every refusal carries a code and params (docs/i18n.md): `name` is the file as the user named it.
  const name = unquoted(source);
  if (typeof data !== 'object' || data === null || Array.isArray(data)) throw new SceneFileError(`${source} is not a luxbox configuration (expected a JSON object)`, { code: 'fileNotObject', params: { name } });
  // Depth and length first (a host page may hand over anything): nothing below may recurse into a hostile value.
  const shape = jsonShapeIssue(data);
  if (shape) throw fileProblem(source, shape);
  const doc = data as Record<string, unknown>;
  if (doc.format !== SCENE_FILE_FORMAT) {
    if ('luminaires' in doc) throw new SceneFileError(`${source} is a lighting scene (input of luxbox bake), not a configuration file`, { code: 'fileIsLightingScene', params: { name } });
    throw new SceneFileError(`${source} is not a luxbox configuration (format must be '${SCENE_FILE_FORMAT}')`, { code: 'fileWrongFormat', params: { name, format: SCENE_FILE_FORMAT } });
  }
  if (typeof doc.version !== 'number' || !Number.isInteger(doc.version) || doc.version < 1) throw new SceneFileError(`${source}: version must be a positive integer`, { code: 'fileVersionInvalid', params: { name } });
  if (doc.version > SCENE_FILE_VERSION)
    throw new SceneFileError(`${source} was made by a newer luxbox (version ${doc.version}; this one reads up to ${SCENE_FILE_VERSION})`, { code: 'fileTooNew', params: { name, version: doc.version, max: SCENE_FILE_VERSION } });
  let migrated: Record<string, unknown>;
  try {
    migrated = migrateSceneFile(doc, catalog);
  } catch (e) {
    if (e instanceof SceneFileError) throw fileProblem(source, codedText(e.message, e));
    throw e;
  }
  const r = safeParseInEnglish(fileSchema, migrated);
  if (!r.success) throw fileProblem(source, describeIssueCoded(r.error.issues, FIELD_NAMES));
  if (r.data.catalog !== catalog.id) {
    const theirs = excerpt(r.data.catalog).replace(/^"|"$/g, "'");
    throw new SceneFileError(`${source} was made for catalog ${theirs}, but this configurator uses '${catalog.id}'`, { code: 'fileOtherCatalog', params: { name, catalog: theirs.replace(/^'|'$/g, ''), ours: catalog.id } });
  }
  const config = normaliseRoom(withShapeRead(r.data.configuration, source), source);
  const problems = validate(config, catalog, { firstOnly: true });
  if (problems.length > 0) {
    const path = `configuration.${problems[0].path}`;
    throw new SceneFileError(`${source}: ${path}: ${problems[0].message}`, { code: 'fileInvalidAt', params: { name, path }, detail: problemText(problems[0]) });
  }
  return config;
}

/**
 * The room's shape and the daylight (version 10) read by the room-shape chunk (roomShapeSupport.ts),
 * which every caller that may meet one has loaded: before that either is refused
 * (RoomShapeSupportMissing), never dropped.
 */
function withShapeRead(data: SceneFile['configuration'], source: string): SceneFile['configuration'] {
  if (data.room.shape === undefined && data.daylight === undefined) return data;
  const support = roomShapeSupport();
  if (!support) throw new RoomShapeSupportMissing(`${source}: configuration.${data.room.shape === undefined ? 'daylight' : 'room.shape'}`);
  let out = data;
  if (data.room.shape !== undefined) {
    const read = support.readShape(data.room.shape, ['configuration', 'room', 'shape']);
    if ('problem' in read) throw fileProblem(source, read.problem);
    out = { ...out, room: { ...out.room, shape: read.shape } };
  }
  if (data.daylight !== undefined) {
    const read = support.readDaylight(data.daylight, ['configuration', 'daylight']);
    if ('problem' in read) throw fileProblem(source, read.problem);
    out = { ...out, daylight: read.daylight };
  }
  return out;
}

/**
 * Fills left-out reflectances with DEFAULT_REFLECTANCE, caps legacy values above MAX_REFLECTANCE,
 * gives left-out objects and meshes their empty defaults and decodes the meshes' base64 arrays.
 */
function normaliseRoom(data: SceneFile['configuration'], source: string): Configuration {
  const given: Partial<Record<SurfaceName, Reflectance>> = data.room.reflectance ?? {};
  const reflectance = Object.fromEntries(SURFACE_NAMES.map((s) => [s, capReflectance(given[s] ?? DEFAULT_REFLECTANCE[s])])) as Record<SurfaceName, Reflectance>;
  const importedMeshes: Record<string, ImportedMesh> = {};
  for (const [key, m] of Object.entries(data.importedMeshes ?? {})) {
    const mesh = decodeMesh(m);
    if ('problem' in mesh)
      throw new SceneFileError(`${source}: configuration.importedMeshes.${key}.${mesh.field}: ${mesh.problem}`, {
        code: 'fileMeshField',
        params: { name: unquoted(source), path: `configuration.importedMeshes.${key}.${mesh.field}`, problem: mesh.problem },
      });
    importedMeshes[key] = { name: m.name, units: m.units, mesh };
  }
  const { objects, importedMeshes: _encoded, ...rest } = data;
  return { ...rest, room: { ...data.room, reflectance }, objects: (objects ?? []) as RoomObject[], importedMeshes } as Configuration;
}
