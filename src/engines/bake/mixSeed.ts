/**
 * One 32-bit seed from several integers (seed, surface, bounce): FNV-1a's
 * offset basis and prime (Fowler–Noll–Vo) with an xorshift-multiply finaliser
 * per value, so that neighbouring inputs give unrelated sample streams.
 */
export function mixSeed(...values: number[]): number {
  let h = 0x811c9dc5;
  for (const v of values) {
    h = Math.imul(h ^ (v >>> 0), 0x01000193) >>> 0;
    h ^= h >>> 15;
    h = Math.imul(h, 0x2c1b3c6d) >>> 0;
  }
  return h >>> 0;
}
