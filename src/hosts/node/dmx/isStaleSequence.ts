/**
 * The out-of-order check luxbox applies to both protocols (docs/dmx.md, "Sequence numbers"): a
 * packet whose sequence number is 1 to 19 steps behind the last accepted one (modulo 256, as a
 * signed 8-bit difference) is late and discarded; any other difference is new data.
 *
 * E1.31-2018 §6.7.2 discards a difference in (−20, 0], that is also an **equal** number. That
 * freezes a sender that never increments its sequence field (after its first packet every packet
 * differs by 0), and such consoles and cheap nodes exist (issue 32). An equal number is therefore
 * accepted: from a correct sender it can only be a duplicate of the packet just applied (the same
 * data: applying it again changes nothing), from a stuck sender it is the next look.
 *
 * Art-Net 4 (ArtDmx, Sequence) uses the same byte with 0 meaning "sequencing disabled": callers
 * skip the check when either number is 0. A source whose packets have all been discarded for
 * SEQUENCE_RESYNC_MS is followed again whatever its number (createUniverseStore).
 */
export function isStaleSequence(last: number, next: number): boolean {
  // The difference as a signed 8-bit number, the arithmetic §6.7.2 prescribes.
  const diff = (((next - last) & 0xff) << 24) >> 24;
  return diff < 0 && diff > -20;
}
