/** The merge rule, the E1.31 §6.7.2 sequence window, the per-universe store and the coalescing queue, without sockets. */
import { describe, expect, it } from 'vitest';
import { createFrameQueue } from '../../../../src/hosts/node/dmx/createFrameQueue';
import { createUniverseStore } from '../../../../src/hosts/node/dmx/createUniverseStore';
import { isStaleSequence } from '../../../../src/hosts/node/dmx/isStaleSequence';
import { mergeUniverse } from '../../../../src/hosts/node/dmx/mergeUniverse';
import { sacnMulticastGroup } from '../../../../src/hosts/node/dmx/sacnMulticastGroup';
import type { E131Packet } from '../../../../src/hosts/node/dmx/parseE131';

const u8 = (...v: number[]) => new Uint8Array(v);

describe('mergeUniverse', () => {
  it('highest priority wins, then HTP per slot; no source gives null', () => {
    expect(mergeUniverse([])).toBeNull();
    const m = mergeUniverse([
      { priority: 100, channels: u8(10, 200, 0) },
      { priority: 100, channels: u8(50, 20) },
      { priority: 99, channels: u8(255, 255, 255) },
    ])!;
    expect(Array.from(m.subarray(0, 4))).toEqual([50, 200, 0, 0]);
    expect(m.length).toBe(512);
    const top = mergeUniverse([
      { priority: 0, channels: u8(9) },
      { priority: 200, channels: u8(1) },
    ])!;
    expect(top[0]).toBe(1);
  });
});

describe('isStaleSequence (E1.31-2018 §6.7.2, an equal number accepted)', () => {
  it('discards 1 to 19 behind (mod 256), accepts everything else, the same number too (a sender that never increments)', () => {
    expect(isStaleSequence(10, 10)).toBe(false);
    expect(isStaleSequence(0, 0)).toBe(false);
    expect(isStaleSequence(10, 9)).toBe(true);
    expect(isStaleSequence(10, 247)).toBe(true); // -19
    expect(isStaleSequence(10, 246)).toBe(false); // -20: a restarted source
    expect(isStaleSequence(10, 11)).toBe(false);
    expect(isStaleSequence(255, 0)).toBe(false);
    expect(isStaleSequence(0, 255)).toBe(true);
    expect(isStaleSequence(250, 5)).toBe(false);
  });
});

describe('sacnMulticastGroup (E1.31-2018 §9.3.1)', () => {
  it('is 239.255.hi.lo', () => {
    expect(sacnMulticastGroup(1)).toBe('239.255.0.1');
    expect(sacnMulticastGroup(258)).toBe('239.255.1.2');
    expect(sacnMulticastGroup(63999)).toBe('239.255.249.255');
  });
});

function sacn(cid: string, universe: number, values: number[], extra: Partial<E131Packet> = {}): E131Packet {
  return { cid, sourceName: cid, priority: 100, syncAddress: 0, sequence: 0, preview: false, terminated: false, universe, data: u8(...values), ...extra };
}

describe('createUniverseStore', () => {
  it('holds the last look when the last source leaves, and reports only real changes', () => {
    const s = createUniverseStore({ sacnTimeoutMs: 100 });
    expect(s.acceptE131(sacn('a', 1, [5]), 'x', 0)).toEqual({ ok: true, universe: 1, changed: true });
    expect(s.acceptE131(sacn('a', 1, [5], { sequence: 1 }), 'x', 10)).toEqual({ ok: true, universe: 1, changed: false });
    expect(s.expire(50)).toEqual([]);
    expect(s.expire(111)).toEqual([]);
    expect(s.sources(111)).toEqual([]);
    expect(s.get(1)![0]).toBe(5);
    expect(s.universes()).toEqual([1]);
  });

  it('sequence 0 disables the check for Art-Net only; in sACN it is an ordinary number', () => {
    const s = createUniverseStore();
    s.acceptE131(sacn('a', 1, [1], { sequence: 0 }), 'x', 0);
    expect(s.acceptE131(sacn('a', 1, [2], { sequence: 255 }), 'x', 0)).toEqual({ ok: false, reason: 'stale-sequence' });
    expect(s.acceptE131(sacn('a', 1, [2], { sequence: 1 }), 'x', 0)).toEqual({ ok: true, universe: 1, changed: true });
    const art = (sequence: number, v: number) => ({ sequence, physical: 0, portAddress: 0, data: u8(v) });
    s.acceptArtDmx(art(0, 1), 'y', 0);
    expect(s.acceptArtDmx(art(0, 2), 'y', 0).ok).toBe(true);
    expect(s.acceptArtDmx(art(9, 3), 'y', 0).ok).toBe(true);
    expect(s.acceptArtDmx(art(8, 4), 'y', 0)).toEqual({ ok: false, reason: 'stale-sequence' });
    expect(s.acceptArtDmx(art(0, 5), 'y', 0).ok).toBe(true);
  });

  it('a sender stuck on one non-zero sequence number keeps being applied, both protocols (issue 32)', () => {
    const s = createUniverseStore();
    const art = (v: number) => ({ sequence: 42, physical: 0, portAddress: 1, data: u8(v) });
    for (let i = 1; i <= 50; i++) {
      expect(s.acceptE131(sacn('a', 1, [i], { sequence: 42 }), 'x', i * 25)).toEqual({ ok: true, universe: 1, changed: true });
      expect(s.acceptArtDmx(art(i), 'y', i * 25)).toEqual({ ok: true, universe: 2, changed: true });
    }
    expect(s.get(1)![0]).toBe(50);
    expect(s.get(2)![0]).toBe(50);
    // A late packet is still discarded while the source is live.
    expect(s.acceptE131(sacn('a', 1, [7], { sequence: 41 }), 'x', 1300)).toEqual({ ok: false, reason: 'stale-sequence' });
  });

  it('a source whose packets were all discarded for SEQUENCE_RESYNC_MS is followed again whatever its number', () => {
    const s = createUniverseStore({ sequenceResyncMs: 1000 });
    s.acceptE131(sacn('a', 1, [1], { sequence: 100 }), 'x', 0);
    // Restarted at 90 and counting on: 90..99 are behind 100, discarded for up to a second …
    expect(s.acceptE131(sacn('a', 1, [2], { sequence: 90 }), 'x', 500).ok).toBe(false);
    expect(s.acceptE131(sacn('a', 1, [2], { sequence: 95 }), 'x', 1000).ok).toBe(false);
    // … then the source is followed from its current number.
    expect(s.acceptE131(sacn('a', 1, [3], { sequence: 96 }), 'x', 1001)).toEqual({ ok: true, universe: 1, changed: true });
    expect(s.acceptE131(sacn('a', 1, [4], { sequence: 97 }), 'x', 1002).ok).toBe(true);
    expect(s.acceptE131(sacn('a', 1, [5], { sequence: 96 }), 'x', 1003).ok).toBe(false);
  });

  it('limits universes and sources per universe, and counts them as ignored', () => {
    const s = createUniverseStore({ maxUniverses: 2, maxSourcesPerUniverse: 2 });
    s.acceptE131(sacn('a', 1, [1]), 'x', 0);
    s.acceptE131(sacn('a', 2, [1]), 'x', 0);
    expect(s.acceptE131(sacn('a', 3, [1]), 'x', 0)).toEqual({ ok: false, reason: 'universe-limit' });
    s.acceptE131(sacn('b', 1, [1]), 'x', 0);
    expect(s.acceptE131(sacn('c', 1, [1]), 'x', 0)).toEqual({ ok: false, reason: 'source-limit' });
    // A terminate for an unknown source or universe is accepted and changes nothing.
    expect(s.acceptE131(sacn('z', 9, [], { terminated: true }), 'x', 0)).toEqual({ ok: true, universe: 9, changed: false });
  });

  it('tells Art-Net sources apart by IP address (Art-Net 4 merge), sACN sources by CID', () => {
    const s = createUniverseStore();
    const art = (v: number) => ({ sequence: 0, physical: 0, portAddress: 0, data: u8(v) });
    s.acceptArtDmx(art(10), '10.0.0.1:6454', 0);
    s.acceptArtDmx(art(20), '10.0.0.1:50000', 0);
    s.acceptArtDmx(art(5), '10.0.0.2:6454', 0);
    expect(s.sources(0).map((x) => x.id)).toEqual(['10.0.0.1', '10.0.0.2']);
    expect(s.get(1)![0]).toBe(20);
  });
});

describe('createFrameQueue', () => {
  it('sends at once while the client keeps up, keeps only the newest frame per universe while it lags', () => {
    const sent: string[] = [];
    const pending: (() => void)[] = [];
    let buffered = 0;
    const q = createFrameQueue(
      {
        send: (text, done) => {
          sent.push(text);
          buffered += text.length;
          pending.push(() => {
            buffered -= text.length;
            done();
          });
        },
        bufferedAmount: () => buffered,
        isOpen: () => true,
      },
      10,
    );
    q.push(1, 'u1-a-xxxxxxxx'); // goes out: the buffer was empty
    q.push(1, 'u1-b');
    q.push(2, 'u2-a');
    q.push(1, 'u1-c'); // replaces u1-b
    expect(sent).toEqual(['u1-a-xxxxxxxx']);
    expect(q.coalesced()).toBe(1);
    pending.shift()!(); // the socket drained: both waiting universes go, oldest first
    expect(sent).toEqual(['u1-a-xxxxxxxx', 'u2-a', 'u1-c']);
  });

  it('drops what waits when the client is gone', () => {
    let open = true;
    const sent: string[] = [];
    const q = createFrameQueue({ send: (t) => sent.push(t), bufferedAmount: () => 100, isOpen: () => open }, 10);
    q.push(1, 'a');
    open = false;
    q.push(1, 'b');
    expect(sent).toEqual([]);
  });
});
