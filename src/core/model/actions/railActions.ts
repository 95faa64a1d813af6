/**
 * Rail length, distribution, and growing or shortening the snake.
 * Rail lengths snap to the catalog step; a length that would cut off modules is
 * refused (never clamped), and the reason names the shortest length that works.
 * Range, fit, walls and clashes are validate()'s rules, checked on the result
 * where the action is bound; these definitions only word the refusals.
 */
import { z } from 'zod';
import type { ActionDefinition } from '../action';
import { DISTRIBUTIONS, findConnector, type Catalog } from '../catalogSchema';
import type { Configuration, Feed, LightSystem, Rail } from '../configuration';
import { plannedFeeds } from '../feedLoads';
import { keepFixingsIfValid, withoutFixings } from '../fixingRules';
import { withoutOffsets } from '../freePositions';
import { railModuleOffsets, railPlacements } from '../geometry';
import { FIT_CODES } from './moduleActions';
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
  /** Moved fixing points stay only when they keep the rules on the new length (fixingRules.ts). */
  perform(state, p, catalog) {
    const next = updateRail(state, p.railId, { length: snapRailLength(p.length, catalog) });
    const si = findRail(next, p.railId).systemIndex;
    return replaceSystem(next, si, keepFixingsIfValid(next.systems[si], catalog));
  },
  explain(problem, state, p, catalog) {
    if (!FIT_CODES.has(problem.code)) return problem.message;
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
  /** On a freely arranged rail this also clears the free positions: one step, undone as one. */
  perform(state, p) {
    const { rail } = findRail(state, p.railId);
    return updateRail(state, p.railId, { distribution: p.distribution, modules: withoutOffsets(rail.modules) });
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
    // Moved fixing points stay only when they keep the rules on the longer chain (fixingRules.ts).
    return replaceSystem(next, si, keepFixingsIfValid({ ...s, rails: [...s.rails, rail], joints: [...s.joints, { connector: p.connector, turn: p.turn }] }, catalog));
  },
  explain(problem, _state, p, catalog) {
    if (problem.code !== 'bad-turn') return problem.message;
    const con = findConnector(catalog, p.connector);
    if (con.flex) return `the ${con.name} turns by a multiple of ${con.flex.step}° within ±${con.flex.maxAngle}°`;
    return con.angle === 0 ? `${con.name} does not turn` : `${con.name} turns by ±${con.angle}°`;
  },
};

const railIdParams = z.object({ railId: z.string() });

/**
 * Removes any rail of a chain with its modules (docs/model.md, "Removing a rail"); a system keeps
 * at least one rail. The last rail: the chain ends one connector earlier. The first rail: the
 * chain starts at the next rail (the system's anchor and heading move there). A middle rail: the
 * chain splits into two systems, each keeping its side's rails, joints, modules and feeds (see
 * splitChain); refused when a part would be invalid.
 */
export const removeRail: ActionDefinition<z.infer<typeof railIdParams>> = {
  name: 'removeRail',
  label: 'Remove rail',
  params: railIdParams,
  perform(state, p, catalog) {
    // Removing a rail renumbers the chain's coordinates: moved fixing points go back to the derived ones.
    const ref = findRail(state, p.railId);
    const { systemIndex: si, railIndex } = ref;
    const system = withoutFixings(ref.system);
    const n = system.rails.length;
    if (n > 1 && railIndex === n - 1) {
      // The connector before the removed rail becomes the chain end: a feed there stays where it is, now at 'end'.
      const feeds = system.feeds.map((f) => (typeof f.at === 'object' && f.at.joint === railIndex - 1 ? { ...f, at: 'end' as const } : f));
      return replaceSystem(state, si, { ...system, rails: system.rails.slice(0, -1), joints: system.joints.slice(0, railIndex - 1), feeds });
    }
    if (n > 1 && railIndex === 0) {
      // The first connector becomes the chain start: a feed there stays where it is, now at 'start'; the others shift down one connector.
      const placement = railPlacements(system, catalog)[1];
      const feeds = system.feeds.map((f) => (typeof f.at === 'object' ? { ...f, at: f.at.joint === 0 ? ('start' as const) : { joint: f.at.joint - 1 } } : f));
      return replaceSystem(state, si, { ...system, x: placement.start[0], z: placement.start[1], rotation: placement.heading, rails: system.rails.slice(1), joints: system.joints.slice(1), feeds });
    }
    if (n === 1) return replaceSystem(state, si, { ...system, rails: [], joints: [] });
    return splitChain(state, si, railIndex, catalog);
  },
  explain(problem, state, p) {
    const { system, railIndex } = findRail(state, p.railId);
    if (problem.code === 'feed-duplicate') {
      return railIndex === 0
        ? 'a feed at the chain start and one at the first connector would meet; remove one of them first'
        : 'a feed at the last connector and one at the chain end would meet; remove one of them first';
    }
    if (problem.code === 'no-rails') return 'a system keeps at least one rail; delete the system instead';
    if (railIndex > 0 && railIndex < system.rails.length - 1 && problem.code !== 'feed-overload') return `splitting the chain here would leave an invalid part: ${problem.message}`;
    return problem.message;
  },
};

/**
 * Removes middle rail k of system si: rails 0…k−1 stay in the system (joints 0…k−2), rails k+1…
 * become a new system (joints k+1…) anchored at rail k+1's start with its heading, same
 * suspension and mounting. Feeds follow their position: connector k−1 becomes the first part's
 * end, connector k the second part's start, the chain end stays the second part's end, connectors
 * past k shift down by k+1. A part left without a feed gets the feeds a new system of its shape
 * gets (plannedFeeds: the default driver at its start, or a driver that carries its load);
 * when no driver can, validate() refuses the split with the overload.
 */
function splitChain(state: Configuration, si: number, k: number, catalog: Catalog): Configuration {
  const system = withoutFixings(state.systems[si]);
  const placement = railPlacements(system, catalog)[k + 1];
  const firstFeeds: Feed[] = [];
  const secondFeeds: Feed[] = [];
  for (const f of system.feeds) {
    if (f.at === 'start') firstFeeds.push(f);
    else if (f.at === 'end') secondFeeds.push(f);
    else if (f.at.joint < k - 1) firstFeeds.push(f);
    else if (f.at.joint === k - 1) firstFeeds.push({ ...f, at: 'end' });
    else if (f.at.joint === k) secondFeeds.push({ ...f, at: 'start' });
    else secondFeeds.push({ ...f, at: { joint: f.at.joint - k - 1 } });
  }
  const [newId, withSystemId] = takeId(state, 's');
  let next = withSystemId;
  const first: LightSystem = { ...system, rails: system.rails.slice(0, k), joints: system.joints.slice(0, k - 1), feeds: firstFeeds };
  const { presetId: _preset, ...rest } = system;
  const second: LightSystem = { ...rest, id: newId, x: placement.start[0], z: placement.start[1], rotation: placement.heading, rails: system.rails.slice(k + 1), joints: system.joints.slice(k + 1), feeds: secondFeeds };
  const withFeeds = (part: LightSystem): LightSystem => {
    if (part.feeds.length > 0) return part;
    const planned = plannedFeeds(part, catalog);
    const feeds = planned.map((f) => {
      let id: string;
      [id, next] = takeId(next, 'f');
      return { id, ...f };
    });
    return { ...part, feeds };
  };
  const a = withFeeds(first);
  const b = withFeeds(second);
  return { ...next, systems: [...next.systems.slice(0, si), a, b, ...next.systems.slice(si + 1)] };
}
