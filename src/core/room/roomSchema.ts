/**
 * The version-3 `room` object of a lighting scene (issue 29; docs/scene-format.md, "Version 3
 * room") as a zod schema: the structure and types first (strict: an unknown field is
 * refused), then the room's own rules (roomProblems) as issues at their paths. parseLightingScene
 * reads version 3 with it; the configuration file's room shape reuses its outline, slope and
 * opening schemas (sceneFileSchema.ts).
 */
import { z } from 'zod/mini';
import { safeParseInEnglish } from '../zodEnglish';
import { OPENING_KINDS, ROOM_SHAPE_LIMITS } from './roomInput';
import { roomProblems } from './roomProblems';
import type { RoomInput, RoomReflectance } from './roomInput';

const show = (v: unknown): string => {
  const text = typeof v === 'number' && !Number.isFinite(v) ? String(v) : (JSON.stringify(v) ?? String(v));
  return text.length > 40 ? `${text.slice(0, 37)}...` : text;
};

const finite = z.number({ error: (i) => (i.input === undefined ? 'is missing' : `must be a number, got ${show(i.input)}`) }).check(z.refine(Number.isFinite, 'must be a finite number'));
const coordinate = finite.check(z.refine((v) => Math.abs(v) <= ROOM_SHAPE_LIMITS.maxCoordinate, { error: (i) => `${show(i.input)} m is beyond ±${ROOM_SHAPE_LIMITS.maxCoordinate} m` }));
const reflectanceValue = finite.check(
  z.refine((v) => v >= 0 && v < 1, {
    error: (i) => `reflectance ${show(i.input)} is outside [0, 1) (at 1 a closed room would never lose light)`,
  }),
);
const reflectance = z.union([reflectanceValue, z.tuple([reflectanceValue, reflectanceValue, reflectanceValue])], {
  error: (i) => (i.input === undefined ? 'is missing' : `must be a number in [0, 1) or [r, g, b], got ${show(i.input)}`),
});
const index = z.number({ error: (i) => (i.input === undefined ? 'is missing' : `must be a wall index, got ${show(i.input)}`) }).check(z.int('must be a whole number'), z.gte(0, 'must be 0 or more'));

/** One roof slope (exported for the configuration file's room shape, sceneFileSchema.ts). */
export const roomSlopeSchema = z.strictObject(
  {
    wall: index,
    kneeHeight: finite.check(z.refine((v) => v >= 0, { error: (i) => `${show(i.input)} m is below the floor` })),
    pitch: finite.check(z.refine((v) => v > 0 && v < 90, { error: (i) => `${show(i.input)}° is not between 0° and 90°` })),
    reflectance: z.optional(reflectance),
  },
  { error: 'must be an object' },
);

/** One opening. */
export const roomOpeningSchema = z.strictObject(
  {
    wall: index,
    offset: finite,
    width: finite.check(z.refine((v) => v > 0, { error: (i) => `${show(i.input)} m is not above 0 m` })),
    sill: finite.check(z.refine((v) => v >= 0, { error: (i) => `${show(i.input)} m is below the floor` })),
    height: finite.check(z.refine((v) => v > 0, { error: (i) => `${show(i.input)} m is not above 0 m` })),
    kind: z.enum(OPENING_KINDS, { error: (i) => `must be "door", "window" or "opening", got ${show(i.input)}` }),
  },
  { error: 'must be an object' },
);

/**
 * `walls`: one reflectance, or a list with one per wall. Told apart by the rule the room model
 * reads them by (wallReflectances: three bare numbers are [r, g, b]) rather than by a zod union, so
 * a bad entry of a per-wall list is reported at its own path (`walls[2][0]`), not as the whole list.
 */
const wallReflectances = z.custom<unknown>().check(
  z.superRefine((value, ctx) => {
    const perWall = Array.isArray(value) && !(value.length === 3 && value.every((v) => typeof v === 'number'));
    const check = (v: unknown, at: number[]) => {
      const r = safeParseInEnglish(reflectance, v);
      if (!r.success) for (const issue of r.error.issues) ctx.addIssue({ code: 'custom', message: issue.message, path: [...at, ...issue.path] as (string | number)[], input: v });
    };
    if (!perWall) return check(value, []);
    const list = value as unknown[];
    if (list.length > ROOM_SHAPE_LIMITS.maxCorners) ctx.addIssue({ code: 'custom', message: `has more than ${ROOM_SHAPE_LIMITS.maxCorners} entries`, input: value });
    else list.forEach((v, k) => check(v, [k]));
  }),
) as unknown as z.ZodMiniType<RoomReflectance | RoomReflectance[]>;

/** The floor outline: 3 to 64 corners [x, z] within ±500 m. */
export const roomOutlineSchema = z
  .array(z.tuple([coordinate, coordinate], { error: (i) => `must be [x, z] in metres, got ${show(i.input)}` }), { error: (i) => (i.input === undefined ? 'is missing' : 'must be a list of corners [x, z]') })
  .check(z.minLength(ROOM_SHAPE_LIMITS.minCorners, `needs at least ${ROOM_SHAPE_LIMITS.minCorners} corners`), z.maxLength(ROOM_SHAPE_LIMITS.maxCorners, `has more than ${ROOM_SHAPE_LIMITS.maxCorners} corners`));

const roomShape = z.strictObject(
  {
    outline: roomOutlineSchema,
    height: finite.check(
      z.refine((v) => v >= ROOM_SHAPE_LIMITS.minHeight && v <= ROOM_SHAPE_LIMITS.maxHeight, {
        error: (i) => `${show(i.input)} m is outside ${ROOM_SHAPE_LIMITS.minHeight}..${ROOM_SHAPE_LIMITS.maxHeight} m`,
      }),
    ),
    slopes: z.optional(z.array(roomSlopeSchema, { error: 'must be a list of slopes' }).check(z.maxLength(ROOM_SHAPE_LIMITS.maxCorners, `has more than ${ROOM_SHAPE_LIMITS.maxCorners} slopes`))),
    openings: z.optional(z.array(roomOpeningSchema, { error: 'must be a list of openings' }).check(z.maxLength(4 * ROOM_SHAPE_LIMITS.maxCorners, `has more than ${4 * ROOM_SHAPE_LIMITS.maxCorners} openings`))),
    reflectance: z.strictObject(
      {
        floor: reflectance,
        ceiling: reflectance,
        walls: wallReflectances,
      },
      { error: (i) => (i.input === undefined ? 'is missing' : 'must be an object with floor, ceiling and walls') },
    ),
  },
  { error: (i) => (i.input === undefined ? 'is missing' : 'must be an object') },
);

/**
 * The version-3 room: its shape by zod, then the geometric rules (walls ≥ 0.1 m, no
 * self-intersection, slopes, openings inside their walls and apart, one reflectance per wall)
 * as issues at the path roomProblems names, relative to the room object (so `outline[3]`, not
 * `room.outline[3]`). The issue's `params.code` carries the problem's code for a UI.
 */
export const roomSchema = roomShape.check(
  z.superRefine((room, ctx) => {
    for (const p of roomProblems(room as RoomInput)) {
      const path = p.path
        .replace(/^room\.?/, '')
        .split(/[.[\]]/)
        .filter((s) => s !== '')
        .map((s) => (/^\d+$/.test(s) ? Number(s) : s));
      ctx.addIssue({ code: 'custom', message: p.message, path, params: { code: p.code, ...p.params } });
    }
  }),
);
