/**
 * setRoom on a drawn room (issue 29, docs/model.md "Editing the room's shape"): the outline scaled
 * to the new width and depth; openings keep their size and their centre's place along their wall
 * in proportion. Part of the room-shape chunk (actions/roomShapeChunk.ts).
 */
import { InputError } from '../../inputError';
import type { PlanPoint } from '../../room/planPolygon';
import { roomProblems } from '../../room/roomProblems';
import type { Configuration, RoomShape } from '../configuration/configuration';
import { settleShape, shapeRoomInput, wallLength } from './roomShapeGeometry';

/** The room's new size, as setRoom takes it. */
export interface RoomSize {
  width: number;
  depth: number;
  height: number;
}

/** The state with its drawn room scaled to `p`, or an InputError carrying the first room rule the result breaks. */
export function scaleRoomShape(state: Configuration, p: RoomSize): Configuration {
  const shape: RoomShape = state.room.shape!;
  // A drawn room is scaled to the new width and depth (docs/model.md, "Editing the room's shape"):
  // openings keep their size and their place along their wall in proportion.
  const sx = p.width / state.room.width;
  const sz = p.depth / state.room.depth;
  const outline = shape.outline.map((c): PlanPoint => [c[0] * sx, c[1] * sz]);
  const openings = shape.openings.map((o) => {
    const centre = (o.offset + o.width / 2) * (wallLength(outline, o.wall) / wallLength(shape.outline, o.wall));
    return { ...o, offset: Math.round((centre - o.width / 2) * 1000) / 1000 };
  });
  const next = settleShape({ ...state, room: { ...state.room, height: p.height } }, { ...shape, outline, openings });
  const problems = roomProblems(shapeRoomInput(next.room));
  if (problems.length > 0) throw new InputError(problems[0].message, { code: problems[0].code, params: problems[0].params });
  return next;
}
