/**
 * Aiming adjustable modules (docs/aiming.md): the catalog's limits, the one clamp-and-snap rule
 * that keeps an aim valid, the orientation an aim gives the luminaire, and the aim that points a
 * module's axis at a world point.
 *
 * Frames (docs/scene-format.md "Units and frames"): y up, a plan heading h points along
 * (cos h, 0, −sin h) (counterclockwise seen from above), a luminaire's optical axis is its local
 * −y, and world = Ry(yaw)·Rx(pitch)·Ry(roll)·local.
 */
import type { ModuleTypeSpec } from '../catalogSchema/moduleTypeSchema';
import { keyed } from '../configuration/coding';
import type { ModuleAim } from '../configuration/configuration';
import type { Vec3 } from '../lightingScene/lightingScene';

/** A type's `adjustable` limits (catalog-format.md). */
export type AimLimits = NonNullable<ModuleTypeSpec['adjustable']>;
export interface AimRange {
  readonly min: number;
  readonly max: number;
  /** Detent spacing, degrees; absent: continuous. */
  readonly stops?: number;
}

const DEG = Math.PI / 180;
/** Float noise allowed on limits and stops (a microdegree). */
const EPS = 1e-6;

/** Degrees into [0, 360). */
function wrap360(deg: number): number {
  const r = deg % 360;
  const w = r < 0 ? r + 360 : r;
  // + 0 turns −0 (atan2 of −0) into 0.
  return w >= 360 ? 0 : w + 0;
}

/** Rounds to the nearest stop (stops are multiples of `stops` from 0: the schema puts min and max on that grid). */
function snap(value: number, stops: number | undefined): number {
  if (!stops) return value;
  const k = Math.round(value / stops);
  // Rounded to a microdegree so that 3 × 5 stays 15, not 15.000000000000002.
  return Math.round(k * stops * 1e6) / 1e6;
}

/** Circular distance between two angles in degrees, in [0, 180]. */
function circularDistance(a: number, b: number): number {
  const d = Math.abs(wrap360(a) - wrap360(b));
  return Math.min(d, 360 - d);
}

/**
 * The valid aim nearest to a requested one: rotation wrapped into [0, 360), snapped to its stops and,
 * when it falls in the range's gap (e.g. 355–360 for a 0–355° head), moved to the nearer end around
 * the circle; tilt snapped and clamped to its range. Non-finite values count as 0.
 */
export function clampAim(aim: ModuleAim, limits: AimLimits): ModuleAim {
  const { rotation: rr, tilt: tr } = limits;
  let rotation = wrap360(snap(wrap360(Number.isFinite(aim.rotation) ? aim.rotation : 0), rr.stops));
  if (rotation < rr.min - EPS || rotation > rr.max + EPS) rotation = circularDistance(rotation, rr.min) <= circularDistance(rotation, rr.max) ? rr.min : rr.max;
  let tilt = snap(Number.isFinite(aim.tilt) ? aim.tilt : 0, tr.stops);
  tilt = Math.min(tr.max, Math.max(tr.min, tilt));
  return { rotation, tilt };
}

function onStop(value: number, stops: number | undefined): boolean {
  if (!stops) return true;
  const k = value / stops;
  return Math.abs(k - Math.round(k)) * stops < EPS;
}

/** The sentence keys of each angle's rules (docs/i18n.md). */
const RANGE_KEYS = {
  rotation: { notNumber: 'aimRotationNotNumber', range: 'aimRotationRange', stops: 'aimRotationStops' },
  tilt: { notNumber: 'aimTiltNotNumber', range: 'aimTiltRange', stops: 'aimTiltStops' },
} as const;

function rangeProblem(value: number, r: AimRange, what: 'rotation' | 'tilt'): { key: string; message: string; params: Record<string, string | number> } | null {
  const keys = RANGE_KEYS[what];
  if (!Number.isFinite(value)) return { key: keys.notNumber, message: `${what} must be a number of degrees (got ${String(value)})`, params: { value: String(value) } };
  if (value < r.min - EPS || value > r.max + EPS) return { key: keys.range, message: `${what} must be between ${r.min}° and ${r.max}° (got ${value}°)`, params: { min: r.min, max: r.max, value } };
  if (!onStop(value, r.stops)) return { key: keys.stops, message: `${what} must be a multiple of ${r.stops}° (got ${value}°)`, params: { step: r.stops ?? 0, value } };
  return null;
}

/** validate()'s rule for a module's aim: null when valid, else the problem's field and sentence. */
export function aimProblem(aim: ModuleAim, type: ModuleTypeSpec): { field: 'aim' | 'aim.rotation' | 'aim.tilt'; message: string } | null {
  if (!type.adjustable) return keyed({ field: 'aim', message: `${type.name} is fixed: it cannot be aimed` }, 'aimFixed', { name: type.name, typeId: type.id });
  if (typeof aim !== 'object' || aim === null) return keyed({ field: 'aim', message: 'aim must be { rotation, tilt }' }, 'aimShape');
  if (Number.isFinite(aim.rotation) && (aim.rotation < 0 || aim.rotation >= 360)) return keyed({ field: 'aim.rotation', message: `rotation must be in [0, 360) degrees (got ${aim.rotation}°)` }, 'aimRotationTurn', { value: aim.rotation });
  const r = rangeProblem(aim.rotation, type.adjustable.rotation, 'rotation');
  if (r) return keyed({ field: 'aim.rotation', message: r.message }, r.key, r.params);
  const t = rangeProblem(aim.tilt, type.adjustable.tilt, 'tilt');
  return t ? keyed({ field: 'aim.tilt', message: t.message }, t.key, t.params) : null;
}

/**
 * World direction of the optical axis of a module on a rail of plan heading `heading` with `aim`:
 * tilted `tilt` from straight down toward the plan direction heading + rotation.
 */
export function aimAxis(heading: number, aim: ModuleAim | undefined): Vec3 {
  const t = (aim?.tilt ?? 0) * DEG;
  const a = (heading + (aim?.rotation ?? 0)) * DEG;
  return [Math.sin(t) * Math.cos(a), -Math.cos(t), -Math.sin(t) * Math.sin(a)];
}

/**
 * The lighting-scene orientation of an aimed module. With pitch = tilt, Ry(yaw)·Rx(tilt) sends
 * local −y to (−sin yaw·sin t, −cos t, −cos yaw·sin t); equal to aimAxis for a = heading + rotation
 * exactly when sin yaw = −cos a and cos yaw = sin a, i.e. yaw = a − 90°. The roll then gets +90° so
 * that, untilted, the head's C0 still runs along a = heading + rotation (Ry(a − 90)·Ry(roll + 90) =
 * Ry(a + roll)): the head turns, then tilts, like a track spot's swivel and trunnion. Untilted
 * aims keep pitch 0 and yaw = a, the unaimed module's convention, so an unaimed module's basis
 * key (engines/relight/luminaireGroups.ts) does not change.
 */
export function aimedOrientation(heading: number, roll: number, aim: ModuleAim | undefined): { yaw: number; pitch: number; roll: number } {
  const a = heading + (aim?.rotation ?? 0);
  if (!aim || aim.tilt === 0) return { yaw: wrap360(a), pitch: 0, roll };
  return { yaw: wrap360(a - 90), pitch: aim.tilt, roll: roll + 90 };
}

/**
 * The aim whose axis points from `from` at `to` (world metres), for a rail of plan heading `heading`,
 * before limits: tilt = the angle from straight down, rotation = the plan direction relative to the
 * rail. A point straight below keeps `keepRotation` (any rotation aims there). Null when the points
 * coincide (no direction).
 */
export function aimToward(from: Vec3, to: Vec3, heading: number, keepRotation = 0): ModuleAim | null {
  const d = [to[0] - from[0], to[1] - from[1], to[2] - from[2]];
  const horizontal = Math.hypot(d[0], d[2]);
  if (!(Math.hypot(horizontal, d[1]) > 1e-9)) return null;
  const tilt = Math.atan2(horizontal, -d[1]) / DEG;
  if (horizontal < 1e-9) return { rotation: wrap360(keepRotation), tilt };
  // The plan direction (cos a, −sin a) of docs/scene-format.md: a = atan2(−dz, dx).
  return { rotation: wrap360(Math.atan2(-d[2], d[0]) / DEG - heading), tilt };
}
