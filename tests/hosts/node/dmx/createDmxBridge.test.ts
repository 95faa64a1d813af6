/**
 * The bridge end to end: a test console sends real Art-Net and sACN datagrams on the loopback
 * interface, a real `ws` client reads what the app would read.
 */
import { createSocket } from 'node:dgram';
import { afterEach, describe, expect, it } from 'vitest';
import { createDmxBridge, type DmxBridge, type DmxBridgeOptions } from '../../../../src/hosts/node/dmx/createDmxBridge';
import { buildArtDmx, buildE131, CID_A, CID_B, connect, levels, openConsole, type TestClient, type TestConsole } from './testConsole';

let bridge: DmxBridge | null = null;
let console_: TestConsole | null = null;
const clients: TestClient[] = [];

async function start(options: DmxBridgeOptions = {}) {
  bridge = await createDmxBridge({ artnetPort: 0, sacnPort: 0, wsPort: 0, bind: '127.0.0.1', log: () => {}, ...options });
  console_ = await openConsole();
  const a = bridge.address();
  const client = await connect(a.ws.url);
  clients.push(client);
  return { bridge, console: console_, client, artnetPort: a.artnet?.port ?? -1, sacnPort: a.sacn?.port ?? -1 };
}

afterEach(async () => {
  for (const c of clients.splice(0)) await c.close();
  await console_?.close();
  await bridge?.close();
  bridge = null;
  console_ = null;
});

const at = (u: number, ch: number, v: number) => (f: { universe: number; channels: number[] }) => f.universe === u && f.channels[ch] === v;

describe('createDmxBridge', () => {
  it('serves Art-Net and sACN levels as { universe, channels[512] }; Art-Net Port-Address p is universe p + 1', async () => {
    const { console: tc, client, artnetPort, sacnPort } = await start();
    await tc.send(buildArtDmx({ net: 0, subNet: 0, universe: 0, data: levels(0, { 0: 11, 511: 12 }) }), artnetPort);
    const a = await client.waitFor(at(1, 0, 11), 'Art-Net universe 0 → 1');
    expect(a.channels).toHaveLength(512);
    expect(a.channels[511]).toBe(12);
    // Net 1, Sub-Net 2, Universe 3: Port-Address 0x123 = 291 → luxbox 292.
    await tc.send(buildArtDmx({ net: 1, subNet: 2, universe: 3, sequence: 1, data: [200, 201] }), artnetPort);
    const b = await client.waitFor(at(292, 0, 200), 'Art-Net Port-Address 0x123');
    expect(b.channels.slice(0, 3)).toEqual([200, 201, 0]);
    await tc.send(buildE131({ cid: CID_A, universe: 7, sequence: 1, data: levels(0, { 4: 99 }) }), sacnPort);
    const c = await client.waitFor(at(7, 4, 99), 'sACN universe 7');
    expect(c.channels.every((v, i) => (i === 4 ? v === 99 : v === 0))).toBe(true);
  });

  it('a client that connects gets every known universe at once', async () => {
    const { bridge: b, console: tc, client, sacnPort } = await start();
    await tc.send(buildE131({ cid: CID_A, universe: 1, data: levels(10) }), sacnPort);
    await tc.send(buildE131({ cid: CID_A, universe: 2, data: levels(20) }), sacnPort);
    await client.waitFor(at(2, 0, 20), 'universe 2');
    const late = await connect(b.address().ws.url);
    clients.push(late);
    await late.waitFor(at(1, 0, 10), 'universe 1 on connect');
    await late.waitFor(at(2, 0, 20), 'universe 2 on connect');
    expect(late.frames.map((f) => f.universe)).toEqual([1, 2]);
  });

  it('merges sACN by priority: the higher priority wins outright, lower values included', async () => {
    const { console: tc, client, sacnPort } = await start();
    await tc.send(buildE131({ cid: CID_A, priority: 100, universe: 1, data: levels(200) }), sacnPort);
    await client.waitFor(at(1, 0, 200), 'A alone');
    await tc.send(buildE131({ cid: CID_B, priority: 150, universe: 1, data: levels(30, { 1: 40 }) }), sacnPort);
    const f = await client.waitFor(at(1, 0, 30), 'B at priority 150 wins');
    expect(f.channels[1]).toBe(40);
    expect(f.channels[2]).toBe(30);
    // A keeps sending at the lower priority: nothing changes.
    await tc.send(buildE131({ cid: CID_A, priority: 100, sequence: 1, universe: 1, data: levels(255) }), sacnPort);
    const s = await client.status();
    expect(s.sources.map((x) => x.priority).sort()).toEqual([100, 150]);
    expect(client.frames.at(-1)!.channels[0]).toBe(30);
  });

  it('merges equal priorities HTP, and Art-Net counts as priority 100', async () => {
    const { console: tc, client, sacnPort, artnetPort } = await start();
    await tc.send(buildE131({ cid: CID_A, priority: 100, universe: 1, data: levels(0, { 0: 100, 1: 10 }) }), sacnPort);
    await tc.send(buildE131({ cid: CID_B, priority: 100, universe: 1, data: levels(0, { 0: 50, 1: 60, 2: 5 }) }), sacnPort);
    const f = await client.waitFor((x) => x.universe === 1 && x.channels[1] === 60, 'HTP of A and B');
    expect(f.channels.slice(0, 4)).toEqual([100, 60, 5, 0]);
    // Art-Net universe 0 → 1 joins the merge at 100.
    await tc.send(buildArtDmx({ universe: 0, data: levels(0, { 3: 77, 0: 1 }) }), artnetPort);
    const g = await client.waitFor(at(1, 3, 77), 'Art-Net joins HTP');
    expect(g.channels.slice(0, 4)).toEqual([100, 60, 5, 77]);
    // A higher sACN priority overrides Art-Net and the priority-100 sources.
    await tc.send(buildE131({ cid: CID_A, priority: 101, sequence: 1, universe: 1, data: levels(0, { 0: 9 }) }), sacnPort);
    const h = await client.waitFor(at(1, 0, 9), 'priority 101 alone');
    expect(h.channels.slice(0, 4)).toEqual([9, 0, 0, 0]);
  });

  it('discards a packet 1 to 19 sequence numbers behind the last accepted one (E1.31 §6.7.2), both protocols', async () => {
    const { console: tc, client, sacnPort, artnetPort } = await start();
    await tc.send(buildE131({ cid: CID_A, sequence: 10, universe: 1, data: levels(10) }), sacnPort);
    await client.waitFor(at(1, 0, 10), 'seq 10');
    await tc.send(buildE131({ cid: CID_A, sequence: 9, universe: 1, data: levels(9) }), sacnPort); // late: discarded
    await tc.send(buildE131({ cid: CID_A, sequence: 250, universe: 1, data: levels(250) }), sacnPort); // 250 - 10 = -16 mod 256: discarded
    await tc.send(buildE131({ cid: CID_A, sequence: 11, universe: 1, data: levels(11) }), sacnPort);
    await client.waitFor(at(1, 0, 11), 'seq 11');
    await tc.send(buildArtDmx({ sequence: 100, universe: 4, data: levels(1) }), artnetPort);
    await client.waitFor(at(5, 0, 1), 'Art-Net seq 100');
    await tc.send(buildArtDmx({ sequence: 99, universe: 4, data: levels(2) }), artnetPort); // late: discarded
    await tc.send(buildArtDmx({ sequence: 0, universe: 4, data: levels(3) }), artnetPort); // 0: no sequencing, accepted
    await client.waitFor(at(5, 0, 3), 'Art-Net seq 0');
    expect(client.frames.some((f) => f.channels[0] === 9 || f.channels[0] === 250 || (f.universe === 5 && f.channels[0] === 2))).toBe(false);
    const s = await client.status();
    expect(s.sacn.ignored['stale-sequence']).toBe(2);
    expect(s.artnet.ignored['stale-sequence']).toBe(1);
  });

  it('a sender stuck on one non-zero sequence number keeps being applied, Art-Net and sACN (issue 32)', async () => {
    const { console: tc, client, sacnPort, artnetPort } = await start();
    for (let v = 1; v <= 5; v++) {
      await tc.send(buildE131({ cid: CID_A, sequence: 7, universe: 1, data: levels(v) }), sacnPort);
      await client.waitFor(at(1, 0, v), `sACN look ${v}, sequence 7`);
      await tc.send(buildArtDmx({ sequence: 7, universe: 4, data: levels(10 + v) }), artnetPort);
      await client.waitFor(at(5, 0, 10 + v), `Art-Net look ${v}, sequence 7`);
    }
    const s = await client.status();
    expect(s.sacn.ignored['stale-sequence'] ?? 0).toBe(0);
    expect(s.artnet.ignored['stale-sequence'] ?? 0).toBe(0);
  });

  it('Stream_Terminated drops the source at once and the merge falls back; a silent source leaves after its timeout', async () => {
    const { console: tc, client, sacnPort, artnetPort } = await start({ sacnTimeoutMs: 150, artnetTimeoutMs: 150 });
    await tc.send(buildE131({ cid: CID_A, priority: 100, universe: 1, data: levels(10) }), sacnPort);
    await tc.send(buildE131({ cid: CID_B, priority: 120, sequence: 1, universe: 1, data: levels(20) }), sacnPort);
    await client.waitFor(at(1, 0, 20), 'B wins');
    // B terminates (its data is not used, §6.2.6): A's levels come back.
    await tc.send(buildE131({ cid: CID_B, priority: 120, sequence: 2, universe: 1, terminated: true, data: levels(99) }), sacnPort);
    await client.waitFor(at(1, 0, 10), 'back to A after B terminated');
    expect(client.frames.some((f) => f.channels[0] === 99)).toBe(false);
    // Two sources at one priority, one falls silent: after the timeout the HTP is recomputed.
    await tc.send(buildArtDmx({ universe: 1, data: levels(0, { 0: 50 }) }), artnetPort); // universe 2
    await tc.send(buildE131({ cid: CID_A, universe: 2, sequence: 5, data: levels(0, { 0: 30, 1: 30 }) }), sacnPort);
    await client.waitFor((f) => f.universe === 2 && f.channels[0] === 50 && f.channels[1] === 30, 'HTP of Art-Net and sACN');
    const mergedAt = client.frames.length;
    // Only the sACN source keeps sending; the Art-Net one times out.
    let seq = 5;
    const keepAlive = setInterval(() => void tc.send(buildE131({ cid: CID_A, universe: 2, sequence: ++seq & 0xff, data: levels(0, { 0: 30, 1: 30 }) }), sacnPort), 30);
    try {
      await client.waitFor((f) => f.universe === 2 && f.channels[0] === 30 && f.channels[1] === 30, 'Art-Net source timed out', 5000, mergedAt);
    } finally {
      clearInterval(keepAlive);
    }
    const s = await client.status();
    expect(s.sources.filter((x) => x.universes.includes(2)).map((x) => x.protocol)).toEqual(['sacn']);
    expect(s.sources).toEqual([expect.objectContaining({ protocol: 'sacn', id: CID_A.map((b) => b.toString(16)).join(''), universes: [2], name: 'test console' })]);
  });

  it('ignores non-zero START Codes, counts every datagram as accepted or ignored with a reason', async () => {
    const { console: tc, client, sacnPort, artnetPort } = await start();
    await tc.send(buildE131({ cid: CID_A, universe: 1, startCode: 0xdd, data: levels(1) }), sacnPort);
    await tc.send(Buffer.from('hello'), sacnPort);
    await tc.send(buildArtDmx({ version: 13, data: levels(1) }), artnetPort);
    await tc.send(buildE131({ cid: CID_A, universe: 1, data: levels(42) }), sacnPort);
    await tc.send(buildArtDmx({ universe: 9, data: levels(43) }), artnetPort);
    await client.waitFor(at(1, 0, 42), 'good sACN');
    await client.waitFor(at(10, 0, 43), 'good Art-Net');
    const s = await client.status();
    expect(s.type).toBe('status');
    expect(s.sacn.ignored['start-code']).toBe(1);
    expect(s.sacn.ignored['too-short']).toBe(1);
    expect(s.artnet.ignored['old-protocol']).toBe(1);
    expect(s.sacn).toMatchObject({ packets: 3, accepted: 1, enabled: true });
    expect(s.artnet).toMatchObject({ packets: 2, accepted: 1, enabled: true });
    expect(s.universes).toEqual([1, 10]);
    expect(s.clients).toBe(1);
  });

  it('a slow client gets the newest frame of each universe, not a queue', async () => {
    // The only client, so what the bridge counts as coalesced is this client's.
    const { bridge: b, console: tc, client: slow, sacnPort } = await start({ highWaterBytes: 1 });
    // The slow client stops reading: its socket fills, then the bridge must coalesce.
    slow.ws.pause();
    const universes = [1, 2, 3];
    // Rounds until the slow client's socket is full and the bridge has had to coalesce (how many
    // depends on the machine's TCP buffers, a few MB on Linux loopback), then 50 more.
    let rounds = 0;
    for (let r = 1, fullAt = Infinity; r <= fullAt + 50; r++) {
      rounds = r;
      if (fullAt === Infinity && r % 100 === 0 && b.status().coalesced > 0) fullAt = r;
      if (r > 30_000) throw new Error('the slow client never filled its socket');
      for (const u of universes) {
        // Channel 0 counts the round; the rest makes each message about 2 kB, so the socket fills.
        await tc.send(buildE131({ cid: CID_A, universe: u, sequence: r & 0xff, data: levels(100 + (r % 100), { 0: r & 0xff, 1: r >> 8 }) }), sacnPort);
      }
      // Let the bridge read (it shares this process): paced, no datagram is lost to a full buffer.
      if (r % 10 === 0) await new Promise((resolve) => setTimeout(resolve, 1));
    }
    const last = (u: number) => (f: { universe: number; channels: number[] }) => f.universe === u && f.channels[0] === (rounds & 0xff) && f.channels[1] === rounds >> 8;
    for (let wait = 0; b.status().sacn.packets < rounds * universes.length; wait++) {
      if (wait > 500) throw new Error(`the bridge received ${b.status().sacn.packets} of ${rounds * universes.length} datagrams`);
      await new Promise((resolve) => setTimeout(resolve, 10));
    }
    expect(b.status().sacn.accepted).toBe(rounds * universes.length);
    expect(b.status().coalesced).toBeGreaterThan(0);
    slow.ws.resume();
    for (const u of universes) await slow.waitFor(last(u), `slow client, universe ${u}, last round`, 20_000);
    // Fewer frames than were sent, and per universe in order: skipped, never reordered.
    expect(slow.frames.length).toBeLessThan(rounds * universes.length);
    for (const u of universes) {
      const seq = slow.frames.filter((f) => f.universe === u).map((f) => f.channels[0] + 256 * f.channels[1]);
      expect(seq).toEqual([...seq].sort((x, y) => x - y));
    }
  });

  it('joins the sACN multicast group of each universe asked for (E1.31 §9.3.1) and closes cleanly', async () => {
    const b = await createDmxBridge({ artnet: false, sacnPort: 0, wsPort: 0, universes: [1, 258], log: () => {} });
    bridge = b;
    const a = b.address();
    expect(a.artnet).toBeNull();
    // Where the machine has no multicast route the join fails with a warning; when it works the groups are these.
    for (const g of a.sacn!.multicast) expect(['239.255.0.1', '239.255.1.2']).toContain(g);
    expect(b.status().artnet.enabled).toBe(false);
    await b.close();
    await b.close();
    bridge = null;
  });

  it('receives sACN multicast on 239.255.hi.lo for a joined universe', async () => {
    const warnings: string[] = [];
    const b = await createDmxBridge({ artnet: false, sacnPort: 0, wsPort: 0, universes: [3], log: (l) => warnings.push(l) });
    bridge = b;
    const { sacn, ws } = b.address();
    if (sacn!.multicast.length === 0) {
      // A machine without a multicast route: the failed join is said, and unicast still works.
      expect(warnings.join('\n')).toMatch(/cannot join multicast group 239\.255\.0\.3 for universe 3/);
      return;
    }
    expect(sacn!.multicast).toEqual(['239.255.0.3']);
    const client = await connect(ws.url);
    clients.push(client);
    const sender = createSocket('udp4');
    await new Promise<void>((resolve) => sender.bind(0, () => resolve()));
    sender.setMulticastLoopback(true);
    try {
      await new Promise<void>((resolve, reject) => sender.send(buildE131({ cid: CID_A, universe: 3, data: levels(0, { 0: 33 }) }), sacn!.port, '239.255.0.3', (e) => (e ? reject(e) : resolve())));
      await client.waitFor(at(3, 0, 33), 'multicast frame');
    } finally {
      sender.close();
    }
  });

  it('a port in use is a clear start error', async () => {
    const first = await createDmxBridge({ artnet: false, sacnPort: 0, wsPort: 0, bind: '127.0.0.1', log: () => {} });
    bridge = first;
    const taken = first.address().ws.port;
    await expect(createDmxBridge({ artnet: false, sacnPort: 0, wsPort: taken, bind: '127.0.0.1', log: () => {} })).rejects.toThrow(/WebSocket: cannot listen on 127\.0\.0\.1:\d+ \(port in use/);
  });
});
