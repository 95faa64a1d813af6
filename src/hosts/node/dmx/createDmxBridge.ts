import { createSocket, type RemoteInfo, type Socket } from 'node:dgram';
import { WebSocketServer, type WebSocket } from 'ws';
import { createFrameQueue, type FrameQueue } from './createFrameQueue';
import { ARTNET_SOURCE_TIMEOUT_MS, createUniverseStore, SACN_SOURCE_TIMEOUT_MS, STORE_IGNORE_REASONS, type DmxProtocol, type DmxSourceInfo, type StoreIgnoreReason, type UniverseStoreOptions } from './createUniverseStore';
import { ARTNET_IGNORE_REASONS, parseArtDmx, type ArtNetIgnoreReason } from './parseArtDmx';
import { parseE131, SACN_IGNORE_REASONS, type SacnIgnoreReason } from './parseE131';
import { sacnMulticastGroup } from './sacnMulticastGroup';

export const ARTNET_PORT = 6454;
export const SACN_PORT = 5568;
export const DMX_WS_PORT = 9090;

export interface DmxBridgeOptions extends UniverseStoreOptions {
  /** Receive Art-Net (default true). */
  artnet?: boolean;
  /** Receive sACN / E1.31 (default true). */
  sacn?: boolean;
  /** UDP port for Art-Net (default 6454, Art-Net 4); 0 picks a free one. */
  artnetPort?: number;
  /** UDP port for sACN (default 5568, E1.31-2018 §9.3.1); 0 picks a free one. */
  sacnPort?: number;
  /** The WebSocket port on 127.0.0.1 (default 9090); 0 picks a free one. */
  wsPort?: number;
  /** Address the UDP sockets listen on (default 0.0.0.0: every interface, broadcast and multicast). */
  bind?: string;
  /** sACN universes whose multicast group 239.255.hi.lo is joined (default [1]). */
  universes?: readonly number[];
  /** A client whose socket holds this many unsent bytes gets only the newest frame per universe (default 64 KiB). */
  highWaterBytes?: number;
  /** At most one status line per this many milliseconds (default 1000). */
  statusIntervalMs?: number;
  /** Where status lines and warnings go (default: stderr). */
  log?: (line: string) => void;
  /** Clock in milliseconds (default Date.now); tests keep the real one. */
  now?: () => number;
}

export interface DmxBridgeAddress {
  artnet: { address: string; port: number } | null;
  sacn: { address: string; port: number; multicast: string[] } | null;
  ws: { address: string; port: number; url: string };
}

export interface ProtocolStatus {
  enabled: boolean;
  /** Datagrams received; always accepted + the sum of ignored. */
  packets: number;
  accepted: number;
  packetsPerSecond: number;
  ignored: Record<string, number>;
}

/** One sending device: an sACN CID or an Art-Net IP address, with every universe it sends. */
export interface DmxSourceStatus {
  protocol: DmxProtocol;
  id: string;
  address: string;
  name: string;
  /** Its highest priority over its universes (Art-Net: 100). */
  priority: number;
  universes: number[];
  /** Milliseconds since its last accepted packet, any universe. */
  ageMs: number;
}

export interface DmxBridgeStatus {
  type: 'status';
  uptimeS: number;
  artnet: ProtocolStatus;
  sacn: ProtocolStatus & { multicast: string[] };
  sources: DmxSourceStatus[];
  universes: number[];
  clients: number;
  /** Frames replaced by a newer one before a slow client could take them. */
  coalesced: number;
  ws: string;
}

export interface DmxBridge {
  address(): DmxBridgeAddress;
  status(): DmxBridgeStatus;
  /** Closes the UDP sockets, the clients and the WebSocket server. */
  close(): Promise<void>;
}

/** A socket could not be opened (port in use, address not local): bad input, not a bug. */
export class DmxBridgeStartError extends Error {
  override name = 'DmxBridgeStartError';
}

interface Counters<R extends string> {
  packets: number;
  accepted: number;
  lastPackets: number;
  perSecond: number;
  ignored: Record<R | StoreIgnoreReason, number>;
}

function counters<R extends string>(reasons: readonly R[]): Counters<R> {
  const ignored = {} as Record<R | StoreIgnoreReason, number>;
  for (const r of [...reasons, ...STORE_IGNORE_REASONS]) ignored[r] = 0;
  return { packets: 0, accepted: 0, lastPackets: 0, perSecond: 0, ignored };
}

function bindUdp(port: number, address: string, label: string): Promise<Socket> {
  return new Promise((resolve, reject) => {
    // No reuseAddr: with SO_REUSEADDR a second program on the port silently takes the unicast
    // traffic; a clear "in use" error is better.
    const socket = createSocket({ type: 'udp4' });
    const onError = (error: NodeJS.ErrnoException) => {
      socket.close();
      reject(new DmxBridgeStartError(`${label}: cannot listen on udp ${address}:${port} (${error.code === 'EADDRINUSE' ? 'port in use by another program' : (error.code ?? error.message)})`));
    };
    socket.once('error', onError);
    socket.bind(port, address, () => {
      socket.off('error', onError);
      resolve(socket);
    });
  });
}

function listenWs(port: number, host: string): Promise<WebSocketServer> {
  return new Promise((resolve, reject) => {
    // Incoming messages are only ever the word "status": a tiny maxPayload keeps a client from
    // making the bridge buffer large frames.
    const server = new WebSocketServer({ host, port, maxPayload: 1024, perMessageDeflate: false });
    const onError = (error: NodeJS.ErrnoException) => {
      server.close();
      reject(new DmxBridgeStartError(`WebSocket: cannot listen on ${host}:${port} (${error.code === 'EADDRINUSE' ? 'port in use by another program' : (error.code ?? error.message)})`));
    };
    server.once('error', onError);
    server.once('listening', () => {
      server.off('error', onError);
      resolve(server);
    });
  });
}

function groupSources(perUniverse: readonly DmxSourceInfo[]): DmxSourceStatus[] {
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

function ignoredSummary(ignored: Record<string, number>): string {
  const parts = Object.entries(ignored)
    .filter(([, n]) => n > 0)
    .map(([r, n]) => `${r} ${n}`);
  return parts.length ? parts.join(', ') : '0';
}

/**
 * The DMX bridge (docs/dmx.md): Art-Net and sACN in over UDP, the merged universes out to the app
 * over a WebSocket on localhost. Every datagram is either used or counted as ignored with a reason.
 */
export async function createDmxBridge(options: DmxBridgeOptions = {}): Promise<DmxBridge> {
  const useArtnet = options.artnet ?? true;
  const useSacn = options.sacn ?? true;
  const bind = options.bind ?? '0.0.0.0';
  const now = options.now ?? Date.now;
  const log = options.log ?? ((line: string) => void process.stderr.write(line + '\n'));
  const highWater = options.highWaterBytes ?? 64 * 1024;
  const statusInterval = options.statusIntervalMs ?? 1000;
  const started = now();
  const store = createUniverseStore(options);
  const artnet = counters<ArtNetIgnoreReason>(ARTNET_IGNORE_REASONS);
  const sacn = counters<SacnIgnoreReason>(SACN_IGNORE_REASONS);
  const clients = new Map<WebSocket, FrameQueue>();
  let coalescedByGone = 0;
  const multicast: string[] = [];

  const opened: Socket[] = [];
  let artnetSocket: Socket | null = null;
  let sacnSocket: Socket | null = null;
  let wss: WebSocketServer;
  try {
    if (useArtnet) opened.push((artnetSocket = await bindUdp(options.artnetPort ?? ARTNET_PORT, bind, 'Art-Net')));
    if (useSacn) opened.push((sacnSocket = await bindUdp(options.sacnPort ?? SACN_PORT, bind, 'sACN')));
    wss = await listenWs(options.wsPort ?? DMX_WS_PORT, '127.0.0.1');
  } catch (error) {
    for (const s of opened) s.close();
    throw error;
  }

  function frameText(universe: number, levels: Uint8Array): string {
    return JSON.stringify({ universe, channels: Array.from(levels) });
  }

  function broadcast(universe: number): void {
    const levels = store.get(universe);
    if (!levels || clients.size === 0) return;
    const text = frameText(universe, levels);
    for (const queue of clients.values()) queue.push(universe, text);
  }

  function onDatagram(protocol: DmxProtocol, msg: Buffer, from: RemoteInfo): void {
    // Whatever the bytes, this handler must not throw (a throw in a 'message' listener ends the
    // process): the parsers and the store never throw, which tests/hosts/node/dmx/fuzz.test.ts checks.
    const c: Counters<string> = protocol === 'artnet' ? artnet : sacn;
    c.packets++;
    const address = `${from.address}:${from.port}`;
    const t = now();
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
      return;
    }
    c.accepted++;
    if (result.changed) broadcast(result.universe);
  }

  if (artnetSocket) {
    artnetSocket.on('message', (msg, from) => onDatagram('artnet', msg, from));
    artnetSocket.on('error', (error) => log(`dmx: Art-Net socket: ${error.message}`));
  }
  if (sacnSocket) {
    sacnSocket.on('message', (msg, from) => onDatagram('sacn', msg, from));
    sacnSocket.on('error', (error) => log(`dmx: sACN socket: ${error.message}`));
    // E1.31-2018 §9.3.1: each universe is multicast to 239.255.hi.lo; unicast needs no join.
    for (const universe of options.universes ?? [1]) {
      const group = sacnMulticastGroup(universe);
      try {
        sacnSocket.addMembership(group, bind === '0.0.0.0' ? undefined : bind);
        multicast.push(group);
      } catch (error) {
        log(`dmx: sACN: cannot join multicast group ${group} for universe ${universe} (${(error as Error).message}); unicast still works`);
      }
    }
  }
  for (const s of opened) {
    // Consoles send bursts (one packet per universe per frame); a larger buffer loses fewer.
    try {
      s.setRecvBufferSize(1 << 20);
    } catch {
      // Capped by the OS (net.core.rmem_max): the default buffer still works.
    }
  }

  const wsAddress = wss.address() as { address: string; port: number };

  function status(): DmxBridgeStatus {
    const t = now();
    const protocolStatus = (enabled: boolean, c: Counters<string>): ProtocolStatus => ({
      enabled,
      packets: c.packets,
      accepted: c.accepted,
      packetsPerSecond: c.perSecond,
      ignored: { ...c.ignored },
    });
    let coalesced = coalescedByGone;
    for (const q of clients.values()) coalesced += q.coalesced();
    return {
      type: 'status',
      uptimeS: Math.round((t - started) / 100) / 10,
      artnet: protocolStatus(useArtnet, artnet),
      sacn: { ...protocolStatus(useSacn, sacn), multicast: [...multicast] },
      sources: groupSources(store.sources(t)),
      universes: store.universes(),
      clients: clients.size,
      coalesced,
      ws: `ws://127.0.0.1:${wsAddress.port}`,
    };
  }

  wss.on('connection', (ws) => {
    const queue = createFrameQueue(
      {
        send: (text, done) => ws.send(text, done),
        bufferedAmount: () => ws.bufferedAmount,
        isOpen: () => ws.readyState === ws.OPEN,
      },
      highWater,
    );
    clients.set(ws, queue);
    // A client that connects gets every known universe at once.
    for (const universe of store.universes()) queue.push(universe, frameText(universe, store.get(universe)!));
    ws.on('message', (data, isBinary) => {
      if (!isBinary && data.toString() === 'status' && ws.readyState === ws.OPEN) ws.send(JSON.stringify(status()));
    });
    ws.on('error', () => {
      // A broken client (bad frame, over maxPayload) is closed by ws; nothing to do for the others.
    });
    ws.on('close', () => {
      coalescedByGone += queue.coalesced();
      clients.delete(ws);
    });
  });
  wss.on('error', (error) => log(`dmx: WebSocket server: ${error.message}`));

  // Source loss (E1.31-2018 §6.7.1): checked often enough that a source leaves within a fifth of its timeout.
  const shortestTimeout = Math.min(options.sacnTimeoutMs ?? SACN_SOURCE_TIMEOUT_MS, options.artnetTimeoutMs ?? ARTNET_SOURCE_TIMEOUT_MS);
  const expireTimer = setInterval(
    () => {
      for (const universe of store.expire(now())) broadcast(universe);
    },
    Math.max(10, Math.min(500, shortestTimeout / 5)),
  );

  let lastLine = '';
  const statusTimer = setInterval(() => {
    for (const c of [artnet, sacn]) {
      c.perSecond = Math.round(((c.packets - c.lastPackets) * 1000) / statusInterval);
      c.lastPackets = c.packets;
    }
    const s = status();
    const line =
      `dmx: ` +
      (useArtnet ? `Art-Net ${artnet.perSecond} pkt/s, ` : '') +
      (useSacn ? `sACN ${sacn.perSecond} pkt/s, ` : '') +
      `${s.sources.length} source${s.sources.length === 1 ? '' : 's'}, universes ${s.universes.length ? s.universes.join(',') : 'none'}, ` +
      `${s.clients} client${s.clients === 1 ? '' : 's'}, ignored ` +
      (useArtnet ? `Art-Net ${ignoredSummary(artnet.ignored)}` : '') +
      (useArtnet && useSacn ? '; ' : '') +
      (useSacn ? `sACN ${ignoredSummary(sacn.ignored)}` : '');
    // Quiet while nothing happens: a line only when the picture changed or packets are flowing.
    if (line !== lastLine || artnet.perSecond > 0 || sacn.perSecond > 0) log(line);
    lastLine = line;
  }, statusInterval);

  let closing: Promise<void> | null = null;
  return {
    address: () => ({
      artnet: artnetSocket ? artnetSocket.address() : null,
      sacn: sacnSocket ? { ...sacnSocket.address(), multicast: [...multicast] } : null,
      ws: { address: wsAddress.address, port: wsAddress.port, url: `ws://127.0.0.1:${wsAddress.port}` },
    }),
    status,
    close() {
      closing ??= (async () => {
        clearInterval(expireTimer);
        clearInterval(statusTimer);
        await Promise.all(opened.map((s) => new Promise<void>((resolve) => s.close(() => resolve()))));
        // A clean close handshake (1001 "going away"), but a client that does not answer within
        // half a second is cut off: Ctrl-C must not hang on a stalled browser tab.
        const sockets = [...clients.keys()];
        await Promise.all(
          sockets.map(
            (ws) =>
              new Promise<void>((resolve) => {
                if (ws.readyState === ws.CLOSED) return resolve();
                const timer = setTimeout(() => ws.terminate(), 500);
                ws.once('close', () => {
                  clearTimeout(timer);
                  resolve();
                });
                ws.close(1001, 'bridge closing');
              }),
          ),
        );
        await new Promise<void>((resolve) => wss.close(() => resolve()));
      })();
      return closing;
    },
  };
}
