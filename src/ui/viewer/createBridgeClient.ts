/**
 * The WebSocket client of the DMX bridge (`luxbox dmx`, docs/dmx.md): frames
 * `{ universe, channels }` in, the word "status" out (answered with
 * `{ type: 'status', … }`). It reconnects every few seconds when there is no
 * bridge or the bridge went away, and says which of the two it is, so the
 * view can keep the last look and tell the user why it is frozen.
 */

export type BridgeState =
  | { readonly kind: 'connecting' }
  | { readonly kind: 'connected'; readonly status: BridgeSummary | null }
  /** Never reached the bridge (not started, wrong port); retrying. */
  | { readonly kind: 'no-bridge' }
  /** Was connected, the connection closed; retrying. */
  | { readonly kind: 'lost' };

/** The parts of the bridge's status line the panel shows. */
export interface BridgeSummary {
  readonly universes: readonly number[];
  readonly sources: number;
  readonly protocols: readonly string[];
}

/** What the client needs of a WebSocket (the browser's, or a test's stand-in). */
export interface SocketLike {
  onopen: ((ev: unknown) => void) | null;
  onclose: ((ev: unknown) => void) | null;
  onerror: ((ev: unknown) => void) | null;
  onmessage: ((ev: { data: unknown }) => void) | null;
  send(data: string): void;
  close(): void;
}

export interface BridgeClientOptions {
  readonly url: string;
  onState(state: BridgeState): void;
  /** A universe's 512 channel values (0–255), as sent; called for every frame (the caller keeps the latest). */
  onFrame(universe: number, channels: readonly number[]): void;
  /** Seconds between reconnection attempts (default 3). */
  readonly retryS?: number;
  /** How often the status is asked for while connected, seconds (default 2). */
  readonly statusS?: number;
  readonly createSocket?: (url: string) => SocketLike;
  readonly setTimer?: (f: () => void, ms: number) => unknown;
  readonly clearTimer?: (handle: unknown) => void;
}

export const BRIDGE_RETRY_S = 3;

export interface BridgeClient {
  close(): void;
}

/** A frame message, or null when the message is something else (status, junk: ignored). */
export function parseFrame(data: unknown): { universe: number; channels: number[] } | null {
  if (typeof data !== 'object' || data === null) return null;
  const { universe, channels } = data as Record<string, unknown>;
  if (typeof universe !== 'number' || !Number.isInteger(universe) || universe < 0) return null;
  if (!Array.isArray(channels) || channels.length > 512 || !channels.every((v) => typeof v === 'number')) return null;
  return { universe, channels: channels as number[] };
}

/** The summary of a status message, or null when it is not one. */
export function parseStatus(data: unknown): BridgeSummary | null {
  if (typeof data !== 'object' || data === null || (data as Record<string, unknown>).type !== 'status') return null;
  const d = data as Record<string, unknown>;
  const universes = Array.isArray(d.universes) ? d.universes.filter((u): u is number => typeof u === 'number') : [];
  const sources = Array.isArray(d.sources) ? d.sources.length : 0;
  const on = (key: string) => typeof d[key] === 'object' && d[key] !== null && (d[key] as Record<string, unknown>).enabled !== false;
  const protocols = [on('sacn') ? 'sACN' : null, on('artnet') ? 'Art-Net' : null].filter((p): p is string => p !== null);
  return { universes, sources, protocols };
}

export function createBridgeClient(options: BridgeClientOptions): BridgeClient {
  const createSocket = options.createSocket ?? ((url: string) => new WebSocket(url) as unknown as SocketLike);
  const setTimer = options.setTimer ?? ((f, ms) => setTimeout(f, ms));
  const clearTimer = options.clearTimer ?? ((h) => clearTimeout(h as ReturnType<typeof setTimeout>));
  const retryMs = (options.retryS ?? BRIDGE_RETRY_S) * 1000;
  const statusMs = (options.statusS ?? 2) * 1000;
  let socket: SocketLike | null = null;
  let closed = false;
  let everConnected = false;
  let retry: unknown = null;
  let poll: unknown = null;

  const connect = () => {
    retry = null;
    if (closed) return;
    let ws: SocketLike;
    try {
      ws = createSocket(options.url);
    } catch {
      // A malformed URL throws at once: same as no bridge, and retried (the port may be edited meanwhile).
      options.onState({ kind: everConnected ? 'lost' : 'no-bridge' });
      retry = setTimer(connect, retryMs);
      return;
    }
    socket = ws;
    ws.onopen = () => {
      everConnected = true;
      options.onState({ kind: 'connected', status: null });
      ws.send('status');
      const ask = () => {
        if (socket !== ws || closed) return;
        ws.send('status');
        poll = setTimer(ask, statusMs);
      };
      poll = setTimer(ask, statusMs);
    };
    ws.onmessage = (ev) => {
      if (typeof ev.data !== 'string') return;
      let data: unknown;
      try {
        data = JSON.parse(ev.data);
      } catch {
        return;
      }
      const frame = parseFrame(data);
      if (frame) return options.onFrame(frame.universe, frame.channels);
      const status = parseStatus(data);
      if (status) options.onState({ kind: 'connected', status });
    };
    ws.onerror = () => {};
    ws.onclose = () => {
      if (socket !== ws || closed) return;
      socket = null;
      if (poll !== null) clearTimer(poll);
      poll = null;
      options.onState({ kind: everConnected ? 'lost' : 'no-bridge' });
      retry = setTimer(connect, retryMs);
    };
  };

  options.onState({ kind: 'connecting' });
  connect();
  return {
    close() {
      closed = true;
      if (retry !== null) clearTimer(retry);
      if (poll !== null) clearTimer(poll);
      const ws = socket;
      socket = null;
      ws?.close();
    },
  };
}
