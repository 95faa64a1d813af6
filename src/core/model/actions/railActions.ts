/**
 * Rail length, distribution, and growing or shortening the snake.
 * Rail lengths snap to the catalog step; a length that would cut off modules is
 * refused (never clamped), and the reason names the shortest length that works.
 * Range, fit, walls and clashes are validate()'s rules, checked on the result
 * where the action is bound; these definitions only word the refusals.
 */
import { z } from 'zod';
import { InputError } from '../../inputError';
import type { ActionDefinition } from '../action';
import { DISTRIBUTIONS, findConnector, type Catalog } from '../catalogSchema';
import type { Rail } from '../configuration';
import { railModuleOffsets } from '../geometry';
import { findRail, replaceSystem, systemIndex, takeId, updateRail } from './lookup';

/** Nearest multiple of the catalog step, rounded to a micrometre so 1.3 stays 1.3. */
export function snapRailLength(length: number, catalog: Catalog): number {
  const step = catalog.rail.step;
  return Math.round(Math.round(length / step) * step * 1e6) / 1e6;
}

/** The shortest on-grid length within the catalog range that holds the rail's modules, or null. */
export function minRailLength(rail: Rail, catalog: Catalog): number | null {
  const { minLength, maxLength } = catalog.rail;
  for (let len = snapRailLength(minLength, catalog); len <= maxLength + 1e-9; len = snapRailLength(len + catalog.rail.step, catalog)) {
    if (railModuleOffsets({ ...rail, length: len }, catalog) !== null) return len;
  }
  return null;
}

const lengthParams = z.object({ railId: z.string(), length: z.number() });

export const setRailLength: ActionDefinition<z.infer<typeof lengthParams>> = {
  name: 'setRailLength',
  label: 'Rail length',
  params: lengthParams,
  perform(state, p, catalog) {
    return updateRail(state, p.railId, { length: snapRailLength(p.length, catalog) });
  },
  explain(problem, state, p, catalog) {
    if (problem.code !== 'modules-do-not-fit') return problem.message;
    const { rail } = findRail(state, p.railId);
    const needed = minRailLength(rail, catalog) ?? catalog.rail.maxLength;
    return `${snapRailLength(p.length, catalog)} m would cut off modules; this rail needs at least ${needed} m (remove modules to shorten it)`;
  },
};

const distributionParams = z.object({ railId: z.string(), distribution: z.enum(DISTRIBUTIONS) });

export const setDistribution: ActionDefinition<z.infer<typeof distributionParams>> = {
  name: 'setDistribution',
  label: 'Distribution',
  params: distributionParams,
  perform(state, p) {
    return updateRail(state, p.railId, { distribution: p.distribution });
  },
  explain(problem, state, p) {
    return problem.code === 'modules-do-not-fit' ? `the modules do not fit '${p.distribution}' on this ${findRail(state, p.railId).rail.length} m rail` : problem.message;
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
  perform(state, p, catalog) {
    const si = systemIndex(state, p.systemId);
    const [id, next] = takeId(state, 'r');
    const s = next.systems[si];
    const rail: Rail = { id, length: snapRailLength(p.length ?? catalog.rail.defaultLength, catalog), distribution: 'inside-centred', modules: [] };
    return replaceSystem(next, si, { ...s, rails: [...s.rails, rail], joints: [...s.joints, { connector: p.connector, turn: p.turn }] });
  },
  explain(problem, _state, p, catalog) {
    if (problem.code !== 'bad-turn') return problem.message;
    const con = findConnector(catalog, p.connector);
    return con.angle === 0 ? `${con.name} does not turn` : `${con.name} turns by ±${con.angle}°`;
  },
};

const railIdParams = z.object({ railId: z.string() });

/** Removes the last rail of a snake (with its modules and joint); a system keeps at least one rail. */
export const removeRail: ActionDefinition<z.infer<typeof railIdParams>> = {
  name: 'removeRail',
  label: 'Remove rail',
  params: railIdParams,
  perform(state, p) {
    const { systemIndex: si, system, railIndex } = findRail(state, p.railId);
    if (railIndex !== system.rails.length - 1) throw new InputError('only the last rail of a chain can be removed');
    // The connector before the removed rail becomes the chain end: a feed there stays where it is, now at 'end'.
    const feeds = system.feeds.map((f) => (typeof f.at === 'object' && f.at.joint === railIndex - 1 ? { ...f, at: 'end' as const } : f));
    return replaceSystem(state, si, { ...system, rails: system.rails.slice(0, -1), joints: system.joints.slice(0, railIndex - 1), feeds });
  },
  explain(problem) {
    if (problem.code === 'feed-duplicate') return 'a feed at the last connector and one at the chain end would meet; remove one of them first';
    return problem.code === 'no-rails' ? 'a system keeps at least one rail; delete the system instead' : problem.message;
  },
};
