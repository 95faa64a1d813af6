import { isStaleSequence } from './isStaleSequence';
import { mergeUniverse } from './mergeUniverse';
import { DMX_SLOTS, type ArtDmxPacket } from './parseArtDmx';
import type { E131Packet } from './parseE131';

export type DmxProtocol = 'artnet' | 'sacn';

/** Why an otherwise well-formed packet was not used. */
export type StoreIgnoreReason =
  /** 1 to 19 sequence numbers behind the last accepted one (E1.31-2018 §6.7.2, an equal number accepted: isStaleSequence). */
  | 'stale-sequence'
  /** A universe beyond `maxUniverses`. */
  | 'universe-limit'
  /** A source beyond `maxSourcesPerUniverse` for its universe. */
  | 'source-limit';

export const STORE_IGNORE_REASONS: readonly StoreIgnoreReason[] = ['stale-sequence', 'universe-limit', 'source-limit'];

/** Art-Net has no priority; its sources merge as if they sent the E1.31 default (§6.2.3). */
export const ARTNET_PRIORITY = 100;
/** E1.31-2018 §6.7.1: a source is lost after 2.5 s without a packet (network data loss). */
export const SACN_SOURCE_TIMEOUT_MS = 2500;
/** Art-Net 4, ArtDmx merging: a source that sends nothing for 10 s leaves the merge. */
export const ARTNET_SOURCE_TIMEOUT_MS = 10_000;
/**
 * A source none of whose packets was accepted for this long is followed again whatever its
 * sequence number: a sender that restarted a little below its old number, or one that counts
 * backwards, resumes within a second instead of freezing (issue 32). Out-of-order delivery on a
 * network is a matter of milliseconds, far below this.
 */
export const SEQUENCE_RESYNC_MS = 1000;

export interface UniverseStoreOptions {
  sacnTimeoutMs?: number;
  artnetTimeoutMs?: number;
  maxUniverses?: number;
  maxSourcesPerUniverse?: number;
  sequenceResyncMs?: number;
}

export interface DmxSourceInfo {
  protocol: DmxProtocol;
  /** The sender's IP address (and port). */
  address: string;
  /** sACN: the CID (hex); Art-Net: the IP address, which is how Art-Net tells sources apart. */
  id: string;
  /** sACN source name; empty for Art-Net. */
  name: string;
  priority: number;
  universe: number;
  /** Milliseconds since the source's last accepted packet. */
  ageMs: number;
}

export type AcceptResult = { ok: true; universe: number; changed: boolean } | { ok: false; reason: StoreIgnoreReason };

export interface UniverseStore {
  /** Port-Address p becomes luxbox universe p + 1 (Art-Net 0 = sACN 1, docs/dmx.md). */
  acceptArtDmx(packet: ArtDmxPacket, address: string, now: number): AcceptResult;
  acceptE131(packet: E131Packet, address: string, now: number): AcceptResult;
  /** Drops sources past their timeout; returns the universes whose merged levels changed. */
  expire(now: number): number[];
  /** The merged levels of a universe (512 slots), or undefined if it was never seen. */
  get(universe: number): Uint8Array | undefined;
  /** Every universe that has levels, ascending. */
  universes(): number[];
  sources(now: number): DmxSourceInfo[];
}

interface SourceState {
  protocol: DmxProtocol;
  id: string;
  address: string;
  name: string;
  priority: number;
  sequence: number;
  channels: Uint8Array;
  lastSeen: number;
}

interface UniverseState {
  sources: Map<string, SourceState>;
  /** Held after the last source leaves: the last look stays until a source sends again. */
  levels: Uint8Array | null;
}

function sameLevels(a: Uint8Array | null, b: Uint8Array | null): boolean {
  if (a === null || b === null) return a === b;
  for (let i = 0; i < DMX_SLOTS; i++) if (a[i] !== b[i]) return false;
  return true;
}

/** The store's limits and its table of universes, shared by its parts. */
interface StoreCore {
  readonly sacnTimeout: number;
  readonly artnetTimeout: number;
  readonly maxUniverses: number;
  readonly maxSources: number;
  readonly resyncMs: number;
  readonly table: Map<number, UniverseState>;
}

/** Recomputes the merge; returns whether the levels the app sees changed. */
function remerge(state: UniverseState): boolean {
  const merged = mergeUniverse([...state.sources.values()]);
  // No source left: hold the last look rather than black out (E1.31 §6.7.1 leaves it to the receiver).
  if (merged === null || sameLevels(merged, state.levels)) return false;
  state.levels = merged;
  return true;
}

function accept(core: StoreCore, universe: number, key: string, incoming: Omit<SourceState, 'channels' | 'lastSeen'>, data: Uint8Array, terminated: boolean, now: number): AcceptResult {
  let state = core.table.get(universe);
  if (!state) {
    // A terminating packet for a universe we never saw has nothing to end.
    if (terminated) return { ok: true, universe, changed: false };
    if (core.table.size >= core.maxUniverses) return { ok: false, reason: 'universe-limit' };
    state = { sources: new Map(), levels: null };
    core.table.set(universe, state);
  }
  const known = state.sources.get(key);
  if (terminated) {
    // Stream_Terminated (E1.31 §6.2.6): the source leaves at once; its data is not used.
    if (!known) return { ok: true, universe, changed: false };
    state.sources.delete(key);
    return { ok: true, universe, changed: remerge(state) };
  }
  // Art-Net 4 (ArtDmx, Sequence): 0 disables the check; in E1.31 0 is an ordinary sequence number.
  const sequenced = incoming.protocol === 'sacn' || (known?.sequence !== 0 && incoming.sequence !== 0);
  // Written so that a NaN time resynchronises rather than freezing the source.
  const recent = known !== undefined && now - known.lastSeen <= core.resyncMs;
  if (known && sequenced && recent && isStaleSequence(known.sequence, incoming.sequence)) {
    return { ok: false, reason: 'stale-sequence' };
  }
  if (!known && state.sources.size >= core.maxSources) return { ok: false, reason: 'source-limit' };
  const channels = new Uint8Array(DMX_SLOTS);
  channels.set(data.subarray(0, DMX_SLOTS));
  state.sources.set(key, { ...incoming, channels, lastSeen: now });
  return { ok: true, universe, changed: remerge(state) };
}

/** Drops sources past their protocol's timeout; returns the universes whose merged levels changed. */
function expire(core: StoreCore, now: number): number[] {
  const changed: number[] = [];
  for (const [universe, state] of core.table) {
    let dropped = false;
    for (const [key, source] of state.sources) {
      const timeout = source.protocol === 'sacn' ? core.sacnTimeout : core.artnetTimeout;
      if (now - source.lastSeen > timeout) {
        state.sources.delete(key);
        dropped = true;
      }
    }
    if (dropped && remerge(state)) changed.push(universe);
  }
  return changed;
}

function sourcesOf(core: StoreCore, now: number): DmxSourceInfo[] {
  const out: DmxSourceInfo[] = [];
  for (const [universe, state] of core.table) {
    for (const s of state.sources.values()) {
      out.push({ protocol: s.protocol, address: s.address, id: s.id, name: s.name, priority: s.priority, universe, ageMs: now - s.lastSeen });
    }
  }
  return out.sort((a, b) => a.universe - b.universe || a.id.localeCompare(b.id));
}

/** Per-universe, per-source state and the merge; pure (time is passed in), so it is tested without sockets. */
export function createUniverseStore(options: UniverseStoreOptions = {}): UniverseStore {
  const core: StoreCore = {
    sacnTimeout: options.sacnTimeoutMs ?? SACN_SOURCE_TIMEOUT_MS,
    artnetTimeout: options.artnetTimeoutMs ?? ARTNET_SOURCE_TIMEOUT_MS,
    maxUniverses: options.maxUniverses ?? 512,
    maxSources: options.maxSourcesPerUniverse ?? 16,
    resyncMs: options.sequenceResyncMs ?? SEQUENCE_RESYNC_MS,
    table: new Map(),
  };
  return {
    acceptArtDmx(packet, address, now) {
      const ip = address.replace(/:\d+$/, '');
      return accept(core, packet.portAddress + 1, `artnet:${ip}`, { protocol: 'artnet', id: ip, address, name: '', priority: ARTNET_PRIORITY, sequence: packet.sequence }, packet.data, false, now);
    },
    acceptE131(packet, address, now) {
      return accept(core, packet.universe, `sacn:${packet.cid}`, { protocol: 'sacn', id: packet.cid, address, name: packet.sourceName, priority: packet.priority, sequence: packet.sequence }, packet.data, packet.terminated, now);
    },
    expire: (now) => expire(core, now),
    get(universe) {
      return core.table.get(universe)?.levels ?? undefined;
    },
    universes() {
      return [...core.table]
        .filter(([, s]) => s.levels !== null)
        .map(([u]) => u)
        .sort((a, b) => a - b);
    },
    sources: (now) => sourcesOf(core, now),
  };
}
