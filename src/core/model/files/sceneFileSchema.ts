/** The scene file's structure, as strict zod (unknown fields refused, naming the field), and its version history. */
import { z } from 'zod/mini';
import { DISTRIBUTIONS } from '../catalogSchema/railSystemSchema';
import { MESH_UNITS, MOUNTINGS, WALL_NAMES } from '../configuration/configuration';
import { SURFACE_NAMES } from '../lightingScene/lightingScene';

export const SCENE_FILE_FORMAT = 'luxbox-configuration';
/**
 * 10: daylight (`daylight`: on, place, date, time, sky, ground reflectance) and a window's glazing
 *    (`transmittance` on a window of `room.shape.openings`), docs/daylight.md "The shopper's daylight".
 * 9: the room may have a shape (`room.shape`: outline, slopes, openings, per-wall finishes),
 *    docs/model.md "Room shape"; a room without one is the box it always was.
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
export const SCENE_FILE_VERSION = 10;
/**
 * Read side of a reflectance: [0, 1) as version 1 files have always allowed. Channels above
 * MAX_REFLECTANCE (0.95, src/core/model/lightingScene/reflectance.ts) in files written before that cap are lowered
 * to it on load (normaliseRoom), so old files keep loading; new files never hold them.
 */
export const fileReflectanceSchema = z.union([z.number().check(z.gte(0), z.lt(1)), z.tuple([z.number().check(z.gte(0), z.lt(1)), z.number().check(z.gte(0), z.lt(1)), z.number().check(z.gte(0), z.lt(1))])]);
const id = z.string().check(z.regex(/^[A-Za-z0-9_-]{1,64}$/, 'must be 1-64 letters, digits, _ or -'));
/** A catalog reference (module type, beam, connector, preset id); validate() checks it exists. */
const ref = z.string().check(z.maxLength(200));

// Strict objects: an unknown (misspelt, or newer) field is refused, never dropped.
const configurationSchema = z.strictObject({
  room: z.strictObject({
    width: z.number(),
    depth: z.number(),
    height: z.number(),
    // Optional per surface and as a whole: a hand-written file may leave out the finishes, which then default.
    reflectance: z.optional(z.strictObject(Object.fromEntries(SURFACE_NAMES.map((s) => [s, z.optional(fileReflectanceSchema)])) as Record<(typeof SURFACE_NAMES)[number], z.ZodMiniOptional<typeof fileReflectanceSchema>>)),
    // Version 9: the room's shape. Its schema is in the room-shape chunk (roomShapeFileSchema.ts), which the
    // reader asks once this structure has passed (sceneFile.ts); its rules and its fit to width and depth are validate()'s.
    shape: z.optional(z.custom<unknown>()),
  }),
  systems: z.array(
    z.strictObject({
      id,
      presetId: z.optional(ref),
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
              dmx: z.optional(z.strictObject({ universe: z.number(), address: z.number(), resolution: z.union([z.literal(8), z.literal(16)]), cct: z.boolean() })),
              // Version 5: a free position (start, metres from the rail start); its rules are validate()'s (module-past-end, module-overlap).
              offset: z.optional(z.number()),
              // Version 7: on/off, colour filter and aim; their rules are validate()'s.
              on: z.optional(z.boolean()),
              filter: z.optional(ref),
              aim: z.optional(z.strictObject({ rotation: z.number(), tilt: z.number() })),
            }),
          ),
        }),
      ),
      // Version 8: `parent`, the rail whose end the joint's connector sits on; tree rules are validate()'s (joint-parent, node-*).
      joints: z.array(z.strictObject({ connector: ref, turn: z.number(), parent: z.optional(z.number()) })),
      // Version 4 (`{ end: i }` version 8). Positions, drivers and loads are validate()'s rules (feed-position, unknown-driver, feed-overload).
      feeds: z.array(z.strictObject({ id, at: z.union([z.literal('start'), z.literal('end'), z.strictObject({ joint: z.number() }), z.strictObject({ end: z.number() })]), driver: ref })),
      mounting: z.enum(MOUNTINGS),
      // Version 6: moved fixing points (chain coordinates); their rules are validate()'s (fixing-*).
      fixings: z.optional(z.array(z.number())),
    }),
  ),
  // Version 3; optional so a hand-written file may leave them out (empty).
  objects: z.optional(
    z.array(
      z.strictObject({
        id,
        source: z.discriminatedUnion('kind', [z.strictObject({ kind: z.literal('library'), item: ref }), z.strictObject({ kind: z.literal('imported'), mesh: id })]),
        placement: z.discriminatedUnion('on', [z.strictObject({ on: z.literal('floor'), x: z.number(), z: z.number() }), z.strictObject({ on: z.literal('wall'), wall: z.enum(WALL_NAMES), u: z.number(), y: z.number() })]),
        yaw: z.number(),
        scale: z.number(),
        // Material names and finish ids are checked against the mesh and the finish list by validate().
        finishes: z.record(z.string().check(z.maxLength(200)), z.union([ref, z.tuple([z.number(), z.number(), z.number()])])),
      }),
    ),
  ),
  importedMeshes: z.optional(
    z.record(
      id,
      z.strictObject({
        name: z.string().check(z.maxLength(200)),
        units: z.enum(MESH_UNITS),
        // base64 of the little-endian typed arrays (meshCodec.ts).
        positions: z.string(),
        indices: z.string(),
        materialOfTriangle: z.string(),
        materials: z.array(z.strictObject({ name: z.string().check(z.maxLength(200)), reflectance: z.tuple([z.number().check(z.gte(0), z.lt(1)), z.number().check(z.gte(0), z.lt(1)), z.number().check(z.gte(0), z.lt(1))]) })),
      }),
    ),
  ),
  // Version 7: light scenes (cues); names, fades, module ids and looks are validate()'s rules.
  lightScenes: z.optional(
    z.array(
      z.strictObject({
        id,
        name: z.string().check(z.maxLength(200)),
        fade: z.number(),
        looks: z.record(id, z.strictObject({ on: z.boolean(), level: z.number(), cct: z.number(), filter: z.optional(ref) })),
      }),
    ),
  ),
  // Version 10: daylight. Its schema is in the room-shape chunk (daylightFileSchema.ts), read as the room's shape is (sceneFile.ts); its rules are validate()'s.
  daylight: z.optional(z.custom<unknown>()),
  nextId: z.number().check(z.int(), z.positive()),
});

/** The typed structure the reader parses with (sceneFileSchema is the same, for walking). */
export const fileSchema = z.strictObject({
  format: z.literal(SCENE_FILE_FORMAT),
  version: z.literal(SCENE_FILE_VERSION),
  catalog: z.string(),
  configuration: configurationSchema,
});

/** The structure zod checks (tests walk it to reach every numeric field). */
export const sceneFileSchema: z.ZodMiniType = fileSchema;

export type SceneFile = z.infer<typeof fileSchema>;
