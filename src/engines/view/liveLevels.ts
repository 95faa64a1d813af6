/**
 * Live control (docs/live-control.md): what the console's DMX frames say about
 * each patched module. Pure: the latest frame per universe in, a level (and a
 * CCT for tunable modules with a CCT channel) per module out; modules that are
 * not patched, or whose universe has sent nothing yet, are left out and keep
 * the configuration's own dimming.
 */
import { findModuleType, type Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import { cctChannelValue, cctFromChannel, decodeLevel, patchedModules } from '../../core/model/modules/dmxPatch';

export interface LiveLevel {
  /** 0..1, replaces the module's dimming while live control is on. */
  readonly dimming: number;
  /** Kelvin from the CCT channel, or null (no CCT channel: the module's own CCT). */
  readonly cct: number | null;
}

/** The latest 512 channel values (0–255) per universe. */
export type DmxFrames = ReadonlyMap<number, ArrayLike<number>>;

export function levelsFromFrames(config: Configuration, catalog: Catalog, frames: DmxFrames): Map<string, LiveLevel> {
  const out = new Map<string, LiveLevel>();
  for (const { module, patch } of patchedModules(config)) {
    const channels = frames.get(patch.universe);
    if (!channels) continue;
    const value = cctChannelValue(channels, patch);
    out.set(module.id, { dimming: decodeLevel(channels, patch), cct: value === null ? null : cctFromChannel(value, findModuleType(catalog, module.type)) });
  }
  return out;
}

/** Whether two level sets are the same (a console repeats unchanged frames ~40 times a second: those need no relight). */
export function sameLevels(a: ReadonlyMap<string, LiveLevel> | null, b: ReadonlyMap<string, LiveLevel> | null): boolean {
  if (a === b) return true;
  if (!a || !b || a.size !== b.size) return false;
  for (const [id, x] of a) {
    const y = b.get(id);
    if (!y || y.dimming !== x.dimming || y.cct !== x.cct) return false;
  }
  return true;
}
