/**
 * A configuration file's `room.shape` (version 9, docs/model.md "Room shape"): the outline,
 * slopes and openings with the lighting scene's limits (src/core/room/roomSchema.ts) and the
 * walls' own finishes. Part of the room-shape chunk (actions/roomShapeChunk.ts): the file
 * schema takes the shape as it comes (sceneFileSchema.ts) and the reader asks readRoomShape.
 */
import { z } from 'zod/mini';
import type { CodedText } from '../../inputError';
import { ROOM_SHAPE_LIMITS } from '../../room/roomInput';
import { roomOpeningSchema, roomOutlineSchema, roomSlopeSchema } from '../../room/roomSchema';
import { safeParseInEnglish } from '../../zodEnglish';
import { describeIssueCoded, schemaFieldNames } from '../../zodIssues';
import type { RoomShape } from '../configuration/configuration';
import { fileReflectanceSchema } from './sceneFileSchema';
import { transmittanceFileSchema } from './daylightFileSchema';

/** An opening as the room model has it, and a window's glazing (version 10; validate() refuses it on a door or opening). */
const shapeOpeningSchema = z.extend(roomOpeningSchema, { transmittance: z.optional(transmittanceFileSchema) });

// Strict: an unknown (misspelt, or newer) field is refused, never dropped.
export const roomShapeFileSchema = z.strictObject({
  outline: roomOutlineSchema,
  slopes: z.array(roomSlopeSchema).check(z.maxLength(ROOM_SHAPE_LIMITS.maxCorners)),
  openings: z.array(shapeOpeningSchema).check(z.maxLength(4 * ROOM_SHAPE_LIMITS.maxCorners)),
  wallReflectance: z.optional(z.array(fileReflectanceSchema).check(z.maxLength(ROOM_SHAPE_LIMITS.maxCorners))),
});

const FIELD_NAMES = schemaFieldNames(roomShapeFileSchema);

/** The shape as read, or its first problem as a coded sentence at its path under `prefix` (configuration.room.shape). */
export function readRoomShape(value: unknown, prefix: readonly PropertyKey[]): { shape: RoomShape } | { problem: CodedText } {
  const r = safeParseInEnglish(roomShapeFileSchema, value);
  if (!r.success) return { problem: describeIssueCoded(r.error.issues, FIELD_NAMES, prefix) };
  return { shape: r.data as RoomShape };
}
