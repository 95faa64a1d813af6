import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import { modulePlacements, systemElementTree, type PlanRect } from '../../core/model/rails/geometry';
import { suspensionPoints } from '../../core/model/rails/suspensionPoints';
import { objectPolygons } from './objectShapes';
import { type PlanPoint, type PlanView, type ScreenPoint, screenToWorld } from './viewTransform';

/** What is under a point of the plan (all undefined on empty floor or outside the room). */
export interface PlanHit {
  systemId?: string;
  railId?: string;
  moduleId?: string;
  /** A piece of furniture or an imported model (found only where no system is). */
  objectId?: string;
  /** Index of a movable fixing point (suspension or clip on a rail, not on a connector) within FIXING_HIT_PX, with its system. */
  fixing?: number;
}

/** A fixing point's dot takes a press this close to its centre (pixels). */
export const FIXING_HIT_PX = 8;

/** Module symbols are drawn wider than the rail profile so they read as separate parts. */
export const MODULE_WIDTH_FACTOR = 1.8;

/** Rails are a few centimetres wide: invisible hit strips keep them easy to tap (44 px across). */
export const HIT_HALF_WIDTH_PX = 22;

/** A module's drawn symbol: its footprint, widened. */
export function moduleSymbol(footprint: PlanRect): PlanRect {
  return { ...footprint, halfWidth: footprint.halfWidth * MODULE_WIDTH_FACTOR };
}

/** A rail's or connector's invisible hit strip at this scale (px/m). */
export function hitStrip(r: PlanRect, scale: number): PlanRect {
  return { ...r, halfWidth: Math.max(r.halfWidth, HIT_HALF_WIDTH_PX / scale) };
}

function inside(r: PlanRect, x: number, z: number): boolean {
  const dx = x - r.centre[0];
  const dz = z - r.centre[1];
  const along = dx * r.axis[0] + dz * r.axis[1];
  const across = -dx * r.axis[1] + dz * r.axis[0];
  return Math.abs(along) <= r.halfLength && Math.abs(across) <= r.halfWidth;
}

/** Objects closer than this to the pointer (outside their outline) still take a tap: a 3 cm picture on its wall stays tappable. */
export const OBJECT_HIT_MARGIN_PX = 12;

/** Whether (x, z) is inside a polygon (even-odd rule, the SVG default fill rule). */
export function insidePolygon(poly: readonly PlanPoint[], x: number, z: number): boolean {
  let inside = false;
  for (let i = 0, j = poly.length - 1; i < poly.length; j = i++) {
    const a = poly[i];
    const b = poly[j];
    if (a.z > z !== b.z > z && x < ((b.x - a.x) * (z - a.z)) / (b.z - a.z) + a.x) inside = !inside;
  }
  return inside;
}

/** Distance from (x, z) to a polygon's edges. */
export function distanceToPolygon(poly: readonly PlanPoint[], x: number, z: number): number {
  let best = Infinity;
  for (let i = 0, j = poly.length - 1; i < poly.length; j = i++) {
    const a = poly[j];
    const b = poly[i];
    const ex = b.x - a.x;
    const ez = b.z - a.z;
    const len2 = ex * ex + ez * ez;
    const t = len2 > 0 ? Math.max(0, Math.min(1, ((x - a.x) * ex + (z - a.z) * ez) / len2)) : 0;
    best = Math.min(best, Math.hypot(x - (a.x + t * ex), z - (a.z + t * ez)));
  }
  return best;
}

/**
 * The object under a plan point, as PlanSvg stacks them (later objects above earlier ones):
 * first one whose outline contains it, else the nearest within `margin` metres.
 */
export function objectAt(config: Configuration, x: number, z: number, margin: number): string | undefined {
  const objects = [...config.objects].reverse();
  const shapes = objects.map((o) => objectPolygons(config, o.id));
  // Even-odd over the outline's loops, as it is filled: a point in a hole (under a table's rim) is not on it.
  const inside = objects.findIndex((_, i) => shapes[i].filter((p) => insidePolygon(p, x, z)).length % 2 === 1);
  if (inside >= 0) return objects[inside].id;
  let best: { id: string; d: number } | undefined;
  objects.forEach((o, i) => {
    const d = Math.min(...shapes[i].map((p) => distanceToPolygon(p, x, z)));
    if (d <= margin && (!best || d < best.d)) best = { id: o.id, d };
  });
  return best?.id;
}

/**
 * The plan element under a screen point, found the way the drawn SVG stacks them (PlanSvg):
 * later systems above earlier ones; inside a system the module symbols on top, then the
 * visible rails and connectors, then the wide hit strips; objects come last, under every system. A rail names
 * itself; a connector node names the rail it ends (selecting it shows that node's branches and ports).
 */
export function planHitTest(config: Configuration, catalog: Catalog, view: PlanView, point: ScreenPoint): PlanHit {
  const { x, z } = screenToWorld(view, point);
  // The nearest movable fixing dot of the hit system within FIXING_HIT_PX, added to the hit (what a tap selects is unchanged).
  const withFixing = (hit: PlanHit & { systemId: string }): PlanHit => {
    const system = config.systems.find((s) => s.id === hit.systemId);
    if (!system) return hit;
    const dots = suspensionPoints(system, catalog).map((p, i) => ({ i, joint: p.joint, d: Math.hypot(p.plan[0] - x, p.plan[1] - z) }));
    const dot = dots.filter((q) => q.joint === null && q.d * view.scale <= FIXING_HIT_PX).sort((a, b) => a.d - b.d)[0];
    return dot ? { ...hit, fixing: dot.i } : hit;
  };
  for (const system of [...config.systems].reverse()) {
    const module = [...modulePlacements(system, catalog)].reverse().find((m) => inside(moduleSymbol(m.footprint), x, z));
    if (module) return withFixing({ systemId: system.id, moduleId: module.moduleId });
    const { elements, kinds } = systemElementTree(system, catalog);
    for (const widen of [false, true]) {
      for (let i = elements.length - 1; i >= 0; i--) {
        if (elements[i].some((r) => inside(widen ? hitStrip(r, view.scale) : r, x, z))) {
          return withFixing({ systemId: system.id, railId: system.rails[kinds[i].rail]?.id });
        }
      }
    }
  }
  // Objects stand on the floor, drawn under the rails (the lights hang from the ceiling).
  const objectId = objectAt(config, x, z, OBJECT_HIT_MARGIN_PX / view.scale);
  return objectId ? { objectId } : {};
}
