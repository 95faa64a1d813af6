/**
 * Fuzzing the bridge's packet handling (seeded, identical on every machine): mutated, truncated,
 * oversized, foreign and random datagrams through the parsers, then through the live sockets.
 * Nothing may throw; every datagram is either used or counted as ignored with a reason.
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { createRng, type Rng } from '../../../fuzz/mutate';
import { createDmxBridge, type DmxBridge } from '../../../../src/hosts/node/dmx/createDmxBridge';
import { STORE_IGNORE_REASONS } from '../../../../src/hosts/node/dmx/createUniverseStore';
import { ARTNET_IGNORE_REASONS, parseArtDmx } from '../../../../src/hosts/node/dmx/parseArtDmx';
import { parseE131, SACN_IGNORE_REASONS } from '../../../../src/hosts/node/dmx/parseE131';
import { buildArtDmx, buildE131, connect, levels, openConsole, type TestClient, type TestConsole } from './testConsole';

function seedArt(rng: Rng): Buffer {
  const n = 1 + rng.int(512);
  return buildArtDmx({ sequence: rng.int(256), net: rng.int(128), subNet: rng.int(16), universe: rng.int(16), data: Array.from({ length: n }, () => rng.int(256)) });
}

function seedSacn(rng: Rng): Buffer {
  const n = rng.int(513);
  const cid = Array.from({ length: 16 }, () => rng.int(256));
  return buildE131({ cid, priority: rng.int(201), sequence: rng.int(256), universe: 1 + rng.int(63999), terminated: rng.chance(0.05), data: Array.from({ length: n }, () => rng.int(256)) });
}

const BOUNDARY = [0x00, 0x01, 0x7f, 0x80, 0xfe, 0xff, 0x70, 0x10, 0xa1, 0x02, 0x04, 0x08, 0x50];

/** One mutation of a valid packet: flips, boundary bytes, truncation, extension, splices, or plain random bytes. */
function mutate(rng: Rng, seed: Buffer): Buffer {
  const b = Buffer.from(seed);
  switch (rng.int(7)) {
    case 0: {
      for (let k = 1 + rng.int(4); k > 0; k--) b[rng.int(b.length)] ^= 1 << rng.int(8);
      return b;
    }
    case 1: {
      // Header bytes are where the checks are: aim there most of the time.
      for (let k = 1 + rng.int(3); k > 0; k--) b[rng.chance(0.8) ? rng.int(Math.min(b.length, 126)) : rng.int(b.length)] = rng.pick(BOUNDARY);
      return b;
    }
    case 2:
      return b.subarray(0, rng.int(b.length));
    case 3:
      return Buffer.concat([b, Buffer.from(Array.from({ length: 1 + rng.int(rng.chance(0.1) ? 4000 : 40) }, () => rng.int(256)))]);
    case 4: {
      const at = rng.int(b.length);
      return Buffer.concat([b.subarray(0, at), b.subarray(at + 1 + rng.int(8))]);
    }
    case 5:
      return Buffer.from(Array.from({ length: rng.int(700) }, () => rng.int(256)));
    default: {
      // Field lengths that disagree with the datagram.
      const v = rng.pick([0, 1, 2, 0x0fff, 0xffff, b.length, b.length - 16, b.length + 1]);
      // 16: root length / Art-Net Length; 38, 115, 123: framing, DMP, count; 113: universe.
      const at = rng.pick([16, 38, 115, 123, 113]);
      if (at + 1 < b.length) b.writeUInt16BE(v & 0xffff, at);
      return b;
    }
  }
}

describe('DMX packet fuzzing', () => {
  it('the parsers survive 6000 mutated packets and name a known reason for every refusal', () => {
    const rng = createRng(1414);
    const seen = { art: new Map<string, number>(), sacn: new Map<string, number>() };
    for (let i = 0; i < 6000; i++) {
      const art = mutate(rng, seedArt(rng));
      const a = parseArtDmx(art);
      if (a.ok) {
        expect(a.packet.data.length).toBeGreaterThanOrEqual(1);
        expect(a.packet.data.length).toBeLessThanOrEqual(512);
        expect(a.packet.portAddress).toBeLessThan(32768);
        expect(art.length).toBeGreaterThanOrEqual(18 + a.packet.data.length);
      } else expect(ARTNET_IGNORE_REASONS).toContain(a.reason);
      seen.art.set(a.ok ? 'ok' : a.reason, (seen.art.get(a.ok ? 'ok' : a.reason) ?? 0) + 1);

      const sacn = mutate(rng, seedSacn(rng));
      const s = parseE131(sacn);
      if (s.ok) {
        expect(s.packet.data.length).toBeLessThanOrEqual(512);
        expect(sacn.length).toBe(126 + s.packet.data.length);
        expect(s.packet.priority).toBeLessThanOrEqual(200);
        expect(s.packet.universe).toBeGreaterThanOrEqual(1);
        expect(s.packet.universe).toBeLessThanOrEqual(63999);
      } else expect(SACN_IGNORE_REASONS).toContain(s.reason);
      seen.sacn.set(s.ok ? 'ok' : s.reason, (seen.sacn.get(s.ok ? 'ok' : s.reason) ?? 0) + 1);
    }
    // The mutations reach every check, so the test would notice one that stopped refusing.
    for (const r of ARTNET_IGNORE_REASONS) expect(seen.art.get(r) ?? 0, `Art-Net ${r}`).toBeGreaterThan(0);
    for (const r of SACN_IGNORE_REASONS.filter((x) => x !== 'extended')) expect(seen.sacn.get(r) ?? 0, `sACN ${r}`).toBeGreaterThan(0);
    expect(seen.art.get('ok') ?? 0).toBeGreaterThan(0);
    expect(seen.sacn.get('ok') ?? 0).toBeGreaterThan(0);
  });

  it('every truncation of a valid packet is refused', () => {
    const rng = createRng(7);
    for (let k = 0; k < 20; k++) {
      const art = seedArt(rng);
      const sacn = seedSacn(rng);
      for (let n = 0; n < art.length; n++) expect(parseArtDmx(art.subarray(0, n)).ok).toBe(false);
      for (let n = 0; n < sacn.length; n++) expect(parseE131(sacn.subarray(0, n)).ok).toBe(false);
    }
  });

  describe('through the live sockets', () => {
    let bridge: DmxBridge;
    let tc: TestConsole;
    let client: TestClient;
    beforeAll(async () => {
      bridge = await createDmxBridge({ artnetPort: 0, sacnPort: 0, wsPort: 0, bind: '127.0.0.1', log: () => {} });
      tc = await openConsole();
      client = await connect(bridge.address().ws.url);
    });
    afterAll(async () => {
      await client.close();
      await tc.close();
      await bridge.close();
    });

    it('3000 mutated, foreign and oversized datagrams: no crash, each one used or counted by reason', async () => {
      const rng = createRng(2024);
      const { artnet, sacn } = bridge.address();
      // The clean universe exists before the fuzz fills the universe table to its limit.
      // Priority 200 and all 255 after the fuzz: whatever mutant reached universe 2, this frame is the merge.
      const clean = (v: number, sequence: number) => buildE131({ cid: Array(16).fill(0x5a), universe: 2, priority: 200, sequence, data: levels(v) });
      await tc.send(clean(1, 0), sacn!.port);
      await client.waitFor((f) => f.universe === 2 && f.channels[0] === 1, 'clean frame before the fuzz');
      let sent = 1;
      for (let i = 0; i < 3000; i++) {
        const toArt = rng.chance(0.5);
        let packet = mutate(rng, toArt ? seedArt(rng) : seedSacn(rng));
        // Foreign traffic: the other protocol on the wrong port, and datagrams far over any DMX size.
        if (rng.chance(0.05)) packet = toArt ? seedSacn(rng) : seedArt(rng);
        if (rng.chance(0.01)) packet = Buffer.alloc(8000 + rng.int(20000), rng.int(256));
        await tc.send(packet, toArt ? artnet!.port : sacn!.port);
        sent++;
        // The bridge runs in this process: pacing lets it read, so no datagram is lost to a full buffer.
        if (i % 20 === 0) await new Promise((resolve) => setTimeout(resolve, 1));
      }
      // The bridge still works: a clean frame goes through.
      await tc.send(clean(255, 1), sacn!.port);
      sent++;
      await client.waitFor((f) => f.universe === 2 && f.channels.every((v) => v === 255), 'clean frame after the fuzz', 10_000);
      const s = await client.status();
      const sum = (r: Record<string, number>) => Object.values(r).reduce((a, b) => a + b, 0);
      for (const p of [s.artnet, s.sacn]) expect(p.packets).toBe(p.accepted + sum(p.ignored));
      expect(s.artnet.packets + s.sacn.packets).toBe(sent);
      for (const r of Object.keys(s.artnet.ignored)) expect([...ARTNET_IGNORE_REASONS, ...STORE_IGNORE_REASONS]).toContain(r);
      for (const r of Object.keys(s.sacn.ignored)) expect([...SACN_IGNORE_REASONS, ...STORE_IGNORE_REASONS]).toContain(r);
      expect(sum(s.artnet.ignored)).toBeGreaterThan(500);
      expect(sum(s.sacn.ignored)).toBeGreaterThan(500);
      // Random universes from the valid mutants fill the table: the limit holds, and is counted.
      expect(s.universes.length).toBeLessThanOrEqual(512);
    });
  });
});
