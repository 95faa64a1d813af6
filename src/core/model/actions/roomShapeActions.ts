/**
 * Editing the room's shape (issue 29, docs/model.md "Editing the room's shape"): presets,
 * corners, walls, slopes, openings and per-wall finishes. Every action builds the new shape with
 * roomShapeGeometry, refuses with the room rule's own code when roomProblems finds one
 * (src/core/room/roomProblems.ts: 'room-wall-short', 'room-self-intersection', …), and keeps the
 * room's invariant with settleShape (outline at the origin, everything placed moved along, width
 * and depth the extents). What the shape does to rails, modules and objects (outside the room,
 * under a slope) is validate()'s, checked on the result where the action is bound.
 */
import { z } from 'zod/mini';
import { InputError } from '../../inputError';
import type { ActionDefinition } from './action';
import { ROOM_SHAPE_ACTION_LABELS } from './roomShapeActionNames';
import type { Configuration, RoomShape, ShapeOpening } from '../configuration/configuration';
import type { Reflectance } from '../lightingScene/lightingScene';
import { roomProblems } from '../../room/roomProblems';
import { OPENING_KINDS, type OpeningKind, type RoomOpening } from '../../room/roomInput';
import { currentShape, moveCorner, presetOutline, removeCorner, settleShape, setCornerAngle, setWallLength, SHAPE_PRESETS, shapeRoomInput, splitWall, wallFinishes, wallLength } from './roomShapeGeometry';

/** The shape put in the room, or an InputError carrying the first room rule it breaks. */
function withShape(state: Configuration, shape: RoomShape): Configuration {
  const next = settleShape(state, shape);
  const problems = roomProblems(shapeRoomInput(next.room));
  if (problems.length > 0) throw new InputError(problems[0].message, { code: problems[0].code, params: problems[0].params });
  return next;
}

function checkWall(shape: RoomShape, wall: number): void {
  if (wall >= shape.outline.length) throw new InputError(`the room has no wall ${wall} (walls 0 to ${shape.outline.length - 1})`, { code: 'roomNoWall', params: { wall, last: shape.outline.length - 1 } });
}
function checkCorner(shape: RoomShape, corner: number): void {
  if (corner >= shape.outline.length) throw new InputError(`the room has no corner ${corner} (corners 0 to ${shape.outline.length - 1})`, { code: 'roomNoCorner', params: { corner, last: shape.outline.length - 1 } });
}
function checkOpening(shape: RoomShape, opening: number): RoomOpening {
  const o = shape.openings[opening];
  if (!o) throw new InputError(`the room has no opening ${opening}`, { code: 'roomNoOpening', params: { opening } });
  return o;
}

const index = z.number().check(z.int(), z.gte(0));
const metres = z.number();

const presetParams = z.object({ preset: z.enum(SHAPE_PRESETS) });
export const setRoomShapePreset: ActionDefinition<z.infer<typeof presetParams>> = {
  name: 'setRoomShapePreset',
  label: ROOM_SHAPE_ACTION_LABELS.setRoomShapePreset,
  params: presetParams,
  perform(state, p) {
    // A new outline: slopes, openings and per-wall finishes named walls that are gone.
    return withShape(state, { outline: presetOutline(p.preset, state.room.width, state.room.depth), slopes: [], openings: [] });
  },
};

const cornerParams = z.object({ corner: index, x: metres, z: metres });
export const moveRoomCorner: ActionDefinition<z.infer<typeof cornerParams>> = {
  name: 'moveRoomCorner',
  label: ROOM_SHAPE_ACTION_LABELS.moveRoomCorner,
  params: cornerParams,
  perform(state, p) {
    const shape = currentShape(state.room);
    checkCorner(shape, p.corner);
    return withShape(state, moveCorner(shape, p.corner, [p.x, p.z]));
  },
};

const splitParams = z.object({ wall: index, at: metres });
export const splitRoomWall: ActionDefinition<z.infer<typeof splitParams>> = {
  name: 'splitRoomWall',
  label: ROOM_SHAPE_ACTION_LABELS.splitRoomWall,
  params: splitParams,
  perform(state, p) {
    const shape = currentShape(state.room);
    checkWall(shape, p.wall);
    const split = splitWall(shape, p.wall, p.at);
    if ('straddles' in split) throw new InputError(`opening ${split.straddles} is in the way: a wall cannot be split inside an opening`, { code: 'roomSplitInOpening', params: { opening: split.straddles } });
    return withShape(state, split);
  },
};

const lengthParams = z.object({ wall: index, length: metres });
export const setRoomWallLength: ActionDefinition<z.infer<typeof lengthParams>> = {
  name: 'setRoomWallLength',
  label: ROOM_SHAPE_ACTION_LABELS.setRoomWallLength,
  params: lengthParams,
  perform(state, p) {
    const shape = currentShape(state.room);
    checkWall(shape, p.wall);
    return withShape(state, setWallLength(shape, p.wall, p.length));
  },
};

const angleParams = z.object({ corner: index, degrees: z.number().check(z.gt(0), z.lt(360)) });
export const setRoomCornerAngle: ActionDefinition<z.infer<typeof angleParams>> = {
  name: 'setRoomCornerAngle',
  label: ROOM_SHAPE_ACTION_LABELS.setRoomCornerAngle,
  params: angleParams,
  perform(state, p) {
    const shape = currentShape(state.room);
    checkCorner(shape, p.corner);
    return withShape(state, setCornerAngle(shape, p.corner, p.degrees));
  },
};

const removeCornerParams = z.object({ corner: index });
export const removeRoomCorner: ActionDefinition<z.infer<typeof removeCornerParams>> = {
  name: 'removeRoomCorner',
  label: ROOM_SHAPE_ACTION_LABELS.removeRoomCorner,
  params: removeCornerParams,
  perform(state, p) {
    const shape = currentShape(state.room);
    checkCorner(shape, p.corner);
    return withShape(state, removeCorner(shape, p.corner));
  },
};

const slopeParams = z.object({ wall: index, kneeHeight: metres, pitch: z.number() });
export const setRoomSlope: ActionDefinition<z.infer<typeof slopeParams>> = {
  name: 'setRoomSlope',
  label: ROOM_SHAPE_ACTION_LABELS.setRoomSlope,
  params: slopeParams,
  perform(state, p) {
    const shape = currentShape(state.room);
    checkWall(shape, p.wall);
    const slope = { wall: p.wall, kneeHeight: p.kneeHeight, pitch: p.pitch };
    const had = shape.slopes.some((s) => s.wall === p.wall);
    const slopes = had ? shape.slopes.map((s) => (s.wall === p.wall ? { ...s, ...slope } : s)) : [...shape.slopes, slope];
    return withShape(state, { ...shape, slopes });
  },
};

const wallParams = z.object({ wall: index });
export const removeRoomSlope: ActionDefinition<z.infer<typeof wallParams>> = {
  name: 'removeRoomSlope',
  label: ROOM_SHAPE_ACTION_LABELS.removeRoomSlope,
  params: wallParams,
  perform(state, p) {
    const shape = currentShape(state.room);
    if (!shape.slopes.some((s) => s.wall === p.wall)) throw new InputError(`wall ${p.wall} carries no slope`, { code: 'roomNoSlope', params: { wall: p.wall } });
    return withShape(state, { ...shape, slopes: shape.slopes.filter((s) => s.wall !== p.wall) });
  },
};

/** A new opening's size when none is given: a common interior door, a window at sill height, a passage. */
export const OPENING_DEFAULTS: Record<OpeningKind, { width: number; height: number; sill: number }> = {
  door: { width: 0.9, height: 2, sill: 0 },
  window: { width: 1.2, height: 1.2, sill: 0.9 },
  opening: { width: 1, height: 2, sill: 0 },
};

const kind = z.enum(OPENING_KINDS);
const addOpeningParams = z.object({ wall: index, kind, offset: z.optional(metres), width: z.optional(metres), sill: z.optional(metres), height: z.optional(metres) });
export const addRoomOpening: ActionDefinition<z.infer<typeof addOpeningParams>> = {
  name: 'addRoomOpening',
  label: ROOM_SHAPE_ACTION_LABELS.addRoomOpening,
  params: addOpeningParams,
  perform(state, p) {
    const shape = currentShape(state.room);
    checkWall(shape, p.wall);
    const d = OPENING_DEFAULTS[p.kind];
    const length = wallLength(shape.outline, p.wall);
    // Without a width, the default narrowed to leave a wall's end on each side on a short wall.
    const width = p.width ?? Math.min(d.width, Math.round(0.8 * length * 100) / 100);
    const opening: RoomOpening = { wall: p.wall, kind: p.kind, offset: p.offset ?? Math.round(((length - width) / 2) * 1000) / 1000, width, sill: p.sill ?? d.sill, height: p.height ?? d.height };
    return withShape(state, { ...shape, openings: [...shape.openings, opening] });
  },
};

const setOpeningParams = z.object({ opening: index, offset: z.optional(metres), width: z.optional(metres), sill: z.optional(metres), height: z.optional(metres), kind: z.optional(kind) });
/** Moves an opening along its wall (offset) or resizes it (width, sill, height) or changes its kind; unspecified fields stay. */
export const setRoomOpening: ActionDefinition<z.infer<typeof setOpeningParams>> = {
  name: 'setRoomOpening',
  label: ROOM_SHAPE_ACTION_LABELS.setRoomOpening,
  params: setOpeningParams,
  perform(state, p) {
    const shape = currentShape(state.room);
    const o = checkOpening(shape, p.opening);
    const moved: ShapeOpening = { ...o, offset: p.offset ?? o.offset, width: p.width ?? o.width, sill: p.sill ?? o.sill, height: p.height ?? o.height, kind: p.kind ?? o.kind };
    // Only a window has glazing: a window made a door or an opening leaves its glazing behind.
    const { transmittance, ...unglazed } = moved;
    const changed: ShapeOpening = moved.kind === 'window' || transmittance === undefined ? moved : unglazed;
    return withShape(state, { ...shape, openings: shape.openings.map((x, i) => (i === p.opening ? changed : x)) });
  },
};

const openingParams = z.object({ opening: index });
export const removeRoomOpening: ActionDefinition<z.infer<typeof openingParams>> = {
  name: 'removeRoomOpening',
  label: ROOM_SHAPE_ACTION_LABELS.removeRoomOpening,
  params: openingParams,
  perform(state, p) {
    const shape = currentShape(state.room);
    checkOpening(shape, p.opening);
    return withShape(state, { ...shape, openings: shape.openings.filter((_, i) => i !== p.opening) });
  },
};

const finishParams = z.object({ wall: index, value: z.union([z.number(), z.tuple([z.number(), z.number(), z.number()])]) });
/** One wall's own finish; the other walls keep theirs (their own, or the nearest box wall's written out). */
export const setWallFinish: ActionDefinition<z.infer<typeof finishParams>> = {
  name: 'setWallFinish',
  label: ROOM_SHAPE_ACTION_LABELS.setWallFinish,
  params: finishParams,
  perform(state, p) {
    const shape = currentShape(state.room);
    checkWall(shape, p.wall);
    const value: Reflectance = typeof p.value === 'number' ? p.value : [p.value[0], p.value[1], p.value[2]];
    const wallReflectance = wallFinishes(state.room, shape).map((r, i) => (i === p.wall ? value : r));
    return withShape(state, { ...shape, wallReflectance });
  },
};
