/**
 * The version-3 `room` object of a lighting scene (issue 29; docs/scene-format.md, "Version 3
 * room (draft)") as a zod schema: the structure and types first (strict: an unknown field is
 * refused), then the room's own rules (roomProblems) as issues at their paths. Not yet wired into
 * the lighting-scene parser.
 */
import { z } from 'zod/mini';
import { OPENING_KINDS, ROOM_SHAPE_LIMITS } from './roomInput';
import { roomProblems } from './roomProblems';
import type { RoomInput } from './roomInput';

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

const slope = z.strictObject(
  {
    wall: index,
    kneeHeight: finite.check(z.refine((v) => v >= 0, { error: (i) => `${show(i.input)} m is below the floor` })),
    pitch: finite.check(z.refine((v) => v > 0 && v < 90, { error: (i) => `${show(i.input)}° is not between 0° and 90°` })),
    reflectance: z.optional(reflectance),
  },
  { error: 'must be an object' },
);

const opening = z.strictObject(
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

const roomShape = z.strictObject(
  {
    outline: z
      .array(z.tuple([coordinate, coordinate], { error: (i) => `must be [x, z] in metres, got ${show(i.input)}` }), { error: (i) => (i.input === undefined ? 'is missing' : 'must be a list of corners [x, z]') })
      .check(z.minLength(ROOM_SHAPE_LIMITS.minCorners, `needs at least ${ROOM_SHAPE_LIMITS.minCorners} corners`), z.maxLength(ROOM_SHAPE_LIMITS.maxCorners, `has more than ${ROOM_SHAPE_LIMITS.maxCorners} corners`)),
    height: finite.check(
      z.refine((v) => v >= ROOM_SHAPE_LIMITS.minHeight && v <= ROOM_SHAPE_LIMITS.maxHeight, {
        error: (i) => `${show(i.input)} m is outside ${ROOM_SHAPE_LIMITS.minHeight}..${ROOM_SHAPE_LIMITS.maxHeight} m`,
      }),
    ),
    slopes: z.optional(z.array(slope, { error: 'must be a list of slopes' }).check(z.maxLength(ROOM_SHAPE_LIMITS.maxCorners, `has more than ${ROOM_SHAPE_LIMITS.maxCorners} slopes`))),
    openings: z.optional(z.array(opening, { error: 'must be a list of openings' }).check(z.maxLength(4 * ROOM_SHAPE_LIMITS.maxCorners, `has more than ${4 * ROOM_SHAPE_LIMITS.maxCorners} openings`))),
    reflectance: z.strictObject(
      {
        floor: reflectance,
        ceiling: reflectance,
        walls: z.union([reflectance, z.array(reflectance).check(z.maxLength(ROOM_SHAPE_LIMITS.maxCorners))], {
          error: (i) => (i.input === undefined ? 'is missing' : `must be a reflectance, [r, g, b], or one per wall, got ${show(i.input)}`),
        }),
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
