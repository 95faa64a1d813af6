/**
 * Rail length, distribution, and growing or shortening the snake.
 * Rail lengths snap to the catalog step; a length that would cut off modules is
 * refused (never clamped), and the reason names the shortest length that works.
 * Range, fit, walls and clashes are validate()'s rules, checked on the result
 * where the action is bound; these definitions only word the refusals.
 */
import { z } from 'zod/mini';
import type { ActionDefinition } from './action';
import { quoting } from '../configuration/coding';
import { findConnector, type Catalog } from '../catalogSchema/catalogSchema';
import { DISTRIBUTIONS } from '../catalogSchema/railSystemSchema';
import type { Rail } from '../configuration/configuration';
import { plannedFeeds } from '../power/feedLoads';
import { keepFixingsIfValid, withoutFixings } from '../rails/fixingRules';
import { withoutOffsets } from '../rails/freePositions';
import { railModuleOffsets } from '../rails/geometry';
import { isLeafRail } from '../rails/railTree';
import { cutRail, piecesWithout } from '../rails/treeEdits';
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
    return {
      reason: `${snapRailLength(p.length, catalog)} m would cut off modules; this rail needs at least ${needed} m (remove modules to shorten it)`,
      code: 'railWouldCutModules',
      params: { length: snapRailLength(p.length, catalog), needed },
    };
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
    if (problem.code !== 'modules-do-not-fit') return problem.message;
    const length = findRail(state, p.railId).rail.length;
    return { reason: `the modules do not fit '${p.distribution}' on this ${length} m rail`, code: 'distributionDoesNotFit', params: { distribution: p.distribution, length } };
  },
};

const addRailParams = z.object({
  systemId: z.string(),
  connector: z.string(),
  /** Degrees, + = left turn (counterclockwise seen from above); ±the connector's angle, 0 for straight. */
  turn: z.number(),
  length: z.optional(z.number()),
});

/** Appends an empty rail at the end of the last rail through a connector (addBranch grows any other end or node). */
export const addRail: ActionDefinition<z.infer<typeof addRailParams>> = {
  name: 'addRail',
  label: 'Add rail',
  params: addRailParams,
  perform(state, p, catalog) {
    const si = systemIndex(state, p.systemId);
    const [id, next] = takeId(state, 'r');
    const s = next.systems[si];
    const rail: Rail = { id, length: snapRailLength(p.length ?? catalog.rail.defaultLength, catalog), distribution: 'inside-centred', modules: [] };
    // A feed at the last rail's free end written { end: i } moves on to the new end, as 'end' does.
    const last = s.rails.length - 1;
    const feeds = s.feeds.map((f) => (typeof f.at === 'object' && 'end' in f.at && f.at.end === last ? { ...f, at: 'end' as const } : f));
    // Moved fixing points stay only when they keep the rules on the longer chain (fixingRules.ts).
    return replaceSystem(next, si, keepFixingsIfValid({ ...s, rails: [...s.rails, rail], joints: [...s.joints, { connector: p.connector, turn: p.turn }], feeds }, catalog));
  },
  explain(problem, _state, p, catalog) {
    if (problem.code !== 'bad-turn') return problem.message;
    const con = findConnector(catalog, p.connector);
    const named = { name: con.name, connectorId: con.id };
    if (con.flex) return { reason: `the ${con.name} turns by a multiple of ${con.flex.step}° within ±${con.flex.maxAngle}°`, code: 'connectorTurnFlex', params: { ...named, step: con.flex.step, max: con.flex.maxAngle } };
    return con.angle === 0 ? { reason: `${con.name} does not turn`, code: 'connectorNoTurn', params: named } : { reason: `${con.name} turns by ±${con.angle}°`, code: 'connectorTurnAngle', params: { ...named, angle: con.angle } };
  },
};

const railIdParams = z.object({ railId: z.string() });

/**
 * Removes any rail of a system with its modules (docs/model.md, "Removing a rail"); a system keeps
 * at least one rail. The tree falls into the pieces that remain (treeEdits.ts cutRail): the rest
 * of the tree keeps the system (a removed first rail: the first branch's piece keeps it, its
 * anchor and heading moving there), each branch below the removed rail becomes a new system.
 * Feeds stay where they are; a piece left without one gets the feeds a new system of its shape
 * gets (plannedFeeds). Refused when a piece would be invalid (feeds that would meet, a driver
 * that cannot carry its part).
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
    if (system.rails.length === 1) return replaceSystem(state, si, { ...system, rails: [], joints: [] });
    const count = piecesWithout(system, railIndex).length;
    let next = state;
    const newIds: string[] = [];
    for (let i = 1; i < count; i++) {
      let id: string;
      [id, next] = takeId(next, 's');
      newIds.push(id);
    }
    const parts = cutRail(system, catalog, railIndex, newIds).map((part) => {
      if (part.feeds.length > 0) return part;
      const feeds = plannedFeeds(part, catalog).map((f) => {
        let id: string;
        [id, next] = takeId(next, 'f');
        return { id, ...f };
      });
      return { ...part, feeds };
    });
    return { ...next, systems: [...next.systems.slice(0, si), ...parts, ...next.systems.slice(si + 1)] };
  },
  explain(problem, state, p) {
    const { system, railIndex } = findRail(state, p.railId);
    if (problem.code === 'feed-duplicate') {
      return railIndex === 0
        ? { reason: 'a feed at the chain start and one at the first connector would meet; remove one of them first', code: 'feedsMeetAtStart' }
        : isLeafRail(system, railIndex)
          ? { reason: 'a feed at the last connector and one at the chain end would meet; remove one of them first', code: 'feedsMeetAtEnd' }
          : quoting(`two feeds would meet where the chain splits: ${problem.message}; remove one of them first`, 'feedsMeetAtSplit', problem);
    }
    if (problem.code === 'no-rails') return { reason: 'a system keeps at least one rail; delete the system instead', code: 'keepOneRail' };
    if (railIndex > 0 && !isLeafRail(system, railIndex) && problem.code !== 'feed-overload') return quoting(`splitting the chain here would leave an invalid part: ${problem.message}`, 'splitLeavesInvalidPart', problem);
    return problem.message;
  },
};
