import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import { modulePlacements, railPlacements, type PlanVec } from '../../core/model/rails/geometry';
import type { PlanPoint } from './viewTransform';

/** A module's rail as a line in the plan: its start, unit direction, and the module's current start along it. */
export interface ModuleOnRail {
  readonly systemId: string;
  readonly railStart: PlanVec;
  readonly direction: PlanVec;
  /** Metres from the rail start to the module's start, as laid out now. */
  readonly offset: number;
}

/** Where a module sits on its rail, or null when it is not in the configuration (or its rail's layout does not fit). */
export function moduleOnRail(config: Configuration, catalog: Catalog, moduleId: string): ModuleOnRail | null {
  for (const s of config.systems) {
    const m = modulePlacements(s, catalog).find((p) => p.moduleId === moduleId);
    if (!m) continue;
    const rail = railPlacements(s, catalog).find((r) => r.railId === m.railId);
    if (!rail) return null;
    return { systemId: s.id, railStart: rail.start, direction: rail.direction, offset: m.offset };
  }
  return null;
}

/** Distance along the rail of a plan point's projection (the drag follows the pointer along the rail only). */
export function alongRail(on: ModuleOnRail, p: PlanPoint): number {
  return (p.x - on.railStart[0]) * on.direction[0] + (p.z - on.railStart[1]) * on.direction[1];
}

/**
 * The sign of an arrow-key step along a rail: +1 when the arrow's plan direction points along
 * the rail (more than 45° towards its end), −1 against it, 0 across it (the module cannot follow).
 */
export function stepAlongRail(on: ModuleOnRail, dx: number, dz: number): -1 | 0 | 1 {
  const len = Math.hypot(dx, dz);
  if (len === 0) return 0;
  const dot = (dx * on.direction[0] + dz * on.direction[1]) / len;
  return dot > Math.SQRT1_2 - 1e-9 ? 1 : dot < -Math.SQRT1_2 + 1e-9 ? -1 : 0;
}
