import { createSocket, type Socket } from 'node:dgram';
import { WebSocketServer } from 'ws';
import { DmxBridgeStartError } from './dmxBridgeStartError';
import type { DmxBridgeOptions } from './dmxBridge';

export const ARTNET_PORT = 6454;
export const SACN_PORT = 5568;
export const DMX_WS_PORT = 9090;

/** A UDP socket bound to the port, or a DmxBridgeStartError that says why not. */
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

/** A WebSocket server listening on the port, or a DmxBridgeStartError that says why not. */
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

export interface DmxSockets {
  artnet: Socket | null;
  sacn: Socket | null;
  /** Every UDP socket opened. */
  opened: Socket[];
  wss: WebSocketServer;
}

/** The Art-Net and sACN sockets asked for and the WebSocket server on 127.0.0.1; on a failure the sockets opened so far are closed again. */
export async function openDmxSockets(options: DmxBridgeOptions, bind: string): Promise<DmxSockets> {
  const opened: Socket[] = [];
  let artnet: Socket | null = null;
  let sacn: Socket | null = null;
  try {
    if (options.artnet ?? true) opened.push((artnet = await bindUdp(options.artnetPort ?? ARTNET_PORT, bind, 'Art-Net')));
    if (options.sacn ?? true) opened.push((sacn = await bindUdp(options.sacnPort ?? SACN_PORT, bind, 'sACN')));
    const wss = await listenWs(options.wsPort ?? DMX_WS_PORT, '127.0.0.1');
    return { artnet, sacn, opened, wss };
  } catch (error) {
    for (const s of opened) s.close();
    throw error;
  }
}
