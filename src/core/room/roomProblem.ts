/** What every room rule shares: the problem's shape and the float tolerances (issue 29). */
import type { MessageParams } from '../inputError';
import type { PlanPoint } from './planPolygon';

export interface RoomProblem {
  /** Stable machine-readable code, e.g. 'room-wall-short'. */
  readonly code: string;
  /** One English sentence naming the problem and where. */
  readonly message: string;
  readonly params: MessageParams;
  /** Where in the room object, e.g. 'room.openings[1].offset'. */
  readonly path: string;
}

/** Float noise allowed in the geometric comparisons (a nanometre). */
export const EPS = 1e-9;

/** Lengths in messages, to the millimetre. */
export const round = (v: number): number => Math.round(v * 1000) / 1000;
export const isFiniteNumber = (v: unknown): v is number => typeof v === 'number' && Number.isFinite(v);

export function problem(code: string, path: string, message: string, params: MessageParams): RoomProblem {
  return { code, path, message, params };
}

export function reflectanceOk(r: unknown): boolean {
  const ok = (v: unknown) => isFiniteNumber(v) && v >= 0 && v < 1;
  return ok(r) || (Array.isArray(r) && r.length === 3 && r.every(ok));
}

/** A sound outline as the later rules read it: its corners, wall count, orientation and ceiling height. */
export interface RoomFrame {
  corners: readonly PlanPoint[];
  n: number;
  orientation: 1 | -1;
  H: number;
}

export const wallOk = (frame: RoomFrame, w: unknown): w is number => Number.isInteger(w) && (w as number) >= 0 && (w as number) < frame.n;

export function wallLength({ corners, n }: RoomFrame, w: number): number {
  return Math.hypot(corners[(w + 1) % n][0] - corners[w][0], corners[(w + 1) % n][1] - corners[w][1]);
}
