/**
 * mulberry32 (Tommy Ettinger's 32-bit generator): a small seeded generator, the same sequence on
 * every platform, for everything that must be reproducible (the surface textures' patterns, the
 * probe's gather directions). Returns numbers in [0, 1).
 */
export function mulberry32(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
