import type { DmxSourceInfo } from './createUniverseStore';
import type { DmxSourceStatus } from './dmxBridge';

/** The store's sources per universe, one per sending device with all its universes (its highest priority, its newest packet). */
export function groupSources(perUniverse: readonly DmxSourceInfo[]): DmxSourceStatus[] {
  const byId = new Map<string, DmxSourceStatus>();
  for (const s of perUniverse) {
    const key = `${s.protocol}:${s.id}`;
    const known = byId.get(key);
    if (!known) {
      byId.set(key, { protocol: s.protocol, id: s.id, address: s.address, name: s.name, priority: s.priority, universes: [s.universe], ageMs: s.ageMs });
    } else {
      known.universes.push(s.universe);
      known.priority = Math.max(known.priority, s.priority);
      known.ageMs = Math.min(known.ageMs, s.ageMs);
    }
  }
  return [...byId.values()];
}
