import type { WebSocket, WebSocketServer } from 'ws';
import { createFrameQueue, type FrameQueue } from './createFrameQueue';
import type { DmxBridgeStatus } from './dmxBridge';

export interface DmxClients {
  /** Each connected client's frame queue. */
  readonly queues: Map<WebSocket, FrameQueue>;
  /** Frames coalesced so far, those of clients gone included. */
  coalesced(): number;
}

/**
 * The app's WebSocket clients: each gets every known universe at once (`initial`), then the frames
 * the bridge pushes to its queue, and the status when it sends the word "status".
 */
export function serveDmxClients(wss: WebSocketServer, highWater: number, initial: (queue: FrameQueue) => void, status: () => DmxBridgeStatus): DmxClients {
  const queues = new Map<WebSocket, FrameQueue>();
  let coalescedByGone = 0;
  wss.on('connection', (ws) => {
    const queue = createFrameQueue(
      {
        send: (text, done) => ws.send(text, done),
        bufferedAmount: () => ws.bufferedAmount,
        isOpen: () => ws.readyState === ws.OPEN,
      },
      highWater,
    );
    queues.set(ws, queue);
    initial(queue);
    ws.on('message', (data, isBinary) => {
      if (!isBinary && data.toString() === 'status' && ws.readyState === ws.OPEN) ws.send(JSON.stringify(status()));
    });
    ws.on('error', () => {
      // A broken client (bad frame, over maxPayload) is closed by ws; nothing to do for the others.
    });
    ws.on('close', () => {
      coalescedByGone += queue.coalesced();
      queues.delete(ws);
    });
  });
  return {
    queues,
    coalesced() {
      let coalesced = coalescedByGone;
      for (const q of queues.values()) coalesced += q.coalesced();
      return coalesced;
    },
  };
}

/**
 * A clean close handshake (1001 "going away") with each client, but one that does not answer
 * within half a second is cut off: Ctrl-C must not hang on a stalled browser tab.
 */
export async function closeDmxClients(sockets: readonly WebSocket[]): Promise<void> {
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
}
