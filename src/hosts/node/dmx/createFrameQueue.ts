/** Where a client's frames go: the slice of a `ws` WebSocket the queue needs (tests pass a fake). */
export interface FrameSink {
  /** Sends one text message; `done` runs once it has been handed to the operating system. */
  send(text: string, done: (error?: Error) => void): void;
  /** Bytes queued in user space, not yet written to the socket (ws `bufferedAmount`). */
  bufferedAmount(): number;
  isOpen(): boolean;
}

export interface FrameQueue {
  /** Queues the newest frame of a universe, replacing one still waiting for the same universe. */
  push(universe: number, text: string): void;
  /** Frames replaced before they were sent. */
  coalesced(): number;
}

/**
 * One client's outgoing frames without a backlog: while the client keeps up (the socket's
 * user-space buffer under `highWaterBytes`) every frame goes out at once; while it lags, at most
 * one frame per universe waits, always the newest, and the wait ends when a send completes.
 */
export function createFrameQueue(sink: FrameSink, highWaterBytes: number): FrameQueue {
  // Insertion order = age: a universe that changes again moves to the back, so none starves.
  const waiting = new Map<number, string>();
  let replaced = 0;

  function flush(): void {
    while (waiting.size > 0 && sink.isOpen() && sink.bufferedAmount() < highWaterBytes) {
      const [universe, text] = waiting.entries().next().value as [number, string];
      waiting.delete(universe);
      // Each completed send is the moment the buffer may have drained: try again then. A send
      // still pending whenever bufferedAmount is over the mark guarantees this callback comes.
      sink.send(text, () => flush());
    }
    if (!sink.isOpen()) waiting.clear();
  }

  return {
    push(universe, text) {
      if (waiting.delete(universe)) replaced++;
      waiting.set(universe, text);
      flush();
    },
    coalesced: () => replaced,
  };
}
