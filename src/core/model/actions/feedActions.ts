/**
 * Power feeds of a system (docs/model.md, "Power feeds"): add one at a position the catalog
 * allows, move it, remove it (never the last: validate()'s `no-feed`), choose its driver.
 * Whether every feed's load fits its driver is validate()'s rule (`feed-overload`), checked on
 * the result where the action is bound, so a move that would overload a driver is refused too.
 */
import { z } from 'zod/mini';
import type { ActionDefinition, CodedReason } from './action';
import { findDriver } from '../catalogSchema/catalogSchema';
import type { FeedAt } from '../configuration/configuration';
import { describeFeedAt, feedAtParam, feedLabel, feedLoads, formatWatts } from '../power/feedLoads';
import type { Problem } from '../configuration/problem';
import { findFeed, replaceSystem, systemIndex, takeId } from './lookup';

/** 'start', 'end', { joint: k } (the connector joints[k] goes through) or { end: i } (rail i's free end, a branch). */
export const feedAtParams = z.union([z.literal('start'), z.literal('end'), z.strictObject({ joint: z.number().check(z.int(), z.nonnegative()) }), z.strictObject({ end: z.number().check(z.int(), z.nonnegative()) })]);

function positionReason(problem: Problem, at: FeedAt): string | CodedReason {
  if (problem.code === 'feed-duplicate') return { reason: `there is already a feed at ${describeFeedAt(at)}`, code: 'feedAlreadyThere', params: { feedAt: feedAtParam(at) } };
  return problem.message;
}

const addParams = z.object({
  systemId: z.string(),
  at: feedAtParams,
  /** Catalog driver id; default: the catalog's defaultDriver. */
  driver: z.optional(z.string()),
});

/** A second (third, …) feed: the modules nearer to it than to the other feeds move to it. */
export const addFeed: ActionDefinition<z.infer<typeof addParams>> = {
  name: 'addFeed',
  label: 'Add feed',
  params: addParams,
  perform(state, p, catalog) {
    const si = systemIndex(state, p.systemId);
    const [id, next] = takeId(state, 'f');
    const s = next.systems[si];
    return replaceSystem(next, si, { ...s, feeds: [...s.feeds, { id, at: p.at, driver: p.driver ?? catalog.feed.defaultDriver }] });
  },
  explain(problem, _state, p) {
    return positionReason(problem, p.at);
  },
};

const moveParams = z.object({ feedId: z.string(), at: feedAtParams });

export const moveFeed: ActionDefinition<z.infer<typeof moveParams>> = {
  name: 'moveFeed',
  label: 'Move feed',
  params: moveParams,
  perform(state, p) {
    const ref = findFeed(state, p.feedId);
    return replaceSystem(state, ref.systemIndex, { ...ref.system, feeds: ref.system.feeds.map((f, i) => (i === ref.feedIndex ? { ...f, at: p.at } : f)) });
  },
  explain(problem, _state, p) {
    return positionReason(problem, p.at);
  },
};

const feedIdParams = z.object({ feedId: z.string() });

/** Removes a feed; its modules go to the nearest remaining feed. */
export const removeFeed: ActionDefinition<z.infer<typeof feedIdParams>> = {
  name: 'removeFeed',
  label: 'Remove feed',
  params: feedIdParams,
  perform(state, p) {
    const ref = findFeed(state, p.feedId);
    return replaceSystem(state, ref.systemIndex, { ...ref.system, feeds: ref.system.feeds.filter((_, i) => i !== ref.feedIndex) });
  },
  explain(problem) {
    return problem.code === 'no-feed' ? { reason: 'a system keeps at least one power feed', code: 'keepOneFeed' } : problem.message;
  },
};

const driverParams = z.object({ feedId: z.string(), driver: z.string() });

/** Chooses a feed's driver; refused when the feed's load would not fit it. */
export const setFeedDriver: ActionDefinition<z.infer<typeof driverParams>> = {
  name: 'setFeedDriver',
  label: 'Driver',
  params: driverParams,
  perform(state, p, catalog) {
    const ref = findFeed(state, p.feedId);
    const driver = findDriver(catalog, p.driver);
    return replaceSystem(state, ref.systemIndex, { ...ref.system, feeds: ref.system.feeds.map((f, i) => (i === ref.feedIndex ? { ...f, driver: driver.id } : f)) });
  },
  explain(problem, state, p, catalog) {
    if (problem.code !== 'feed-overload') return problem.message;
    const ref = findFeed(state, p.feedId);
    const load = feedLoads(ref.system, catalog)[ref.feedIndex].load;
    const driver = findDriver(catalog, p.driver);
    return {
      reason: `the ${formatWatts(driver.capacity)} W ${driver.name} cannot carry the ${formatWatts(load)} W on ${feedLabel(ref.feedIndex)}; choose a larger driver or add a feed`,
      code: 'driverTooSmall',
      params: { capacity: Number(formatWatts(driver.capacity)), driver: driver.name, driverId: driver.id, load: Number(formatWatts(load)), n: ref.feedIndex + 1 },
    };
  },
};
