/**
 * Rail length, distribution, and growing or shortening the snake.
 * Rail lengths snap to the catalog step; a length that would cut off modules is
 * refused (never clamped), and the reason names the shortest length that works.
 */
import { z } from 'zod';
import { InputError } from '../../inputError';
import { refuse, type ActionDefinition } from '../action';
import { DISTRIBUTIONS, findConnector, findModuleType, type Catalog } from '../catalogSchema';
import type { Rail } from '../configuration';
import { layoutModules } from '../distribution';
import { findRail, guard, replaceRail, replaceSystem, systemFits, systemIndex, takeId } from './lookup';

/** Nearest multiple of the catalog step, rounded to a micrometre so 1.3 stays 1.3. */
export function snapRailLength(length: number, catalog: Catalog): number {
  const step = catalog.rail.step;
  return Math.round(Math.round(length / step) * step * 1e6) / 1e6;
}

/** Whether the rail's modules fit at this length with its distribution. */
function modulesFit(rail: Rail, length: number, catalog: Catalog): boolean {
  return layoutModules(rail.modules.map((m) => findModuleType(catalog, m.type).length), length, rail.distribution) !== null;
}

/** The shortest on-grid length within the catalog range that holds the rail's modules, or null. */
export function minRailLength(rail: Rail, catalog: Catalog): number | null {
  const { minLength, maxLength } = catalog.rail;
  for (let len = snapRailLength(minLength, catalog); len <= maxLength + 1e-9; len = snapRailLength(len + catalog.rail.step, catalog)) {
    if (modulesFit(rail, len, catalog)) return len;
  }
  return null;
}

const lengthParams = z.object({ railId: z.string(), length: z.number() });

export const setRailLength: ActionDefinition<z.infer<typeof lengthParams>> = {
  name: 'setRailLength',
  label: 'Rail length',
  params: lengthParams,
  isEnabled(state, p, catalog) {
    return guard(() => {
      const { rail, systemIndex: si } = findRail(state, p.railId);
      const len = snapRailLength(p.length, catalog);
      const { minLength, maxLength } = catalog.rail;
      if (len < minLength - 1e-9 || len > maxLength + 1e-9) return refuse(`rail length must be between ${minLength} and ${maxLength} m`);
      if (!modulesFit(rail, len, catalog)) {
        const min = minRailLength(rail, catalog);
        return refuse(`${len} m would cut off modules; this rail needs at least ${min ?? maxLength} m (remove modules to shorten it)`);
      }
      return systemFits(setRailLength.perform(state, p, catalog), si, catalog);
    });
  },
  perform(state, p, catalog) {
    const ref = findRail(state, p.railId);
    return replaceRail(state, ref, { ...ref.rail, length: snapRailLength(p.length, catalog) });
  },
};

const distributionParams = z.object({ railId: z.string(), distribution: z.enum(DISTRIBUTIONS) });

export const setDistribution: ActionDefinition<z.infer<typeof distributionParams>> = {
  name: 'setDistribution',
  label: 'Distribution',
  params: distributionParams,
  isEnabled(state, p, catalog) {
    return guard(() => {
      const { rail } = findRail(state, p.railId);
      const lengths = rail.modules.map((m) => findModuleType(catalog, m.type).length);
      return layoutModules(lengths, rail.length, p.distribution) ? true : refuse(`the modules do not fit '${p.distribution}' on this ${rail.length} m rail`);
    });
  },
  perform(state, p) {
    const ref = findRail(state, p.railId);
    return replaceRail(state, ref, { ...ref.rail, distribution: p.distribution });
  },
};

const addRailParams = z.object({
  systemId: z.string(),
  connector: z.string(),
  /** Degrees, + = left turn (counterclockwise seen from above); ±the connector's angle, 0 for straight. */
  turn: z.number(),
  length: z.number().optional(),
});

/** Appends an empty rail to the end of the snake through a connector. */
export const addRail: ActionDefinition<z.infer<typeof addRailParams>> = {
  name: 'addRail',
  label: 'Add rail',
  params: addRailParams,
  isEnabled(state, p, catalog) {
    return guard(() => {
      const si = systemIndex(state, p.systemId);
      const con = findConnector(catalog, p.connector);
      if (Math.abs(p.turn) !== con.angle) return refuse(con.angle === 0 ? `${con.name} does not turn` : `${con.name} turns by ±${con.angle}°`);
      const len = snapRailLength(p.length ?? catalog.rail.defaultLength, catalog);
      if (len < catalog.rail.minLength - 1e-9 || len > catalog.rail.maxLength + 1e-9) return refuse(`rail length must be between ${catalog.rail.minLength} and ${catalog.rail.maxLength} m`);
      return systemFits(addRail.perform(state, p, catalog), si, catalog);
    });
  },
  perform(state, p, catalog) {
    const si = systemIndex(state, p.systemId);
    const [id, next] = takeId(state, 'r');
    const s = next.systems[si];
    const rail: Rail = { id, length: snapRailLength(p.length ?? catalog.rail.defaultLength, catalog), distribution: 'inside-centred', modules: [] };
    return replaceSystem(next, si, { ...s, rails: [...s.rails, rail], joints: [...s.joints, { connector: p.connector, turn: p.turn }] });
  },
};

const railIdParams = z.object({ railId: z.string() });

/** Removes the last rail of a snake (with its modules and joint); a system keeps at least one rail. */
export const removeRail: ActionDefinition<z.infer<typeof railIdParams>> = {
  name: 'removeRail',
  label: 'Remove rail',
  params: railIdParams,
  isEnabled(state, p) {
    return guard(() => {
      const { system, railIndex } = findRail(state, p.railId);
      if (system.rails.length < 2) return refuse('a system keeps at least one rail; delete the system instead');
      if (railIndex !== system.rails.length - 1) return refuse('only the last rail of a chain can be removed');
      return true;
    });
  },
  perform(state, p) {
    const { systemIndex: si, system, railIndex } = findRail(state, p.railId);
    if (railIndex !== system.rails.length - 1) throw new InputError('only the last rail of a chain can be removed');
    return replaceSystem(state, si, { ...system, rails: system.rails.slice(0, -1), joints: system.joints.slice(0, railIndex - 1) });
  },
};
