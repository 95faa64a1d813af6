import { STORE_IGNORE_REASONS, type StoreIgnoreReason } from './createUniverseStore';
import type { ProtocolStatus } from './dmxBridge';

/** Datagrams per protocol: received, accepted, per second, ignored by reason. */
export interface Counters<R extends string> {
  packets: number;
  accepted: number;
  lastPackets: number;
  perSecond: number;
  ignored: Record<R | StoreIgnoreReason, number>;
}

/** Zeroed counters with every reason a datagram can be ignored for (the parser's and the store's). */
export function counters<R extends string>(reasons: readonly R[]): Counters<R> {
  const ignored = {} as Record<R | StoreIgnoreReason, number>;
  for (const r of [...reasons, ...STORE_IGNORE_REASONS]) ignored[r] = 0;
  return { packets: 0, accepted: 0, lastPackets: 0, perSecond: 0, ignored };
}

/** 'reason n, …' for the reasons that occurred, or '0'. */
export function ignoredSummary(ignored: Record<string, number>): string {
  const parts = Object.entries(ignored)
    .filter(([, n]) => n > 0)
    .map(([r, n]) => `${r} ${n}`);
  return parts.length ? parts.join(', ') : '0';
}

/** A protocol's counters as the status reports them. */
export function protocolStatus(enabled: boolean, c: Counters<string>): ProtocolStatus {
  return { enabled, packets: c.packets, accepted: c.accepted, packetsPerSecond: c.perSecond, ignored: { ...c.ignored } };
}

/** Packets per second over the last status interval. */
export function countPerSecond(c: Counters<string>, intervalMs: number): void {
  c.perSecond = Math.round(((c.packets - c.lastPackets) * 1000) / intervalMs);
  c.lastPackets = c.packets;
}
