/**
 * ArtDmx parser (Art-Net 4, "ArtDmx" packet definition). Hand-written: the packet is one fixed
 * layout, and the bridge reads it from the network, so every field is checked against the bytes
 * that actually arrived before it is used (docs/dmx.md, "Why no protocol library").
 *
 * Layout (offsets in bytes):
 *   0  ID[8]        "Art-Net\0"
 *   8  OpCode       0x5000, little-endian (the one little-endian field in Art-Net)
 *  10  ProtVerHi/Lo protocol version, big-endian, 14 for Art-Net 4 (receivers reject lower)
 *  12  Sequence     1–255, 0 = sequencing disabled
 *  13  Physical     input port the data came from (information only)
 *  14  SubUni       low byte of the 15-bit Port-Address (Sub-Net in the high nibble, Universe low)
 *  15  Net          bits 14–8 of the Port-Address (the top bit of the byte is not part of it)
 *  16  LengthHi/Lo  number of DMX slots, big-endian, 2–512 (Art-Net asks for an even count;
 *                   odd counts from real consoles are accepted, 1–512)
 *  18  Data[Length]
 */

export const ARTNET_ID = 'Art-Net\0';
export const OP_DMX = 0x5000;
/** Art-Net 4: ArtDmx is valid from protocol version 14. */
export const MIN_PROTOCOL_VERSION = 14;
export const ARTDMX_HEADER_BYTES = 18;
export const DMX_SLOTS = 512;

export interface ArtDmxPacket {
  sequence: number;
  physical: number;
  /** The 15-bit Port-Address: Net << 8 | Sub-Net << 4 | Universe. */
  portAddress: number;
  /** The DMX slots as sent (1–512 of them); missing slots read as 0 downstream. */
  data: Uint8Array;
}

export type ArtNetIgnoreReason =
  /** Shorter than the 10 bytes of ID and OpCode, or than the ArtDmx header. */
  | 'too-short'
  /** Does not start with "Art-Net\0": not an Art-Net packet. */
  | 'not-art-net'
  /** A valid Art-Net packet of another kind (ArtPoll, ArtSync, ...): not DMX data. */
  | 'not-artdmx'
  | 'old-protocol'
  /** Length 0 or over 512, or more slots announced than the datagram carries. */
  | 'bad-length'
  /** More bytes than an ArtDmx packet can have (18 + 512). */
  | 'oversized';

export const ARTNET_IGNORE_REASONS: readonly ArtNetIgnoreReason[] = ['too-short', 'not-art-net', 'not-artdmx', 'old-protocol', 'bad-length', 'oversized'];

export type ArtDmxResult = { ok: true; packet: ArtDmxPacket } | { ok: false; reason: ArtNetIgnoreReason };

/** Parses one UDP datagram received on the Art-Net port; never throws. */
export function parseArtDmx(bytes: Uint8Array): ArtDmxResult {
  if (bytes.length < 10) return { ok: false, reason: 'too-short' };
  for (let i = 0; i < 8; i++) {
    if (bytes[i] !== ARTNET_ID.charCodeAt(i)) return { ok: false, reason: 'not-art-net' };
  }
  const opCode = bytes[8] | (bytes[9] << 8);
  if (opCode !== OP_DMX) return { ok: false, reason: 'not-artdmx' };
  if (bytes.length < ARTDMX_HEADER_BYTES) return { ok: false, reason: 'too-short' };
  if (bytes.length > ARTDMX_HEADER_BYTES + DMX_SLOTS) return { ok: false, reason: 'oversized' };
  const version = (bytes[10] << 8) | bytes[11];
  if (version < MIN_PROTOCOL_VERSION) return { ok: false, reason: 'old-protocol' };
  const length = (bytes[16] << 8) | bytes[17];
  if (length < 1 || length > DMX_SLOTS || ARTDMX_HEADER_BYTES + length > bytes.length) return { ok: false, reason: 'bad-length' };
  return {
    ok: true,
    packet: {
      sequence: bytes[12],
      physical: bytes[13],
      portAddress: ((bytes[15] & 0x7f) << 8) | bytes[14],
      // A copy into a plain Uint8Array (Buffer#slice would be a view of Node's datagram buffer).
      data: Uint8Array.from(bytes.subarray(ARTDMX_HEADER_BYTES, ARTDMX_HEADER_BYTES + length)),
    },
  };
}
