/**
 * Finding and replacing parts of an immutable configuration by id. Unknown ids
 * throw InputError (the caller passed a stale or foreign id).
 */
import { InputError } from '../../inputError';
import type { Configuration, Feed, LightSystem, ModuleInstance, Rail } from '../configuration/configuration';

export interface RailRef {
  readonly systemIndex: number;
  readonly railIndex: number;
  readonly system: LightSystem;
  readonly rail: Rail;
}

export interface ModuleRef extends RailRef {
  readonly moduleIndex: number;
  readonly module: ModuleInstance;
}

export function systemIndex(config: Configuration, systemId: string): number {
  const i = config.systems.findIndex((s) => s.id === systemId);
  if (i < 0) throw new InputError(`no system with id '${systemId}'`, { code: 'unknownSystem', params: { id: systemId } });
  return i;
}

export function findRail(config: Configuration, railId: string): RailRef {
  for (let s = 0; s < config.systems.length; s++) {
    const system = config.systems[s];
    const r = system.rails.findIndex((x) => x.id === railId);
    if (r >= 0) return { systemIndex: s, railIndex: r, system, rail: system.rails[r] };
  }
  throw new InputError(`no rail with id '${railId}'`, { code: 'unknownRail', params: { id: railId } });
}

export function findModule(config: Configuration, moduleId: string): ModuleRef {
  for (let s = 0; s < config.systems.length; s++) {
    const system = config.systems[s];
    for (let r = 0; r < system.rails.length; r++) {
      const rail = system.rails[r];
      const m = rail.modules.findIndex((x) => x.id === moduleId);
      if (m >= 0) return { systemIndex: s, railIndex: r, system, rail, moduleIndex: m, module: rail.modules[m] };
    }
  }
  throw new InputError(`no module with id '${moduleId}'`, { code: 'unknownModule', params: { id: moduleId } });
}

export interface FeedRef {
  readonly systemIndex: number;
  readonly feedIndex: number;
  readonly system: LightSystem;
  readonly feed: Feed;
}

export function findFeed(config: Configuration, feedId: string): FeedRef {
  for (let s = 0; s < config.systems.length; s++) {
    const system = config.systems[s];
    const f = system.feeds.findIndex((x) => x.id === feedId);
    if (f >= 0) return { systemIndex: s, feedIndex: f, system, feed: system.feeds[f] };
  }
  throw new InputError(`no feed with id '${feedId}'`, { code: 'unknownFeed', params: { id: feedId } });
}

export function replaceSystem(config: Configuration, index: number, system: LightSystem): Configuration {
  return { ...config, systems: config.systems.map((s, i) => (i === index ? system : s)) };
}

export function replaceRail(config: Configuration, ref: { systemIndex: number; railIndex: number }, rail: Rail): Configuration {
  const system = config.systems[ref.systemIndex];
  return replaceSystem(config, ref.systemIndex, { ...system, rails: system.rails.map((r, i) => (i === ref.railIndex ? rail : r)) });
}

/** The configuration with one system's fields replaced (by id). */
export function updateSystem(config: Configuration, systemId: string, patch: Partial<LightSystem>): Configuration {
  const i = systemIndex(config, systemId);
  return replaceSystem(config, i, { ...config.systems[i], ...patch });
}

/** The configuration with one rail's fields replaced (by id). */
export function updateRail(config: Configuration, railId: string, patch: Partial<Rail>): Configuration {
  const ref = findRail(config, railId);
  return replaceRail(config, ref, { ...ref.rail, ...patch });
}

/** The configuration with one module's fields replaced (by id). */
export function updateModule(config: Configuration, moduleId: string, patch: Partial<ModuleInstance>): Configuration {
  const ref = findModule(config, moduleId);
  const m = { ...ref.module, ...patch };
  return replaceRail(config, ref, { ...ref.rail, modules: ref.rail.modules.map((x, i) => (i === ref.moduleIndex ? m : x)) });
}

/** A fresh id with the given one-letter prefix and the configuration with its counter advanced. */
export function takeId(config: Configuration, prefix: 's' | 'r' | 'm' | 'o' | 'i' | 'f' | 'q'): [string, Configuration] {
  return [`${prefix}${config.nextId}`, { ...config, nextId: config.nextId + 1 }];
}
