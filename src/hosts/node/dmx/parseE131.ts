/**
 * E1.31 (sACN) data packet parser, ANSI E1.31-2018. Hand-written: the data packet is one fixed
 * layout (Table 4-1), and every field is checked against the bytes that arrived before it is used
 * (docs/dmx.md, "Why no protocol library").
 *
 * Layout (offsets in bytes, all multi-byte fields big-endian):
 *   Root layer (§5)
 *     0  Preamble Size          0x0010
 *     2  Post-amble Size        0x0000
 *     4  ACN Packet Identifier  "ASC-E1.17\0\0\0" (§5.3)
 *    16  Flags & Length         0x7 in the high 4 bits, PDU length (to the end) in the low 12
 *    18  Vector                 VECTOR_ROOT_E131_DATA 0x00000004 (0x00000008 = extended: sync, discovery)
 *    22  CID[16]                the source's component identifier (§5.6)
 *   Framing layer (§6)
 *    38  Flags & Length
 *    40  Vector                 VECTOR_E131_DATA_PACKET 0x00000002
 *    44  Source Name[64]        UTF-8, null-terminated
 *   108  Priority               0–200 (§6.2.3)
 *   109  Synchronization Address
 *   111  Sequence Number        (§6.2.5, §6.7.2)
 *   112  Options                bit 7 Preview_Data, bit 6 Stream_Terminated, bit 5 Force_Synchronization (§6.2.6)
 *   113  Universe               1–63999 (§6.2.7)
 *   DMP layer (§7)
 *   115  Flags & Length
 *   117  Vector                 VECTOR_DMP_SET_PROPERTY 0x02
 *   118  Address & Data Type    0xa1
 *   119  First Property Address 0x0000
 *   121  Address Increment      0x0001
 *   123  Property Value Count   1–513 (START Code + slots)
 *   125  Property Values        START Code, then the DMX slots
 */

export const ACN_PACKET_IDENTIFIER = [0x41, 0x53, 0x43, 0x2d, 0x45, 0x31, 0x2e, 0x31, 0x37, 0x00, 0x00, 0x00] as const;
export const VECTOR_ROOT_E131_DATA = 0x00000004;
export const VECTOR_ROOT_E131_EXTENDED = 0x00000008;
export const VECTOR_E131_DATA_PACKET = 0x00000002;
export const VECTOR_DMP_SET_PROPERTY = 0x02;
export const E131_HEADER_BYTES = 126;
export const E131_MAX_BYTES = 638;
export const MAX_PRIORITY = 200;
export const MAX_UNIVERSE = 63999;

export interface E131Packet {
  /** The CID as 32 lower-case hex digits: sources are told apart by CID (§5.6), not by address. */
  cid: string;
  sourceName: string;
  priority: number;
  syncAddress: number;
  sequence: number;
  preview: boolean;
  /** Stream_Terminated (§6.2.6): the source has stopped sending this universe; the data is not used. */
  terminated: boolean;
  universe: number;
  /** The DMX slots after the START Code (0–512 of them). */
  data: Uint8Array;
}

export type SacnIgnoreReason =
  | 'too-short'
  | 'oversized'
  /** Preamble, post-amble or ACN packet identifier wrong: not an ACN packet. */
  | 'not-acn'
  /** A Flags & Length field with flags other than 0x7 or a length that does not match the datagram. */
  | 'bad-flags-length'
  /** A root or framing vector that is not E1.31 data, or a DMP vector other than Set Property. */
  | 'bad-vector'
  /** Universe synchronization or discovery (extended root vector): valid, not DMX data. */
  | 'extended'
  /** DMP address type, first address, increment or property value count not as §7 fixes them. */
  | 'bad-dmp'
  | 'bad-priority'
  | 'bad-universe'
  /** Alternate START Code (per-address priority 0xDD, text, ...): only START Code 0 is DMX levels. */
  | 'start-code';

export const SACN_IGNORE_REASONS: readonly SacnIgnoreReason[] = ['too-short', 'oversized', 'not-acn', 'bad-flags-length', 'bad-vector', 'extended', 'bad-dmp', 'bad-priority', 'bad-universe', 'start-code'];

export type E131Result = { ok: true; packet: E131Packet } | { ok: false; reason: SacnIgnoreReason };

function u16(b: Uint8Array, at: number): number {
  return (b[at] << 8) | b[at + 1];
}

function u32(b: Uint8Array, at: number): number {
  return ((b[at] << 24) | (b[at + 1] << 16) | (b[at + 2] << 8) | b[at + 3]) >>> 0;
}

/** A Flags & Length field (§5.4, §6.1, §7.1) covering the datagram from `at` to its end. */
function flagsLengthOk(b: Uint8Array, at: number): boolean {
  const v = u16(b, at);
  return v >>> 12 === 0x7 && (v & 0x0fff) === b.length - at;
}

const utf8 = new TextDecoder('utf-8', { fatal: false });

/** Parses one UDP datagram received on the sACN port; never throws. */
export function parseE131(bytes: Uint8Array): E131Result {
  // The root layer alone is 38 bytes; an extended packet (sync, discovery) may be shorter than a data packet.
  if (bytes.length < 38) return { ok: false, reason: 'too-short' };
  if (bytes.length > E131_MAX_BYTES) return { ok: false, reason: 'oversized' };
  if (u16(bytes, 0) !== 0x0010 || u16(bytes, 2) !== 0x0000) return { ok: false, reason: 'not-acn' };
  for (let i = 0; i < ACN_PACKET_IDENTIFIER.length; i++) {
    if (bytes[4 + i] !== ACN_PACKET_IDENTIFIER[i]) return { ok: false, reason: 'not-acn' };
  }
  if (!flagsLengthOk(bytes, 16)) return { ok: false, reason: 'bad-flags-length' };
  const rootVector = u32(bytes, 18);
  if (rootVector === VECTOR_ROOT_E131_EXTENDED) return { ok: false, reason: 'extended' };
  if (rootVector !== VECTOR_ROOT_E131_DATA) return { ok: false, reason: 'bad-vector' };
  if (bytes.length < E131_HEADER_BYTES) return { ok: false, reason: 'too-short' };
  if (!flagsLengthOk(bytes, 38)) return { ok: false, reason: 'bad-flags-length' };
  if (u32(bytes, 40) !== VECTOR_E131_DATA_PACKET) return { ok: false, reason: 'bad-vector' };
  if (!flagsLengthOk(bytes, 115)) return { ok: false, reason: 'bad-flags-length' };
  if (bytes[117] !== VECTOR_DMP_SET_PROPERTY) return { ok: false, reason: 'bad-vector' };
  const count = u16(bytes, 123);
  if (bytes[118] !== 0xa1 || u16(bytes, 119) !== 0x0000 || u16(bytes, 121) !== 0x0001 || count < 1 || count > 513 || 125 + count !== bytes.length) {
    return { ok: false, reason: 'bad-dmp' };
  }
  const priority = bytes[108];
  if (priority > MAX_PRIORITY) return { ok: false, reason: 'bad-priority' };
  const universe = u16(bytes, 113);
  if (universe < 1 || universe > MAX_UNIVERSE) return { ok: false, reason: 'bad-universe' };
  const options = bytes[112];
  const terminated = (options & 0x40) !== 0;
  // A terminating packet is passed on whatever its START Code: it ends the stream (§6.2.6).
  if (bytes[125] !== 0x00 && !terminated) return { ok: false, reason: 'start-code' };
  let cid = '';
  for (let i = 22; i < 38; i++) cid += bytes[i].toString(16).padStart(2, '0');
  const nameEnd = bytes.subarray(44, 108).indexOf(0);
  const sourceName = utf8.decode(bytes.subarray(44, nameEnd < 0 ? 108 : 44 + nameEnd));
  return {
    ok: true,
    packet: {
      cid,
      sourceName,
      priority,
      syncAddress: u16(bytes, 109),
      sequence: bytes[111],
      preview: (options & 0x80) !== 0,
      terminated,
      universe,
      // A copy into a plain Uint8Array (Buffer#slice would be a view of Node's datagram buffer).
      data: Uint8Array.from(bytes.subarray(126, 125 + count)),
    },
  };
}
