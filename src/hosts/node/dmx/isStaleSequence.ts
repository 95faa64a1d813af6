/**
 * Sequence check of E1.31-2018 §6.7.2: a packet whose sequence number is 0 to 19 steps behind the
 * last accepted one (modulo 256) is out of order and discarded; any other difference is taken as
 * new data, which also lets a restarted source resynchronise at once.
 *
 * Art-Net 4 (ArtDmx, Sequence) uses the same byte with 0 meaning "sequencing disabled": callers
 * skip the check when either number is 0.
 */
export function isStaleSequence(last: number, next: number): boolean {
  // The difference as a signed 8-bit number, the arithmetic §6.7.2 prescribes.
  const diff = (((next - last) & 0xff) << 24) >> 24;
  return diff <= 0 && diff > -20;
}
