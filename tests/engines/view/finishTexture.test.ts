import { describe, expect, it } from 'vitest';
import { defaultSurfaceFinishes } from '../../../src/core/catalog/surfaceFinishes';
import { FINISH_TEXTURE_OF, FINISH_TEXTURES } from '../../../src/engines/view/finishTextureKinds';
import type { Rgb } from '../../../src/core/model/lightingScene/lightingScene';
import { encodeModulation, finishModulation, mipChain } from '../../../src/engines/view/finishTexture';

const rgb = (r: number | Rgb): Rgb => (typeof r === 'number' ? [r, r, r] : r);
const mean = (a: ArrayLike<number>) => {
  let s = 0;
  for (let i = 0; i < a.length; i++) s += a[i];
  return s / a.length;
};

describe('finish textures: mean exactly ρ', () => {
  // Every kind at a dark, a mid and the brightest finish reflectance, plus every catalogue finish with its own ρ.
  const cases: [string, (typeof FINISH_TEXTURES)[number], Rgb][] = [
    ...FINISH_TEXTURES.flatMap((k) => [0.1, 0.5, 0.9].map((r): [string, (typeof FINISH_TEXTURES)[number], Rgb] => [`${k} ρ=${r}`, k, [r, r, r]])),
    ...defaultSurfaceFinishes.map((f): [string, (typeof FINISH_TEXTURES)[number], Rgb] => [f.id, FINISH_TEXTURE_OF[f.id], rgb(f.reflectance)]),
  ];
  it.each(cases)('%s: mean 1 within 1e-6 per channel, 0 ≤ m, ρ·m ≤ 1, a visible but subtle pattern', (_, kind, rho) => {
    const mod = finishModulation(kind, rho);
    expect(mod.channels.every((c) => c.length === mod.size * mod.size)).toBe(true);
    mod.channels.forEach((c, k) => {
      expect(Math.abs(mean(c) - 1)).toBeLessThan(1e-6);
      let lo = Infinity;
      let hi = -Infinity;
      for (const v of c) {
        lo = Math.min(lo, v);
        hi = Math.max(hi, v);
      }
      expect(lo).toBeGreaterThanOrEqual(0);
      expect(rho[k] * hi).toBeLessThanOrEqual(1 + 1e-12);
      // Subtle: no texel beyond ±35 % (grout and joints are the deepest), and a pattern at all.
      expect(hi).toBeLessThan(1.35);
      expect(lo).toBeGreaterThan(0.65);
      expect(hi - lo).toBeGreaterThan(0.02);
    });
  });

  it('is deterministic for a seed and differs between seeds', () => {
    const a = finishModulation('concrete', [0.4, 0.4, 0.4], 3);
    const b = finishModulation('concrete', [0.4, 0.4, 0.4], 3);
    const c = finishModulation('concrete', [0.4, 0.4, 0.4], 4);
    expect(Array.from(a.channels[0].slice(0, 500))).toEqual(Array.from(b.channels[0].slice(0, 500)));
    expect(Array.from(a.channels[0].slice(0, 500))).not.toEqual(Array.from(c.channels[0].slice(0, 500)));
  });

  it('has the real sizes: planks 0.18 m wide, tiles 0.6 m', () => {
    // A joint lies on the texel rows at every plank (tile) edge: the darker of the two rows beside
    // the edge is at least 4 % below the rows 4 to 8 texels (1 to 2 cm) away; mid-plank rows are not.
    const seam = (kind: 'wood' | 'tiles', width: number) => {
      const m = finishModulation(kind, [0.3, 0.3, 0.3]);
      const rows = Array.from({ length: m.size }, (_, j) => mean(m.channels[0].subarray(j * m.size, (j + 1) * m.size)));
      const at = (j: number) => rows[((j % m.size) + m.size) % m.size];
      const dip = (j: number) => Math.min(at(j), at(j - 1)) / mean([4, 5, 6, 7, 8].flatMap((d) => [at(j + d), at(j - 1 - d)]));
      const step = (width / m.period) * m.size;
      expect(Number.isInteger(step)).toBe(true);
      const edges = Array.from({ length: m.size / step }, (_, k) => k * step);
      return { edges: edges.map(dip), middles: edges.map((j) => dip(j + step / 2)) };
    };
    for (const [kind, width] of [
      ['wood', 0.18],
      ['tiles', 0.6],
    ] as const) {
      const { edges, middles } = seam(kind, width);
      edges.forEach((d) => expect(d).toBeLessThan(0.96));
      middles.forEach((d) => expect(d).toBeGreaterThan(0.96));
    }
  });

  it('8-bit encoding: the gain puts the decoded mean back at 1 within 1e-6', () => {
    for (const kind of FINISH_TEXTURES) {
      const { data, gain } = encodeModulation(finishModulation(kind, [0.5, 0.4, 0.3]));
      for (let c = 0; c < 3; c++) {
        let s = 0;
        for (let k = c; k < data.length; k += 4) s += (data[k] / 255) * gain[c];
        expect(Math.abs(s / (data.length / 4) - 1)).toBeLessThan(1e-6);
        expect(Math.abs(gain[c] - 2)).toBeLessThan(0.01);
      }
    }
  });

  it('mip chain: every level keeps the base mean within a tenth of a byte step', () => {
    const mod = finishModulation('carpet', [0.3, 0.3, 0.3]);
    const { data } = encodeModulation(mod);
    const levels = mipChain(data, mod.size);
    expect(levels.map((l) => l.width)).toEqual([256, 128, 64, 32, 16, 8, 4, 2, 1]);
    const base = mean(Array.from(data.filter((_, k) => k % 4 === 0)));
    for (const l of levels.slice(0, 6)) expect(Math.abs(mean(Array.from(l.data.filter((_, k) => k % 4 === 0))) - base)).toBeLessThan(0.1);
  });

  it('every shipped finish has a texture kind, and every kind named is a shipped finish', () => {
    expect(defaultSurfaceFinishes.every((f) => FINISH_TEXTURES.includes(FINISH_TEXTURE_OF[f.id]))).toBe(true);
    expect(Object.keys(FINISH_TEXTURE_OF).every((id) => defaultSurfaceFinishes.some((f) => f.id === id))).toBe(true);
  });
});
