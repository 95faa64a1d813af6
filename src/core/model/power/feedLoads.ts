/**
 * Power feeds and their loads (docs/model.md, "Power feeds"). Every module's input power
 * (the beam's `watts`, at full output: dimming is a setting, not a limit the driver may
 * rely on) goes to the feed nearest to the module's centre along the chain, on a tree along
 * its branches (chainCoordinates.ts distancesFrom, treeDistance); a tie goes to the feed nearer the chain start. A feed is
 * overloaded when its load exceeds its driver's rated output power.
 */
import { findBeam, findModuleType, type Catalog } from '../catalogSchema/catalogSchema';
import { type DriverSpec } from '../catalogSchema/powerSchema';
import type { Configuration, Feed, FeedAt, LightSystem } from '../configuration/configuration';
import { chainCoordinates, distancesFrom, feedCoordinate, feedLocation, onRail, type ChainCoordinates, type TreeLocation } from '../rails/chainCoordinates';
import { firstNodeJoints, jointParent, treeProblem } from '../rails/railTree';
import { railModuleOffsets } from '../rails/geometry';

/** Load sums are compared with a milliwatt of slack so 0.1 + 0.2 style float noise never refuses a fitting driver. */
export const LOAD_EPS = 1e-6;

export interface FeedLoad {
  readonly feed: Feed;
  /** Position in the system's feeds list (label "Feed index+1"). */
  readonly index: number;
  /** Chain coordinate of the feed, metres. */
  readonly s: number;
  readonly driver: DriverSpec;
  /** Sum of the assigned modules' watts. */
  readonly load: number;
  readonly capacity: number;
  readonly moduleIds: readonly string[];
}

/** "Feed 2": what the plan, the options panel and the refusals call a feed. */
export function feedLabel(index: number): string {
  return `Feed ${index + 1}`;
}

/** Watts for people: at most two decimals, no trailing zeros (96, 100.8, 137.56). */
export function formatWatts(w: number): string {
  return String(Math.round(w * 100) / 100);
}

/** A module's place on the tree (its centre) and watts, for the modules whose rails' layouts fit. */
function moduleLoads(system: LightSystem, catalog: Catalog, chain: ChainCoordinates): { id: string; at: TreeLocation; watts: number }[] {
  const out: { id: string; at: TreeLocation; watts: number }[] = [];
  system.rails.forEach((rail, i) => {
    const offsets = railModuleOffsets(rail, catalog);
    if (!offsets) return;
    rail.modules.forEach((m, k) => {
      const type = findModuleType(catalog, m.type);
      out.push({ id: m.id, at: onRail(chain, i, offsets[k] + type.length / 2), watts: findBeam(type, m.beam).watts });
    });
  });
  return out;
}

/** Index (into `coords`) of the nearest feed to s on a snake; ties to the one nearer the chain start. */
export function nearestFeed(coords: readonly number[], s: number): number {
  return nearestBy(
    coords.map((c) => Math.abs(c - s)),
    coords,
  );
}

/** Index of the smallest distance; ties (1e-12) to the smaller chain coordinate. */
function nearestBy(distances: readonly number[], coords: readonly number[]): number {
  let best = 0;
  for (let j = 1; j < distances.length; j++) {
    const d = distances[j];
    const b = distances[best];
    if (d < b - 1e-12 || (Math.abs(d - b) <= 1e-12 && coords[j] < coords[best])) best = j;
  }
  return best;
}

/**
 * nearestBy for a snake, where the distance is |depth − feed depth|: the feeds sorted by depth and
 * a binary search, so a module costs O(log feeds) instead of a pass over every feed (plannedFeeds
 * tries many feed counts on long chains). Candidates are the feeds whose depth is within 1e-9 of the
 * two neighbours of the module's depth; nearestBy over them in index order gives the same feed as
 * over all (the others are farther by more than its 1e-12 tie window). Feeds without a place (NaN)
 * are never nearest, as Infinity in nearestBy.
 */
function snakeNearest(depths: readonly number[], coords: readonly number[]): (depth: number) => number {
  const order = depths
    .map((_, j) => j)
    .filter((j) => !Number.isNaN(depths[j]))
    .sort((a, b) => depths[a] - depths[b] || a - b);
  if (order.length === 0) return () => 0;
  return (x) => {
    let lo = 0;
    let hi = order.length;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (depths[order[mid]] < x) lo = mid + 1;
      else hi = mid;
    }
    const picked = new Set<number>();
    for (const p of [lo - 1, lo]) {
      if (p < 0 || p >= order.length) continue;
      const d = depths[order[p]];
      for (let q = p; q >= 0 && Math.abs(depths[order[q]] - d) <= 1e-9; q--) picked.add(order[q]);
      for (let q = p + 1; q < order.length && Math.abs(depths[order[q]] - d) <= 1e-9; q++) picked.add(order[q]);
    }
    const candidates = [...picked].sort((a, b) => a - b);
    const best = nearestBy(
      candidates.map((j) => Math.abs(x - depths[j])),
      candidates.map((j) => coords[j]),
    );
    return candidates[best];
  };
}

/**
 * Each feed's load and capacity. The system's references must be sound (known drivers,
 * module types and beams, existing joints): validate() checks those first.
 */
export function feedLoads(system: LightSystem, catalog: Catalog): FeedLoad[] {
  const chain = chainCoordinates(system, catalog);
  const coords = system.feeds.map((f) => feedCoordinate(f.at, chain));
  // One distance field per feed (linear in the rails), then one lookup per module and feed.
  const fields = system.feeds.map((f) => {
    const at = feedLocation(f.at, chain);
    return at ? distancesFrom(chain, at) : null;
  });
  const loads = system.feeds.map(() => 0);
  const ids: string[][] = system.feeds.map(() => []);
  if (system.feeds.length > 0) {
    const nearestOnSnake = chain.snake
      ? snakeNearest(
          system.feeds.map((f) => feedLocation(f.at, chain)?.depth ?? NaN),
          coords,
        )
      : null;
    for (const m of moduleLoads(system, catalog, chain)) {
      const j = nearestOnSnake
        ? nearestOnSnake(m.at.depth)
        : nearestBy(
            fields.map((d) => (d ? d(m.at) : Infinity)),
            coords,
          );
      loads[j] += m.watts;
      ids[j].push(m.id);
    }
  }
  return system.feeds.map((feed, index) => {
    const driver = catalog.drivers.find((d) => d.id === feed.driver);
    if (!driver) throw new Error(`feedLoads: unknown driver '${feed.driver}' (validate() reports it first)`);
    return { feed, index, s: coords[index], driver, load: Math.round(loads[index] * 1e6) / 1e6, capacity: driver.capacity, moduleIds: ids[index] };
  });
}

export function isOverloaded(l: FeedLoad): boolean {
  return l.load > l.capacity + LOAD_EPS;
}

/** Same position as written (the planner's controls; validate() also knows that the joints of one node share a spot). */
export function sameFeedAt(a: FeedAt, b: FeedAt): boolean {
  if (typeof a === 'string' || typeof b === 'string') return a === b;
  if ('joint' in a) return 'joint' in b && a.joint === b.joint;
  return 'end' in b && a.end === b.end;
}

/** 'the chain start', 'the chain end', 'connector 2' (joints[1]), 'the end of rail 3'. */
export function describeFeedAt(at: FeedAt): string {
  if (at === 'start') return 'the chain start';
  if (at === 'end') return 'the chain end';
  return 'joint' in at ? `connector ${at.joint + 1}` : `the end of rail ${at.end + 1}`;
}

/** A feed position as one message parameter: 'start', 'end', 'joint:k' or 'rail:i' (indices from 0); a UI words it (docs/i18n.md). */
export function feedAtParam(at: FeedAt): string {
  if (at === 'start' || at === 'end') return at;
  return 'joint' in at ? `joint:${at.joint}` : `rail:${at.end}`;
}

/**
 * The feed positions the catalog allows on a system, in chain order: the start, each connector
 * node once (through its first joint), each free rail end but the last, and the chain end. On a
 * snake: start, connectors 1…n−1, end.
 */
export function allowedFeedPositions(system: LightSystem, catalog: Catalog): FeedAt[] {
  const first = firstNodeJoints(system);
  const nodes = catalog.feed.positions.includes('joints') ? system.joints.flatMap((j, k) => (first[jointParent(j, k)] === k ? [{ joint: k }] : [])) : [];
  const n = system.rails.length;
  const ends = system.rails.flatMap((_, i) => (i < n - 1 && first[i] === undefined ? [{ end: i }] : []));
  return ['start', ...nodes, ...ends, 'end'];
}

/** The drivers by rated power, smallest first (ties by id): the order a driver is picked for a load. */
export function driversBySize(catalog: Catalog): DriverSpec[] {
  return [...catalog.drivers].sort((a, b) => a.capacity - b.capacity || a.id.localeCompare(b.id));
}

/** The driver for a load: the catalog default when it carries it, else the smallest that does; null if none. */
export function driverFor(load: number, catalog: Catalog): DriverSpec | null {
  const preferred = catalog.drivers.find((d) => d.id === catalog.feed.defaultDriver);
  if (preferred && load <= preferred.capacity + LOAD_EPS) return preferred;
  return driversBySize(catalog).find((d) => load <= d.capacity + LOAD_EPS) ?? null;
}

/**
 * Feeds for a system that has none yet (a placed preset, a scene file from before feeds):
 * one feed at the chain start with the catalog's default driver when that carries the
 * whole load; otherwise the smallest driver that does; otherwise n = 2, 3, … feeds spread
 * over the allowed positions (position indices round(i·(P−1)/(n−1)): start and end first,
 * then connectors between), each with the default driver or the smallest that carries its
 * share. When even one feed at every position is not enough, one default feed: validate()
 * then names the overload.
 */
export function plannedFeeds(system: LightSystem, catalog: Catalog): { at: FeedAt; driver: string }[] {
  // A system whose tree is broken (a hostile or corrupt file: joints not one per rail after the first,
  // a bad parent or node) gets the one default feed: validate() refuses the file and names the real
  // problem, and the search below never walks a structure that is not a tree.
  if (system.joints.length !== Math.max(0, system.rails.length - 1) || treeProblem(system, catalog)) return [{ at: 'start', driver: catalog.feed.defaultDriver }];
  // A preset that names its driver (catalog presets[].driver: headroom for the modules a shopper
  // adds next) gets it at the chain start while the system is the preset as shipped (its rails and
  // module counts; a part split off it or an edited file plans as any system) and that one feed
  // carries the load.
  const preset = system.presetId === undefined ? undefined : catalog.presets.find((p) => p.id === system.presetId);
  const shipped = preset?.driver;
  const asShipped = preset !== undefined && preset.rails.length === system.rails.length && preset.rails.every((r, i) => r.modules.length === system.rails[i].modules.length);
  if (shipped !== undefined && asShipped && catalog.drivers.some((d) => d.id === shipped)) {
    const one = feedLoads({ ...system, feeds: [{ id: 'probe', at: 'start', driver: shipped }] }, catalog);
    if (one.length === 1 && !isOverloaded(one[0])) return [{ at: 'start', driver: shipped }];
  }
  const positions = allowedFeedPositions(system, catalog);
  // Fewer feeds than total load / largest driver can never carry the load (some feed would exceed
  // every driver), so the search starts there: the result is the same, and a hostile file with
  // hundreds of rails does not try hundreds of hopeless feed counts (each a feedLoads pass).
  const largest = Math.max(...catalog.drivers.map((d) => d.capacity));
  const chain = chainCoordinates(system, catalog);
  const total = moduleLoads(system, catalog, chain).reduce((sum, m) => sum + m.watts, 0);
  const fewest = Math.max(1, Math.ceil(total / largest - LOAD_EPS));
  for (let n = fewest; n <= positions.length; n++) {
    const chosen = n === 1 ? [positions[0]] : [...new Set(Array.from({ length: n }, (_, i) => Math.round((i * (positions.length - 1)) / (n - 1))))].map((k) => positions[k]);
    const probe: LightSystem = { ...system, feeds: chosen.map((at, i) => ({ id: `probe${i}`, at, driver: catalog.feed.defaultDriver })) };
    const drivers = feedLoads(probe, catalog).map((l) => driverFor(l.load, catalog));
    if (drivers.every((d) => d !== null)) return chosen.map((at, i) => ({ at, driver: drivers[i]!.id }));
  }
  return [{ at: 'start', driver: catalog.feed.defaultDriver }];
}

/**
 * The refusal sentence for a `feed-overload` problem of an action's result, in the shopper's
 * terms: "the 100.8 W driver is full: 96 W used; add a second feed or choose a larger driver"
 * (the feed's load before the action), or, when the feed was not there or already over before,
 * what it would carry. bindDefinition hands it to every action's explain as the problem's message.
 */
export function overloadReason(before: Configuration, after: Configuration, problem: { path: string; message: string }, catalog: Catalog): string {
  return overloadRefusal(before, after, problem, catalog).reason;
}

/** overloadReason with its stable code and parameters ('driverFull' or 'feedOverload'; docs/i18n.md). */
export function overloadRefusal(before: Configuration, after: Configuration, problem: { path: string; message: string }, catalog: Catalog): { reason: string; code?: string; params?: Record<string, string | number> } {
  const m = /^systems\[(\d+)\]\.feeds\[(\d+)\]$/.exec(problem.path);
  const system = m ? after.systems[Number(m[1])] : undefined;
  const feed = system?.feeds[Number(m?.[2])];
  if (!system || !feed) return { reason: problem.message };
  const advice = 'add a second feed or choose a larger driver';
  const now = feedLoads(system, catalog)[Number(m?.[2])];
  const old = before.systems.find((s) => s.id === system.id);
  const oldIndex = old?.feeds.findIndex((f) => f.id === feed.id && f.driver === feed.driver) ?? -1;
  let was: FeedLoad | undefined;
  try {
    was = old && oldIndex >= 0 ? feedLoads(old, catalog)[oldIndex] : undefined;
  } catch {
    was = undefined; // the state before was not sound (a test's raw edit): say what the result would carry
  }
  if (was && !isOverloaded(was) && was.load < now.load) {
    // Name the action that helps: the smallest driver that carries the new load (chosen under
    // Power in the system's options), or, when none does, a second feed.
    const larger = driversBySize(catalog).find((d) => now.load <= d.capacity + LOAD_EPS);
    const params = { capacity: Number(formatWatts(now.capacity)), used: Number(formatWatts(was.load)) };
    if (larger)
      return {
        reason: `the ${formatWatts(now.capacity)} W driver is full: ${formatWatts(was.load)} W used; choose the ${formatWatts(larger.capacity)} W driver in the system options or add a second feed`,
        code: 'driverFull',
        params: { ...params, larger: Number(formatWatts(larger.capacity)) },
      };
    return { reason: `the ${formatWatts(now.capacity)} W driver is full: ${formatWatts(was.load)} W used; add a second feed in the system options`, code: 'driverFullAddFeed', params };
  }
  return {
    reason: `${feedLabel(now.index)} would carry ${formatWatts(now.load)} W, more than its ${formatWatts(now.capacity)} W driver; ${advice}`,
    code: 'feedOverload',
    params: { n: now.index + 1, load: Number(formatWatts(now.load)), capacity: Number(formatWatts(now.capacity)) },
  };
}
