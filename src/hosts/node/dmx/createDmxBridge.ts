import type { RemoteInfo, Socket } from 'node:dgram';
import { ARTNET_SOURCE_TIMEOUT_MS, createUniverseStore, SACN_SOURCE_TIMEOUT_MS, type DmxProtocol, type UniverseStore } from './createUniverseStore';
import type { DmxBridge, DmxBridgeAddress, DmxBridgeOptions, DmxBridgeStatus } from './dmxBridge';
import { dmxStatusLine } from './dmxStatusLine';
import { groupSources } from './groupSources';
import { openDmxSockets } from './openDmxSockets';
import { ARTNET_IGNORE_REASONS, parseArtDmx, type ArtNetIgnoreReason } from './parseArtDmx';
import { parseE131, SACN_IGNORE_REASONS, type SacnIgnoreReason } from './parseE131';
import { countPerSecond, counters, protocolStatus, type Counters } from './protocolCounters';
import { closeDmxClients, serveDmxClients } from './serveDmxClients';
import { enlargeReceiveBuffers, joinSacnMulticast } from './tuneUdpSockets';

export type { DmxBridge, DmxBridgeAddress, DmxBridgeOptions, DmxBridgeStatus, DmxSourceStatus, ProtocolStatus } from './dmxBridge';
export { DmxBridgeStartError } from './dmxBridgeStartError';
export { ARTNET_PORT, DMX_WS_PORT, SACN_PORT } from './openDmxSockets';

/** One datagram into the store: used (a changed universe is returned) or counted as ignored with its reason. Never throws. */
function acceptDatagram(store: UniverseStore, protocol: DmxProtocol, c: Counters<string>, msg: Buffer, from: RemoteInfo, t: number): number | null {
  // Whatever the bytes, this must not throw (a throw in a 'message' listener ends the process):
  // the parsers and the store never throw, which tests/hosts/node/dmx/fuzz.test.ts checks.
  c.packets++;
  const address = `${from.address}:${from.port}`;
  let result;
  if (protocol === 'artnet') {
    const parsed = parseArtDmx(msg);
    result = parsed.ok ? store.acceptArtDmx(parsed.packet, address, t) : parsed;
  } else {
    const parsed = parseE131(msg);
    result = parsed.ok ? store.acceptE131(parsed.packet, address, t) : parsed;
  }
  if (!result.ok) {
    c.ignored[result.reason]++;
    return null;
  }
  c.accepted++;
  return result.changed ? result.universe : null;
}

/** Where the bridge listens: its UDP sockets (sACN with the multicast groups joined) and the WebSocket's URL. */
function bridgeAddress(artnet: Socket | null, sacn: Socket | null, multicast: readonly string[], ws: { address: string; port: number }): DmxBridgeAddress {
  return {
    artnet: artnet ? artnet.address() : null,
    sacn: sacn ? { ...sacn.address(), multicast: [...multicast] } : null,
    ws: { address: ws.address, port: ws.port, url: `ws://127.0.0.1:${ws.port}` },
  };
}

function frameText(universe: number, levels: Uint8Array): string {
  return JSON.stringify({ universe, channels: Array.from(levels) });
}

/**
 * The DMX bridge (docs/dmx.md): Art-Net and sACN in over UDP, the merged universes out to the app
 * over a WebSocket on localhost. Every datagram is either used or counted as ignored with a reason.
 */
export async function createDmxBridge(options: DmxBridgeOptions = {}): Promise<DmxBridge> {
  const [useArtnet, useSacn] = [options.artnet ?? true, options.sacn ?? true];
  const bind = options.bind ?? '0.0.0.0';
  const now = options.now ?? Date.now;
  const log = options.log ?? ((line: string) => void process.stderr.write(line + '\n'));
  const statusInterval = options.statusIntervalMs ?? 1000;
  const started = now();
  const store = createUniverseStore(options);
  const artnet = counters<ArtNetIgnoreReason>(ARTNET_IGNORE_REASONS);
  const sacn = counters<SacnIgnoreReason>(SACN_IGNORE_REASONS);
  const { artnet: artnetSocket, sacn: sacnSocket, opened, wss } = await openDmxSockets(options, bind);
  const multicast: string[] = [];

  const broadcast = (universe: number): void => {
    const levels = store.get(universe);
    if (!levels || clients.queues.size === 0) return;
    const text = frameText(universe, levels);
    for (const queue of clients.queues.values()) queue.push(universe, text);
  };
  const onDatagram = (protocol: DmxProtocol, msg: Buffer, from: RemoteInfo): void => {
    const changed = acceptDatagram(store, protocol, protocol === 'artnet' ? artnet : sacn, msg, from, now());
    if (changed !== null) broadcast(changed);
  };
  artnetSocket?.on('message', (msg, from) => onDatagram('artnet', msg, from));
  artnetSocket?.on('error', (error) => log(`dmx: Art-Net socket: ${error.message}`));
  sacnSocket?.on('message', (msg, from) => onDatagram('sacn', msg, from));
  sacnSocket?.on('error', (error) => log(`dmx: sACN socket: ${error.message}`));
  if (sacnSocket) multicast.push(...joinSacnMulticast(sacnSocket, options.universes ?? [1], bind, log));
  enlargeReceiveBuffers(opened);

  const wsAddress = wss.address() as { address: string; port: number };
  const status = (): DmxBridgeStatus => {
    const t = now();
    return {
      type: 'status',
      uptimeS: Math.round((t - started) / 100) / 10,
      artnet: protocolStatus(useArtnet, artnet),
      sacn: { ...protocolStatus(useSacn, sacn), multicast: [...multicast] },
      sources: groupSources(store.sources(t)),
      universes: store.universes(),
      clients: clients.queues.size,
      coalesced: clients.coalesced(),
      ws: `ws://127.0.0.1:${wsAddress.port}`,
    };
  };
  // A client that connects gets every known universe at once.
  const clients = serveDmxClients(wss, options.highWaterBytes ?? 64 * 1024, (queue) => store.universes().forEach((u) => queue.push(u, frameText(u, store.get(u)!))), status);
  wss.on('error', (error) => log(`dmx: WebSocket server: ${error.message}`));

  // Source loss (E1.31-2018 §6.7.1): checked often enough that a source leaves within a fifth of its timeout.
  const shortestTimeout = Math.min(options.sacnTimeoutMs ?? SACN_SOURCE_TIMEOUT_MS, options.artnetTimeoutMs ?? ARTNET_SOURCE_TIMEOUT_MS);
  const expireTimer = setInterval(() => store.expire(now()).forEach(broadcast), Math.max(10, Math.min(500, shortestTimeout / 5)));
  let lastLine = '';
  const statusTimer = setInterval(() => {
    for (const c of [artnet, sacn]) countPerSecond(c, statusInterval);
    const line = dmxStatusLine(status(), useArtnet ? artnet : null, useSacn ? sacn : null);
    // Quiet while nothing happens: a line only when the picture changed or packets are flowing.
    if (line !== lastLine || artnet.perSecond > 0 || sacn.perSecond > 0) log(line);
    lastLine = line;
  }, statusInterval);

  let closing: Promise<void> | null = null;
  return {
    address: () => bridgeAddress(artnetSocket, sacnSocket, multicast, wsAddress),
    status,
    close() {
      closing ??= (async () => {
        clearInterval(expireTimer);
        clearInterval(statusTimer);
        await Promise.all(opened.map((s) => new Promise<void>((resolve) => s.close(() => resolve()))));
        await closeDmxClients([...clients.queues.keys()]);
        await new Promise<void>((resolve) => wss.close(() => resolve()));
      })();
      return closing;
    },
  };
}
