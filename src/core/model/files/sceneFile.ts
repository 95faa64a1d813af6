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
import { codedText, InputError, type CodedText, type Coding } from '../../inputError';
import { DISTRIBUTIONS, type Catalog } from '../catalogSchema/catalogSchema';
import { plannedFeeds } from '../power/feedLoads';
import { DEFAULT_REFLECTANCE, MESH_UNITS, MOUNTINGS, WALL_NAMES, type Configuration, type LightSystem, type ImportedMesh, type RoomObject } from '../configuration/configuration';
import { decodeMesh, encodeMesh } from './meshCodec';
import { sourceName } from '../objects/objectGeometry';
import { SURFACE_NAMES, type Reflectance, type SurfaceName } from '../lightingScene/lightingScene';
import { capReflectance } from '../lightingScene/reflectance';
import { describeIssueCoded, excerpt, INPUT_LIMITS, jsonShapeIssue, oneLine, parseUntrustedJson, schemaFieldNames, unquoted } from '../../untrustedJson';
import { problemText } from '../configuration/coding';
import { validate } from '../validation/validate';

export const SCENE_FILE_FORMAT = 'luxbox-configuration';
/**
 * 8: a system's rails form a tree: a joint may name the rail it hangs on (`parent`, T and X
 *    connectors), a feed may sit at a branch's free end (`{ end: i }`), docs/model.md "Trees of rails".
 * 7: modules may be switched off (`on`), carry a colour filter (`filter`) and an aim (`aim`); the
 *    configuration may hold light scenes (`lightScenes`), docs/model.md "Light scenes", "Aiming".
 * 6: systems may carry moved fixing points (`fixings`) and joints may use a flexible-angle connector
 *    (any turn within its range), docs/model.md "Flexible connectors", "Moving fixing points".
 * 5: modules may carry a free position along their rail (`offset`, docs/model.md "Free positions").
 * 4: systems carry power feeds (`feeds`) and their mounting (`mounting`), docs/model.md "Power feeds".
 * 3: objects (furniture, imported models) and imported meshes (docs/model.md, "Objects").
 * 2: modules may carry a DMX patch (`dmx`, docs/live-control.md). Older files are migrated on reading.
 */
export const SCENE_FILE_VERSION = 8;
/** Share strings longer than this are refused before decoding (browsers cap URLs near 64k). */
export const MAX_SHARE_STRING = 60_000;

/** Largest scene file text (characters), as for lighting scenes. */
export const MAX_SCENE_FILE_TEXT = INPUT_LIMITS.maxTextLength;

export class SceneFileError extends InputError {
  override name = 'SceneFileError';
  constructor(message: string, coded?: Coding) {
    super(oneLine(message), coded);
  }
}

/** A field a later scene-file version added, in a file that says it is older (coded: docs/i18n.md). */
function needsVersion(path: string, needed: number, version: number): SceneFileError {
  return new SceneFileError(`${path}: needs "version": ${needed} (this file says version ${version})`, { code: 'fileNeedsVersion', params: { path, needed, version } });
}

/** An error of the file named `source`, quoting a coded sentence (the problem found at a path). */
function fileProblem(source: string, detail: CodedText): SceneFileError {
  return new SceneFileError(`${source}: ${detail.text}`, { code: 'fileProblem', params: { name: unquoted(source) }, detail });
}

/**
 * Read side of a reflectance: [0, 1) as version 1 files have always allowed. Channels above
 * MAX_REFLECTANCE (0.95, src/core/model/lightingScene/reflectance.ts) in files written before that cap are lowered
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
              // Version 5: a free position (start, metres from the rail start); its rules are validate()'s (module-past-end, module-overlap).
              offset: z.number().optional(),
              // Version 7: on/off, colour filter and aim; their rules are validate()'s.
              on: z.boolean().optional(),
              filter: ref.optional(),
              aim: z.strictObject({ rotation: z.number(), tilt: z.number() }).optional(),
            }),
          ),
        }),
      ),
      // Version 8: `parent`, the rail whose end the joint's connector sits on; tree rules are validate()'s (joint-parent, node-*).
      joints: z.array(z.strictObject({ connector: ref, turn: z.number(), parent: z.number().optional() })),
      // Version 4 (`{ end: i }` version 8). Positions, drivers and loads are validate()'s rules (feed-position, unknown-driver, feed-overload).
      feeds: z.array(z.strictObject({ id, at: z.union([z.literal('start'), z.literal('end'), z.strictObject({ joint: z.number() }), z.strictObject({ end: z.number() })]), driver: ref })),
      mounting: z.enum(MOUNTINGS),
      // Version 6: moved fixing points (chain coordinates); their rules are validate()'s (fixing-*).
      fixings: z.array(z.number()).optional(),
    }),
  ),
  // Version 3; optional so a hand-written file may leave them out (empty).
  objects: z
    .array(
      z.strictObject({
        id,
        source: z.discriminatedUnion('kind', [z.strictObject({ kind: z.literal('library'), item: ref }), z.strictObject({ kind: z.literal('imported'), mesh: id })]),
        placement: z.discriminatedUnion('on', [
          z.strictObject({ on: z.literal('floor'), x: z.number(), z: z.number() }),
          z.strictObject({ on: z.literal('wall'), wall: z.enum(WALL_NAMES), u: z.number(), y: z.number() }),
        ]),
        yaw: z.number(),
        scale: z.number(),
        // Material names and finish ids are checked against the mesh and the finish list by validate().
        finishes: z.record(z.string().max(200), z.union([ref, z.tuple([z.number(), z.number(), z.number()])])),
      }),
    )
    .optional(),
  importedMeshes: z
    .record(
      id,
      z.strictObject({
        name: z.string().max(200),
        units: z.enum(MESH_UNITS),
        // base64 of the little-endian typed arrays (meshCodec.ts).
        positions: z.string(),
        indices: z.string(),
        materialOfTriangle: z.string(),
        materials: z.array(z.strictObject({ name: z.string().max(200), reflectance: z.tuple([z.number().min(0).lt(1), z.number().min(0).lt(1), z.number().min(0).lt(1)]) })),
      }),
    )
    .optional(),
  // Version 7: light scenes (cues); names, fades, module ids and looks are validate()'s rules.
  lightScenes: z
    .array(
      z.strictObject({
        id,
        name: z.string().max(200),
        fade: z.number(),
        looks: z.record(id, z.strictObject({ on: z.boolean(), level: z.number(), cct: z.number(), filter: ref.optional() })),
      }),
    )
    .optional(),
  nextId: z.number().int().positive(),
});

const fileSchema = z.strictObject({
  format: z.literal(SCENE_FILE_FORMAT),
  version: z.literal(SCENE_FILE_VERSION),
  catalog: z.string(),
  configuration: configurationSchema,
});

/** The structure zod checks (tests walk it to reach every numeric field). */
export const sceneFileSchema: z.ZodType = fileSchema;

const FIELD_NAMES = schemaFieldNames(fileSchema);

export type SceneFile = z.infer<typeof fileSchema>;

/**
 * Migration hook: migrations[n] turns a version-n document into version n+1.
 * A future version adds its step here and bumps SCENE_FILE_VERSION.
 */
export const migrations: Record<number, (doc: Record<string, unknown>, catalog: Catalog) => Record<string, unknown>> = {
  // 1 → 2: version 2 added the optional DMX patch per module; a version 1 module has none, so its
  // content reads as is. A `dmx` field in a version 1 file was never written by luxbox: refused.
  1(doc) {
    const at = v1PatchField(doc.configuration);
    if (at) throw needsVersion(`configuration.${at}`, 2, 1);
    const c = doc.configuration;
    for (const key of ['objects', 'importedMeshes']) {
      if (typeof c === 'object' && c !== null && key in c) throw needsVersion(`configuration.${key}`, 3, 1);
    }
    refuseV4Fields(doc, 1);
    refuseV5Fields(doc, 1);
    refuseV6Fields(doc, 1);
    refuseV7Fields(doc, 1);
    refuseV8Fields(doc, 1);
    return { ...doc, version: 2 };
  },
  // 2 → 3: version 3 added objects and imported meshes; a version 2 configuration has none.
  2(doc) {
    const c = doc.configuration;
    for (const key of ['objects', 'importedMeshes']) {
      if (typeof c === 'object' && c !== null && key in c) throw needsVersion(`configuration.${key}`, 3, 2);
    }
    refuseV4Fields(doc, 2);
    refuseV5Fields(doc, 2);
    refuseV6Fields(doc, 2);
    refuseV7Fields(doc, 2);
    refuseV8Fields(doc, 2);
    return { ...doc, version: 3 };
  },
  // 3 → 4: version 4 added power feeds and the mounting. An older system hung on suspensions and had
  // one feed kit: it gets `mounting: 'suspended'` and the feeds a new system of its shape gets
  // (plannedFeeds: one at the chain start with the catalog's default driver, or what its load needs),
  // with ids from nextId. Anything the schema would refuse is left as it is, for the schema to name.
  3(doc, catalog) {
    const c = doc.configuration;
    if (typeof c !== 'object' || c === null || !Array.isArray((c as Record<string, unknown>).systems)) return { ...doc, version: 4 };
    refuseV4Fields(doc, 3);
    refuseV5Fields(doc, 3);
    refuseV6Fields(doc, 3);
    refuseV7Fields(doc, 3);
    refuseV8Fields(doc, 3);
    const conf = c as Record<string, unknown>;
    let nextId = typeof conf.nextId === 'number' && Number.isInteger(conf.nextId) ? conf.nextId : null;
    const systems = (conf.systems as unknown[]).map((raw) => {
      if (typeof raw !== 'object' || raw === null) return raw;
      const sys = { ...(raw as Record<string, unknown>), mounting: 'suspended' };
      if (nextId === null) return sys;
      let feeds: { at: unknown; driver: string }[];
      try {
        feeds = plannedFeeds({ ...(sys as unknown as LightSystem), feeds: [] }, catalog);
      } catch {
        // Unknown connectors or module types: a plain default feed, and validate() names the real problem.
        feeds = [{ at: 'start', driver: catalog.feed.defaultDriver }];
      }
      return { ...sys, feeds: feeds.map((f) => ({ id: `f${nextId!++}`, ...f })) };
    });
    return { ...doc, version: 4, configuration: { ...conf, systems, ...(nextId === null ? {} : { nextId }) } };
  },
  // 4 → 5: version 5 added free module positions; a version 4 module has none (its rail's
  // distribution places it), so the content reads as is.
  4(doc) {
    refuseV5Fields(doc, 4);
    refuseV6Fields(doc, 4);
    refuseV7Fields(doc, 4);
    refuseV8Fields(doc, 4);
    return { ...doc, version: 5 };
  },
  // 5 → 6: version 6 added moved fixing points and flexible connectors; a version 5 system's
  // fixing points are the derived ones and its joints turn by a fixed angle, so it reads as is.
  5(doc) {
    refuseV6Fields(doc, 5);
    refuseV7Fields(doc, 5);
    refuseV8Fields(doc, 5);
    return { ...doc, version: 6 };
  },
  // 6 → 7: version 7 added on/off, filters and aims per module and light scenes; a version 6 module
  // is on, unfiltered and points straight down, and there are no scenes, so the content reads as is.
  6(doc) {
    refuseV7Fields(doc, 6);
    refuseV8Fields(doc, 6);
    return { ...doc, version: 7 };
  },
  // 7 → 8: version 8 made a system a tree of rails; a version 7 system is a snake, which is a tree
  // whose every joint hangs on the rail before it (no `parent`) and whose feeds sit at the start,
  // the end or a connector, so the content reads as is, exactly.
  7(doc) {
    refuseV8Fields(doc, 7);
    return { ...doc, version: 8 };
  },
};

/** Branches (a joint's `parent`) and feeds at a branch end came with version 8: an older file that has them was not written by luxbox. */
function refuseV8Fields(doc: Record<string, unknown>, version: number): void {
  const c = doc.configuration;
  const list = (o: unknown, key: string): unknown[] => (typeof o === 'object' && o !== null && Array.isArray((o as Record<string, unknown>)[key]) ? ((o as Record<string, unknown>)[key] as unknown[]) : []);
  list(c, 'systems').forEach((sys, i) => {
    list(sys, 'joints').forEach((j, k) => {
      if (typeof j === 'object' && j !== null && 'parent' in j) throw needsVersion(`configuration.systems[${i}].joints[${k}].parent`, 8, version);
    });
    list(sys, 'feeds').forEach((f, k) => {
      const at = typeof f === 'object' && f !== null ? (f as Record<string, unknown>).at : undefined;
      if (typeof at === 'object' && at !== null && 'end' in at) throw needsVersion(`configuration.systems[${i}].feeds[${k}].at.end`, 8, version);
    });
  });
}

/** On/off, filters, aims and light scenes came with version 7: an older file that has them was not written by luxbox. */
function refuseV7Fields(doc: Record<string, unknown>, version: number): void {
  for (const key of ['on', 'filter', 'aim']) {
    const at = firstModuleWith(doc.configuration, key);
    if (at) throw needsVersion(`configuration.${at}`, 7, version);
  }
  const c = doc.configuration;
  if (typeof c === 'object' && c !== null && 'lightScenes' in c) throw needsVersion(`configuration.lightScenes`, 7, version);
}

/** Moved fixing points came with version 6: a file that says it is older and has them was not written by luxbox. */
function refuseV6Fields(doc: Record<string, unknown>, version: number): void {
  const c = doc.configuration;
  const systems = typeof c === 'object' && c !== null && Array.isArray((c as Record<string, unknown>).systems) ? ((c as Record<string, unknown>).systems as unknown[]) : [];
  systems.forEach((s, i) => {
    if (typeof s === 'object' && s !== null && 'fixings' in s) throw needsVersion(`configuration.systems[${i}].fixings`, 6, version);
  });
}

/** Free positions came with version 5: a file that says it is older and has one was not written by luxbox. */
function refuseV5Fields(doc: Record<string, unknown>, version: number): void {
  const at = firstModuleWith(doc.configuration, 'offset');
  if (at) throw needsVersion(`configuration.${at}`, 5, version);
}

/** Feeds and mounting came with version 4: a file that says it is older and has them was not written by luxbox. */
function refuseV4Fields(doc: Record<string, unknown>, version: number): void {
  const c = doc.configuration;
  const systems = typeof c === 'object' && c !== null && Array.isArray((c as Record<string, unknown>).systems) ? ((c as Record<string, unknown>).systems as unknown[]) : [];
  systems.forEach((s, i) => {
    for (const key of ['feeds', 'mounting']) {
      if (typeof s === 'object' && s !== null && key in s) throw needsVersion(`configuration.systems[${i}].${key}`, 4, version);
    }
  });
}

/** Path of the first module carrying `dmx` in a version 1 configuration (its shape is checked later, so every step looks before it leaps). */
function v1PatchField(configuration: unknown): string | null {
  return firstModuleWith(configuration, 'dmx');
}

/** Path of the first module carrying `key` (its shape is checked later, so every step looks before it leaps). */
function firstModuleWith(configuration: unknown, key: string): string | null {
  const list = (o: unknown, key: string): unknown[] => (typeof o === 'object' && o !== null && Array.isArray((o as Record<string, unknown>)[key]) ? ((o as Record<string, unknown>)[key] as unknown[]) : []);
  const systems = list(configuration, 'systems');
  for (let i = 0; i < systems.length; i++) {
    const rails = list(systems[i], 'rails');
    for (let k = 0; k < rails.length; k++) {
      const modules = list(rails[k], 'modules');
      for (let n = 0; n < modules.length; n++) {
        const m = modules[n];
        if (typeof m === 'object' && m !== null && key in m) return `systems[${i}].rails[${k}].modules[${n}].${key}`;
      }
    }
  }
  return null;
}

export function migrateSceneFile(doc: Record<string, unknown>, catalog: Catalog): Record<string, unknown> {
  let d = doc;
  while (typeof d.version === 'number' && d.version < SCENE_FILE_VERSION) {
    const step = migrations[d.version];
    if (!step) throw new SceneFileError(`scene file version ${d.version} is no longer supported`, { code: 'fileVersionUnsupported', params: { version: d.version } });
    d = step(d, catalog);
  }
  return d;
}

export function toSceneFile(config: Configuration, catalog: Catalog): SceneFile {
  const importedMeshes = Object.fromEntries(Object.entries(config.importedMeshes).map(([key, m]) => [key, { name: m.name, units: m.units, ...encodeMesh(m.mesh) }]));
  // Left out when empty, so a configuration without objects reads the same as it did in version 2.
  const configuration = {
    room: config.room,
    systems: config.systems,
    ...(config.objects.length > 0 ? { objects: config.objects } : {}),
    ...(Object.keys(importedMeshes).length > 0 ? { importedMeshes } : {}),
    ...(config.lightScenes && config.lightScenes.length > 0 ? { lightScenes: config.lightScenes } : {}),
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
  if (doc.version > SCENE_FILE_VERSION) throw new SceneFileError(`${source} was made by a newer luxbox (version ${doc.version}; this one reads up to ${SCENE_FILE_VERSION})`, { code: 'fileTooNew', params: { name, version: doc.version, max: SCENE_FILE_VERSION } });
  let migrated: Record<string, unknown>;
  try {
    migrated = migrateSceneFile(doc, catalog);
  } catch (e) {
    if (e instanceof SceneFileError) throw fileProblem(source, codedText(e.message, e));
    throw e;
  }
  const r = fileSchema.safeParse(migrated);
  if (!r.success) throw fileProblem(source, describeIssueCoded(r.error.issues, FIELD_NAMES));
  if (r.data.catalog !== catalog.id) {
    const theirs = excerpt(r.data.catalog).replace(/^"|"$/g, "'");
    throw new SceneFileError(`${source} was made for catalog ${theirs}, but this configurator uses '${catalog.id}'`, { code: 'fileOtherCatalog', params: { name, catalog: theirs.replace(/^'|'$/g, ''), ours: catalog.id } });
  }
  const config = normaliseRoom(r.data.configuration, source);
  const problems = validate(config, catalog, { firstOnly: true });
  if (problems.length > 0) {
    const path = `configuration.${problems[0].path}`;
    throw new SceneFileError(`${source}: ${path}: ${problems[0].message}`, { code: 'fileInvalidAt', params: { name, path }, detail: problemText(problems[0]) });
  }
  return config;
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
    if ('problem' in mesh) throw new SceneFileError(`${source}: configuration.importedMeshes.${key}.${mesh.field}: ${mesh.problem}`, { code: 'fileMeshField', params: { name: unquoted(source), path: `configuration.importedMeshes.${key}.${mesh.field}`, problem: mesh.problem } });
    importedMeshes[key] = { name: m.name, units: m.units, mesh };
  }
  const { objects, importedMeshes: _encoded, ...rest } = data;
  return { ...rest, room: { ...data.room, reflectance }, objects: (objects ?? []) as RoomObject[], importedMeshes } as Configuration;
}

/** An object a share link leaves out (imported models are not in links: they can be megabytes). */
export interface LeftOutObject {
  readonly objectId: string;
  /** The imported file's name ('kitchen.obj'). */
  readonly name: string;
}

/** A share link's text and what it could not carry, with the sentence to show the user (null when complete). */
export interface ShareLink {
  readonly text: string;
  readonly leftOut: readonly LeftOutObject[];
  readonly notice: string | null;
}

/**
 * The share string of a configuration: library objects travel in it, imported ones (and their
 * meshes) are left out and listed, so the UI can tell the user — never silently dropped.
 */
export function encodeShareLink(config: Configuration, catalog: Catalog): ShareLink {
  const leftOut: LeftOutObject[] = config.objects.filter((o) => o.source.kind === 'imported').map((o) => ({ objectId: o.id, name: sourceName(config, o.source) }));
  const shared: Configuration = leftOut.length === 0 ? config : { ...config, objects: config.objects.filter((o) => o.source.kind !== 'imported'), importedMeshes: {} };
  const names = [...new Set(leftOut.map((o) => `'${o.name}'`))];
  const notice = names.length === 0 ? null : `the imported model${names.length > 1 ? 's' : ''} ${names.join(', ')} ${names.length > 1 ? 'are' : 'is'} not in the link; save the file to keep ${names.length > 1 ? 'them' : 'it'}`;
  return { text: encodeShareBytes(serializeConfiguration(shared, catalog, 0)), leftOut, notice };
}

/**
 * base64url (RFC 4648 §5, no padding) of the compact scene-file JSON (no indentation), for
 * share links. Links written with indented JSON (before issue 18) decode all the same.
 */
export function encodeShareString(config: Configuration, catalog: Catalog): string {
  const link = encodeShareLink(config, catalog);
  // Never silently incomplete: callers that can tell the user use encodeShareLink.
  if (link.notice) throw new SceneFileError(link.notice);
  return link.text;
}

function encodeShareBytes(json: string): string {
  const bytes = new TextEncoder().encode(json);
  let bin = '';
  for (const b of bytes) bin += String.fromCharCode(b);
  return btoa(bin).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

export function decodeShareString(s: string, catalog: Catalog): Configuration {
  if (s.length === 0) throw new SceneFileError('share link is empty', { code: 'shareLinkEmpty' });
  if (s.length > MAX_SHARE_STRING) throw new SceneFileError(`share link is too long (${s.length} characters, at most ${MAX_SHARE_STRING})`, { code: 'shareLinkTooLong', params: { length: s.length, max: MAX_SHARE_STRING } });
  if (!/^[A-Za-z0-9_-]+$/.test(s)) throw new SceneFileError('share link is damaged (characters outside base64url)', { code: 'shareLinkCharacters' });
  if (s.length % 4 === 1) throw new SceneFileError('share link is damaged (truncated)', { code: 'shareLinkTruncated' });
  const bin = atob(s.replace(/-/g, '+').replace(/_/g, '/') + '='.repeat((4 - (s.length % 4)) % 4));
  let text: string;
  try {
    text = new TextDecoder('utf-8', { fatal: true }).decode(Uint8Array.from(bin, (c) => c.charCodeAt(0)));
  } catch {
    throw new SceneFileError('share link is damaged (not UTF-8 text)', { code: 'shareLinkNotUtf8' });
  }
  return deserializeConfiguration(text, catalog, 'share link');
}
