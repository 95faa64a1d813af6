import type { DmxBridgeStatus } from './dmxBridge';
import { ignoredSummary, type Counters } from './protocolCounters';

/** The bridge's status line: packets per second per protocol, sources, universes, clients, what was ignored and why. */
export function dmxStatusLine(s: DmxBridgeStatus, artnet: Counters<string> | null, sacn: Counters<string> | null): string {
  return (
    `dmx: ` +
    (artnet ? `Art-Net ${artnet.perSecond} pkt/s, ` : '') +
    (sacn ? `sACN ${sacn.perSecond} pkt/s, ` : '') +
    `${s.sources.length} source${s.sources.length === 1 ? '' : 's'}, universes ${s.universes.length ? s.universes.join(',') : 'none'}, ` +
    `${s.clients} client${s.clients === 1 ? '' : 's'}, ignored ` +
    (artnet ? `Art-Net ${ignoredSummary(artnet.ignored)}` : '') +
    (artnet && sacn ? '; ' : '') +
    (sacn ? `sACN ${ignoredSummary(sacn.ignored)}` : '')
  );
}
