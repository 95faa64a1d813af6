import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import type { FinishTexture } from './finishTextureKinds';
import { mulberry32 } from '../../core/mulberry32';

/**
 * A finish's surface pattern as a modulation m(u, v) of its reflectance, tiling a square of
 * `period` metres in `size` × `size` texels. The 3D view shows L = E·ρ·m/π; because the mean
 * of m over one period is exactly 1 per channel, the mean displayed reflectance is the ρ the
 * baker used, so the light (what every pixel follows from) stays right (docs/viewer.md,
 * "Surface textures"). m ≥ 0 and ρ·m ≤ 1 per channel: no texel reflects more than it receives.
 */
export interface FinishModulation {
  kind: FinishTexture;
  /** Side of the tiling square in metres: the pattern's real size. */
  period: number;
  size: number;
  /** m per channel, row-major (v rows of u texels), mean exactly 1 per channel. */
  channels: [Float64Array, Float64Array, Float64Array];
}

interface KindRecipe {
  period: number;
  size: number;
  /** Largest relative deviation wanted (before the ρ·m ≤ 1 cap): keeps the pattern subtle. */
  amplitude: number;
  /** Per channel exponent on the raw field: > 1 darkens the dark parts more in that channel (wood grain grows warmer). */
  tint: Rgb;
  field: (x: number, y: number, noise: NoiseSet) => number;
}

/** Periodic value noise on a cx × cy lattice over the unit square (smoothstep between lattice values, wrapping), values in [0, 1]. */
function periodicNoise(cx: number, cy: number, random: () => number): (x: number, y: number) => number {
  const lattice = Float64Array.from({ length: cx * cy }, () => random());
  const at = (i: number, j: number) => lattice[(((j % cy) + cy) % cy) * cx + (((i % cx) + cx) % cx)];
  const smooth = (t: number) => t * t * (3 - 2 * t);
  return (x, y) => {
    const fx = x * cx;
    const fy = y * cy;
    const i = Math.floor(fx);
    const j = Math.floor(fy);
    const sx = smooth(fx - i);
    const sy = smooth(fy - j);
    const a = at(i, j) + (at(i + 1, j) - at(i, j)) * sx;
    const b = at(i, j + 1) + (at(i + 1, j + 1) - at(i, j + 1)) * sx;
    return a + (b - a) * sy;
  };
}

interface NoiseSet {
  /** Octaves on square lattices of n cells per period. */
  octave(n: number): (x: number, y: number) => number;
  /** Stretched noise: cx cells along x, cy along y. */
  stretched(cx: number, cy: number): (x: number, y: number) => number;
  random: () => number;
}

function noiseSet(seed: number): NoiseSet {
  const random = mulberry32(seed);
  const cache = new Map<string, (x: number, y: number) => number>();
  const stretched = (cx: number, cy: number) => {
    const key = `${cx}x${cy}`;
    let n = cache.get(key);
    if (!n) cache.set(key, (n = periodicNoise(cx, cy, random)));
    return n;
  };
  return { octave: (n) => stretched(n, n), stretched, random };
}

const fbm = (noise: NoiseSet, x: number, y: number, cells: readonly number[]) => {
  let sum = 0;
  let weight = 0;
  cells.forEach((c, k) => {
    const w = 0.6 ** k;
    sum += w * noise.octave(c)(x, y);
    weight += w;
  });
  return sum / weight;
};

/** A fixed per-cell random value (planks, tiles), seeded by the cell's index. */
const cellValue = (seed: number, i: number, j: number) => mulberry32(seed ^ Math.imul(i + 1, 73856093) ^ Math.imul(j + 1, 19349663))();

/** Planks 0.18 m wide and 0.72 m long (a 1.44 m period: 8 rows, 2 planks a row, rows staggered), lengthwise grain, dark joints. */
function woodField(x: number, y: number, noise: NoiseSet): number {
  const rows = 8;
  const row = Math.floor(y * rows);
  const offset = cellValue(11, row, 0) * 0.5;
  const along = (x + offset) * 2;
  const plank = Math.floor(along);
  const ay = y * rows - row;
  const ax = along - plank;
  const joint = Math.min(ay, 1 - ay) * 0.18 < 0.0015 || Math.min(ax, 1 - ax) * 0.72 < 0.0015 ? 0.7 : 1;
  const tone = 0.85 + 0.3 * cellValue(17, row, ((plank % 2) + 2) % 2);
  // Grain: many cells across the plank, few along it (fibres run the plank's length).
  const grain = 0.75 + 0.5 * noise.stretched(6, 160)(x + offset, y) * (0.6 + 0.4 * noise.stretched(3, 48)(x, y));
  return joint * tone * grain;
}

/**
 * Wood veneer on furniture: one sheet, no plank joints (a table top is not a floor), grain lines
 * about 3 cm apart along u that wander slowly (12 per 0.4 m period, warped by a coarse noise), with fine
 * fibres along them. All its variation is fine, so a table top's mean under a pool of light is the
 * pattern's mean (tests/engines/view/objectWoodTexture.test.ts).
 */
function veneerField(x: number, y: number, noise: NoiseSet): number {
  const t = y * 12 + 1.5 * fbm(noise, x, y, [2, 4]);
  const line = 0.5 - 0.5 * Math.cos(2 * Math.PI * t);
  return 0.8 + 0.35 * line * line + 0.1 * noise.stretched(4, 256)(x, y);
}

/** Square tiles 0.6 m (a 1.2 m period of 2 × 2), grout joints 5 mm, a slight per-tile shade and a fine mottle. */
function tileField(x: number, y: number, noise: NoiseSet): number {
  const n = 2;
  const i = Math.floor(x * n);
  const j = Math.floor(y * n);
  const gx = Math.min(x * n - i, 1 - (x * n - i)) * 0.6;
  const gy = Math.min(y * n - j, 1 - (y * n - j)) * 0.6;
  if (Math.min(gx, gy) < 0.0025) return 0.72;
  return (0.94 + 0.12 * cellValue(23, i, j)) * (0.92 + 0.16 * fbm(noise, x, y, [16, 48, 128]));
}

const RECIPES: Record<FinishTexture, KindRecipe> = {
  // Painted plaster: a soft trowel mottle of 3 to 25 cm.
  plaster: { period: 1, size: 256, amplitude: 0.06, tint: [1, 1, 1], field: (x, y, noise) => fbm(noise, x, y, [4, 8, 16, 32]) },
  wood: { period: 1.44, size: 512, amplitude: 0.22, tint: [1, 1.15, 1.35], field: woodField },
  veneer: { period: 0.4, size: 512, amplitude: 0.18, tint: [1, 1.15, 1.35], field: veneerField },
  tiles: { period: 1.2, size: 512, amplitude: 0.2, tint: [1, 1, 1], field: tileField },
  // Concrete: cloudy patches of 10 to 50 cm with small dark pores.
  concrete: {
    period: 2,
    size: 512,
    amplitude: 0.15,
    tint: [1, 1, 1],
    field: (x, y, noise) => fbm(noise, x, y, [4, 10, 24, 64]) * (noise.octave(200)(x, y) > 0.93 ? 0.8 : 1),
  },
  // Carpet: pile speckle of a few millimetres over a faint cloud.
  carpet: { period: 0.5, size: 256, amplitude: 0.14, tint: [1, 1, 1], field: (x, y, noise) => 0.6 * noise.octave(128)(x, y) + 0.25 * noise.octave(40)(x, y) + 0.15 * noise.octave(4)(x, y) },
  // Fabric: a plain weave of 2 mm threads (50 per 0.1 m period), warp and weft alternating.
  fabric: {
    period: 0.1,
    size: 256,
    amplitude: 0.12,
    tint: [1, 1, 1],
    field: (x, y, noise) => {
      const threads = 50;
      const i = Math.floor(x * threads);
      const j = Math.floor(y * threads);
      const warpOnTop = (i + j) % 2 === 0;
      const across = warpOnTop ? x * threads - i : y * threads - j;
      return (0.7 + 0.3 * Math.sin(Math.PI * across)) * (0.9 + 0.1 * noise.octave(10)(x, y));
    },
  },
};

/** The modulation for one finish: `kind`'s pattern, seeded by `seed`, normalised to mean 1 and capped so that ρ·m ≤ 1 and m ≥ 0. */
export function finishModulation(kind: FinishTexture, reflectance: Rgb, seed = 1): FinishModulation {
  const recipe = RECIPES[kind];
  const { size } = recipe;
  const noise = noiseSet(seed * 2654435761 + kind.length);
  const raw = new Float64Array(size * size);
  for (let j = 0; j < size; j++) for (let i = 0; i < size; i++) raw[j * size + i] = Math.max(recipe.field((i + 0.5) / size, (j + 0.5) / size, noise), 1e-3);
  const channels = [0, 1, 2].map((c) => {
    const f = raw.map((v) => v ** recipe.tint[c]);
    let mean = 0;
    for (const v of f) mean += v;
    mean /= f.length;
    let lo = Infinity;
    let hi = -Infinity;
    for (const v of f) {
      lo = Math.min(lo, v / mean - 1);
      hi = Math.max(hi, v / mean - 1);
    }
    // Scale the deviations (an affine map keeps the mean at exactly 1): at most the recipe's
    // amplitude, never below 0, never above 1/ρ (a texel reflecting more than it receives).
    const limit = Math.min(recipe.amplitude / Math.max(hi, -lo, 1e-12), 0.95 / Math.max(-lo, 1e-12), (1 / Math.max(reflectance[c], 1e-6) - 1) / Math.max(hi, 1e-12));
    const m = f.map((v) => 1 + limit * (v / mean - 1));
    // Remove the last rounding residue of the sum so the mean is 1 to double precision.
    let sum = 0;
    for (const v of m) sum += v;
    const residue = sum / m.length - 1;
    return m.map((v) => v - residue);
  }) as [Float64Array, Float64Array, Float64Array];
  return { kind, period: recipe.period, size, channels };
}

/** RGBA8 texels for the GPU and the per-channel gain that puts the 8-bit mean back at exactly 1: m ≈ (byte/255)·gain. Bytes store m/2 (m < 2). */
export function encodeModulation(mod: FinishModulation): { data: Uint8Array; gain: Rgb } {
  const n = mod.size * mod.size;
  const data = new Uint8Array(n * 4);
  const gain: Rgb = [1, 1, 1];
  for (let c = 0; c < 3; c++) {
    let sum = 0;
    for (let k = 0; k < n; k++) {
      const b = Math.min(255, Math.max(0, Math.round((mod.channels[c][k] / 2) * 255)));
      data[k * 4 + c] = b;
      sum += b / 255;
    }
    gain[c] = n / sum;
  }
  for (let k = 0; k < n; k++) data[k * 4 + 3] = 255;
  return { data, gain };
}

/**
 * The mip chain of an RGBA8 square texture, level 0 first: 2×2 box means rounded to the nearest
 * byte (halves alternately up and down). Made here, not by the GPU's generateMipmap, whose 8-bit rounding is the driver's (a
 * truncating one lowered the mean by about 1 % three levels down): rounding to nearest keeps each
 * level's mean at the base's, so a floor seen from afar keeps its ρ.
 */
export function mipChain(data: Uint8Array, size: number): { data: Uint8Array; width: number; height: number }[] {
  const levels = [{ data, width: size, height: size }];
  let prev = data;
  for (let s = size >> 1; s >= 1; s >>= 1) {
    const next = new Uint8Array(s * s * 4);
    const ps = s * 2;
    for (let j = 0; j < s; j++)
      for (let i = 0; i < s; i++)
        for (let c = 0; c < 4; c++) {
          const a = (2 * j * ps + 2 * i) * 4 + c;
          // Halves round up on one colour of a checkerboard and down on the other: no drift level by level.
          next[(j * s + i) * 4 + c] = (prev[a] + prev[a + 4] + prev[a + ps * 4] + prev[a + ps * 4 + 4] + ((i + j) & 1 ? 1 : 2)) >> 2;
        }
    levels.push({ data: next, width: s, height: s });
    prev = next;
  }
  return levels;
}
