import type { DmxProtocol, UniverseStoreOptions } from './createUniverseStore';

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
