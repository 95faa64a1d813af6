/** parseArtDmx and parseE131 against packets built by hand from the standards' layouts, one test per ignore reason. */
import { describe, expect, it } from 'vitest';
import { parseArtDmx } from '../../../../src/hosts/node/dmx/parseArtDmx';
import { parseE131 } from '../../../../src/hosts/node/dmx/parseE131';
import { buildArtDmx, buildE131, CID_A, levels } from './testConsole';

function reason(r: { ok: boolean; reason?: string }) {
  return r.ok ? 'ok' : r.reason;
}

describe('parseArtDmx (Art-Net 4 ArtDmx)', () => {
  it('reads sequence, physical, the 15-bit Port-Address and the slots', () => {
    const r = parseArtDmx(buildArtDmx({ sequence: 7, physical: 2, net: 0x7f, subNet: 0xf, universe: 0xe, data: [1, 2, 3] }));
    expect(r.ok && r.packet).toEqual({ sequence: 7, physical: 2, portAddress: 0x7ffe, data: new Uint8Array([1, 2, 3]) });
    const full = parseArtDmx(buildArtDmx({ data: levels(9) }));
    expect(full.ok && full.packet.data.length).toBe(512);
  });

  it('the top bit of Net is not part of the Port-Address', () => {
    const r = parseArtDmx(buildArtDmx({ net: 0x81, data: [1, 2] }));
    expect(r.ok && r.packet.portAddress).toBe(0x100);
  });

  it('names what is wrong', () => {
    const good = buildArtDmx({ data: levels(1) });
    expect(reason(parseArtDmx(good.subarray(0, 9)))).toBe('too-short');
    expect(reason(parseArtDmx(good.subarray(0, 17)))).toBe('too-short');
    expect(reason(parseArtDmx(Buffer.from('Art-Net?\x00\x50xxxxxxxxxx', 'latin1')))).toBe('not-art-net');
    const poll = Buffer.from(good.subarray(0, 14));
    poll[9] = 0x20; // OpCode 0x2000 ArtPoll
    expect(reason(parseArtDmx(poll))).toBe('not-artdmx');
    expect(reason(parseArtDmx(buildArtDmx({ version: 13, data: [1, 2] })))).toBe('old-protocol');
    expect(reason(parseArtDmx(buildArtDmx({ version: 15, data: [1, 2] })))).toBe('ok');
    expect(reason(parseArtDmx(Buffer.concat([good, Buffer.from([0])])))).toBe('oversized');
    const zero = Buffer.from(buildArtDmx({ data: [1, 2] }));
    zero[17] = 0;
    expect(reason(parseArtDmx(zero))).toBe('bad-length');
    const long = Buffer.from(buildArtDmx({ data: [1, 2] }));
    long[17] = 3; // announces 3 slots, carries 2
    expect(reason(parseArtDmx(long))).toBe('bad-length');
    const over = Buffer.from(good);
    over[16] = 0x02;
    over[17] = 0x01; // 513
    expect(reason(parseArtDmx(over))).toBe('bad-length');
  });

  it('uses only the announced slots when the datagram carries more', () => {
    const b = Buffer.from(buildArtDmx({ data: [1, 2, 3, 4] }));
    b[17] = 2;
    const r = parseArtDmx(b);
    expect(r.ok && Array.from(r.packet.data)).toEqual([1, 2]);
  });
});

describe('parseE131 (ANSI E1.31-2018 data packet)', () => {
  it('reads the CID, source name, priority, sequence, options, universe and slots', () => {
    const r = parseE131(buildE131({ cid: CID_A, sourceName: 'Desk ☼', priority: 200, sequence: 42, universe: 63999, preview: true, data: [10, 20] }));
    expect(r.ok).toBe(true);
    if (!r.ok) return;
    expect(r.packet).toMatchObject({ cid: 'a0a1a2a3a4a5a6a7a8a9aaabacadaeaf', sourceName: 'Desk ☼', priority: 200, sequence: 42, universe: 63999, preview: true, terminated: false });
    expect(Array.from(r.packet.data)).toEqual([10, 20]);
    const t = parseE131(buildE131({ cid: CID_A, universe: 1, terminated: true, startCode: 0x17, data: [] }));
    expect(t.ok && t.packet.terminated).toBe(true);
    const full = parseE131(buildE131({ cid: CID_A, universe: 1, data: levels(3) }));
    expect(full.ok && full.packet.data.length).toBe(512);
  });

  it('names what is wrong', () => {
    const good = buildE131({ cid: CID_A, universe: 1, data: levels(1) });
    const edit = (f: (b: Buffer) => void) => {
      const b = Buffer.from(good);
      f(b);
      return reason(parseE131(b));
    };
    expect(reason(parseE131(good))).toBe('ok');
    expect(reason(parseE131(good.subarray(0, 37)))).toBe('too-short');
    expect(reason(parseE131(Buffer.concat([good, Buffer.from([0])])))).toBe('oversized');
    expect(edit((b) => (b[1] = 0x11))).toBe('not-acn');
    expect(edit((b) => (b[6] = 0x44))).toBe('not-acn');
    expect(edit((b) => (b[16] = 0x60 | (b[16] & 0x0f)))).toBe('bad-flags-length');
    expect(edit((b) => b.writeUInt16BE(0x7000 | 100, 38))).toBe('bad-flags-length');
    expect(edit((b) => b.writeUInt16BE(0x7000 | 100, 115))).toBe('bad-flags-length');
    expect(edit((b) => b.writeUInt32BE(3, 18))).toBe('bad-vector');
    expect(edit((b) => b.writeUInt32BE(8, 18))).toBe('extended');
    expect(edit((b) => b.writeUInt32BE(1, 40))).toBe('bad-vector');
    expect(edit((b) => (b[117] = 0x01))).toBe('bad-vector');
    expect(edit((b) => (b[118] = 0xa2))).toBe('bad-dmp');
    expect(edit((b) => b.writeUInt16BE(1, 119))).toBe('bad-dmp');
    expect(edit((b) => b.writeUInt16BE(2, 121))).toBe('bad-dmp');
    expect(edit((b) => b.writeUInt16BE(512, 123))).toBe('bad-dmp');
    expect(edit((b) => (b[108] = 201))).toBe('bad-priority');
    expect(edit((b) => b.writeUInt16BE(0, 113))).toBe('bad-universe');
    expect(edit((b) => b.writeUInt16BE(64000, 113))).toBe('bad-universe');
    expect(edit((b) => (b[125] = 0xdd))).toBe('start-code');
    // A sync packet (extended, 49 bytes) is shorter than a data packet but named for what it is.
    const sync = Buffer.from(good.subarray(0, 49));
    sync.writeUInt16BE(0x7000 | (49 - 16), 16);
    sync.writeUInt32BE(8, 18);
    expect(reason(parseE131(sync))).toBe('extended');
    expect(reason(parseE131(good.subarray(0, 125)))).toBe('bad-flags-length');
  });

  it('a source name without its terminating null is read to the end of its field', () => {
    const b = buildE131({ cid: CID_A, universe: 1, data: [1] });
    b.fill(0x41, 44, 108);
    const r = parseE131(b);
    expect(r.ok && r.packet.sourceName).toBe('A'.repeat(64));
  });
});
