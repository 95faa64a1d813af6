import type { Catalog } from '../../core/model/catalogSchema';
import type { Configuration } from '../../core/model/configuration';
import { modulePlacements, systemElements, type PlanRect } from '../../core/model/geometry';
import { type PlanView, type ScreenPoint, screenToWorld } from './viewTransform';

/** What is under a point of the plan (all undefined on empty floor or outside the room). */
export interface PlanHit {
  systemId?: string;
  railId?: string;
  moduleId?: string;
}

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

/**
 * The plan element under a screen point, found the way the drawn SVG stacks them (PlanSvg):
 * later systems above earlier ones; inside a system the module symbols on top, then the
 * visible rails and connectors, then the wide hit strips. Elements alternate rail, connector,
 * rail, … (systemElements' contract), so only even ones name a rail.
 */
export function planHitTest(config: Configuration, catalog: Catalog, view: PlanView, point: ScreenPoint): PlanHit {
  const { x, z } = screenToWorld(view, point);
  for (const system of [...config.systems].reverse()) {
    const module = [...modulePlacements(system, catalog)].reverse().find((m) => inside(moduleSymbol(m.footprint), x, z));
    if (module) return { systemId: system.id, moduleId: module.moduleId };
    const elements = systemElements(system, catalog);
    for (const widen of [false, true]) {
      for (let i = elements.length - 1; i >= 0; i--) {
        if (elements[i].some((r) => inside(widen ? hitStrip(r, view.scale) : r, x, z))) {
          return { systemId: system.id, railId: i % 2 === 0 ? system.rails[i / 2]?.id : undefined };
        }
      }
    }
  }
  return {};
}
