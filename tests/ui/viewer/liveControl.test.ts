import { describe, expect, it } from 'vitest';
import { createBridgeClient, parseFrame, parseStatus, type BridgeState, type SocketLike } from '../../../src/ui/viewer/createBridgeClient';
import { createFrameLatch } from '../../../src/ui/viewer/createFrameLatch';

describe('frame latch', () => {
  it('keeps only the latest frame per universe and applies once per scheduled frame', () => {
    const scheduled: (() => void)[] = [];
    const applied: Map<number, readonly number[]>[] = [];
    const latch = createFrameLatch(
      (f) => applied.push(new Map(f)),
      (f) => scheduled.push(f),
      () => {},
    );
    for (let i = 0; i < 100; i++) latch.put(1, [i]);
    latch.put(2, [7]);
    expect(scheduled.length).toBe(1); // 101 frames, one animation frame asked for
    scheduled.shift()!();
    expect(applied).toEqual([
      new Map([
        [1, [99]],
        [2, [7]],
      ]),
    ]);
    latch.put(1, [100]);
    scheduled.shift()!();
    expect(applied[1]).toEqual(
      new Map([
        [1, [100]],
        [2, [7]],
      ]),
    );
    expect(latch.counts).toEqual({ received: 102, applied: 2 });
    latch.reapply();
    scheduled.shift()!();
    expect(latch.counts.applied).toBe(3);
    latch.put(3, [1]);
    latch.dispose();
    scheduled.shift()!();
    expect(latch.counts.applied).toBe(3);
  });
});

/** A socket the test drives by hand. */
class FakeSocket implements SocketLike {
  static made: FakeSocket[] = [];
  onopen: SocketLike['onopen'] = null;
  onclose: SocketLike['onclose'] = null;
  onerror: SocketLike['onerror'] = null;
  onmessage: SocketLike['onmessage'] = null;
  sent: string[] = [];
  closed = false;
  constructor(readonly url: string) {
    FakeSocket.made.push(this);
  }
  send(data: string) {
    this.sent.push(data);
  }
  close() {
    this.closed = true;
  }
}

describe('bridge client', () => {
  it('parses frames and status, ignoring anything else', () => {
    expect(parseFrame({ universe: 1, channels: [0, 255] })).toEqual({ universe: 1, channels: [0, 255] });
    expect(parseFrame({ universe: 1.5, channels: [] })).toBeNull();
    expect(parseFrame({ universe: 1, channels: new Array(513).fill(0) })).toBeNull();
    expect(parseFrame({ type: 'status' })).toBeNull();
    expect(parseStatus({ type: 'status', universes: [1, 2], sources: [{}], sacn: { enabled: true }, artnet: { enabled: false } })).toEqual({ universes: [1, 2], sources: 1, protocols: ['sACN'] });
    expect(parseStatus({ universe: 1 })).toBeNull();
  });
  it('says no bridge, connected with the status, then lost, retrying every few seconds', () => {
    FakeSocket.made = [];
    const states: BridgeState[] = [];
    const frames: [number, readonly number[]][] = [];
    const timers: { f: () => void; ms: number }[] = [];
    const client = createBridgeClient({
      url: 'ws://127.0.0.1:9090',
      onState: (s) => states.push(s),
      onFrame: (u, ch) => frames.push([u, ch]),
      createSocket: (url) => new FakeSocket(url),
      setTimer: (f, ms) => timers.push({ f, ms }),
      clearTimer: () => {},
    });
    expect(states).toEqual([{ kind: 'connecting' }]);
    FakeSocket.made[0].onclose!({});
    expect(states.at(-1)).toEqual({ kind: 'no-bridge' });
    expect(timers.at(-1)!.ms).toBe(3000);
    timers.pop()!.f();
    const ws = FakeSocket.made[1];
    ws.onopen!({});
    expect(states.at(-1)).toEqual({ kind: 'connected', status: null });
    expect(ws.sent).toEqual(['status']);
    ws.onmessage!({ data: JSON.stringify({ type: 'status', universes: [1], sources: [], sacn: { enabled: true }, artnet: { enabled: true } }) });
    expect(states.at(-1)).toEqual({ kind: 'connected', status: { universes: [1], sources: 0, protocols: ['sACN', 'Art-Net'] } });
    ws.onmessage!({ data: JSON.stringify({ universe: 1, channels: [1, 2, 3] }) });
    ws.onmessage!({ data: 'not json' });
    expect(frames).toEqual([[1, [1, 2, 3]]]);
    ws.onclose!({});
    expect(states.at(-1)).toEqual({ kind: 'lost' });
    timers
      .filter((t) => t.ms === 3000)
      .pop()!
      .f();
    expect(FakeSocket.made.length).toBe(3);
    client.close();
    expect(FakeSocket.made[2].closed).toBe(true);
    const n = states.length;
    FakeSocket.made[2].onclose!({});
    expect(states.length).toBe(n); // closed by us: no state change, no retry
  });
});
