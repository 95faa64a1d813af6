import type { Configuration, RoomObject } from '../../core/model/configuration/configuration';
import { fitPlacement, objectMesh, sourceName } from '../../core/model/objects/objectGeometry';
import { movedPlacement, wallAxis } from './objectMoves';
import type { PlanPoint } from './viewTransform';

/**
 * A drag of an object stops at the walls instead of being refused (issue #27, "Furniture"): the
 * delta is cut back so the moved object lies inside the room (the model's fitPlacement, the same
 * rule a new object is placed by), the corrected coordinate rounded on the `snap` grid toward the
 * room so the drop lands exactly there. An object that cannot fit at all keeps the delta asked for
 * (the move is then refused with the model's reason).
 */
export function clampObjectDelta(config: Configuration, object: RoomObject, delta: PlanPoint, snap: number): PlanPoint {
  const wanted = movedPlacement(object.placement, delta, snap);
  let fitted: RoomObject;
  try {
    fitted = fitPlacement({ ...object, placement: wanted }, objectMesh(config, object.id), config.room, sourceName(config, object.source));
  } catch {
    return delta;
  }
  const from = object.placement;
  const to = fitted.placement;
  // Nothing to stop: the pointer's own delta, so the piece follows the finger smoothly.
  if (JSON.stringify(to) === JSON.stringify(wanted)) return delta;
  const perMetre = Math.round(1 / snap);
  // Toward the room: up when the fit pushed the object up, down when it pulled it back (1 µm of
  // slack: float32 vertices put a 2.1 m sofa's half width at 1.0500000x m).
  const inward = (was: number, now: number) => (now > was ? Math.ceil(now * perMetre - 1e-4) : now < was ? Math.floor(now * perMetre + 1e-4) : Math.round(now * perMetre)) / perMetre;
  if (from.on === 'floor' && wanted.on === 'floor' && to.on === 'floor') {
    return { x: inward(wanted.x, to.x) - from.x, z: inward(wanted.z, to.z) - from.z };
  }
  if (from.on === 'wall' && wanted.on === 'wall' && to.on === 'wall') {
    const along = inward(wanted.u, to.u) - from.u;
    const a = wallAxis(from.wall);
    return { x: a.x ? along : 0, z: a.z ? along : 0 };
  }
  return delta;
}
