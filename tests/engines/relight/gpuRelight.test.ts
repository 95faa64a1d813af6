/**
 * The GPU relight (createGpuRelight.ts, shaders/relightCombine.glsl.ts) against the CPU relight
 * (relightMaps.ts) on the same bases, in headless-gl: the direct and total maps of every wall and
 * of the objects' atlas agree per texel within 1e-5 relative (float32 rounding of a sum of up to
 * 13 terms, fused multiply-adds on the GPU: a few ulp). The weights and terms are the engine's own:
 * per-channel weights (dimming × CCT × filter), a crossfade blend of two solved solutions, and the
 * interim Φ_now/Φ_solve scale of indirectTerms.ts. Half-float bases add at most 0.1 % of the peak.
 */
import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES, type Rgb } from '../../../src/core/model/lightingScene/lightingScene';
import { surfaceLayouts, type SurfaceLayout } from '../../../src/engines/bake/surfaceLayout';
import type { ObjectAtlas } from '../../../src/engines/bake/objects/preparedObjects';
import { createGpuRelight, type GpuLitMaps } from '../../../src/engines/relight/createGpuRelight';
import { indirectTerms } from '../../../src/engines/relight/indirectTerms';
import { emptyLitMaps, relightMaps, type DirectBasis, type IndirectSolution, type IndirectTerm, type LitMaps, type WeightedBasis } from '../../../src/engines/relight/relightMaps';
import { createSolutionCache } from '../../../src/engines/relight/solutionCache';
import { createRng } from '../../fuzz/mutate';
import { withHeadlessGL } from '../bake/withHeadlessGL';

const gl = withHeadlessGL();
const layouts = surfaceLayouts({ width: 3, height: 2.5, depth: 2 }, 0.1, 256);
const byName = emptyLitMaps(layouts).layouts;
const atlas: ObjectAtlas = { width: 24, height: 16, texelSize: 0.05, position: new Float32Array(0), normal: new Float32Array(0), reflectance: new Float32Array(0) } as unknown as ObjectAtlas;
const random = createRng(34).next;

/** Lux-like values: mostly tens to hundreds, a few hot texels near a lamp (up to ~20 000). */
const map = (texels: number) => Float32Array.from({ length: texels * 3 }, () => (random() < 0.02 ? 20000 * random() : 400 * random() * random()));
const texelsOf = (l: SurfaceLayout) => l.width * l.height;

function basis(): DirectBasis {
  const surfaces = Object.fromEntries(layouts.map((l) => [l.name, map(texelsOf(l))])) as DirectBasis['surfaces'];
  const shown = map(atlas.width * atlas.height);
  return { surfaces, objects: { atlas, emitted: shown, shown }, flux: [1 + random(), 1 + random(), 1 + random()] };
}

function solution(key: string): IndirectSolution {
  const surfaces = Object.fromEntries(layouts.map((l) => [l.name, map(texelsOf(l))])) as IndirectSolution['surfaces'];
  return { surfaces, objects: map(atlas.width * atlas.height), flux: [10 + random(), 10 + random(), 10 + random()], key, final: true };
}

const bases = Array.from({ length: 12 }, basis);
/** Dimming × colour per channel; one module off (weight 0: skipped by both). */
const weights: Rgb[] = bases.map((_, i) => (i === 5 ? [0, 0, 0] : [0.2 + random(), 0.2 + random() * 0.8, 0.1 + random() * 0.5]));
const parts: WeightedBasis[] = bases.map((b, i) => ({ basis: b, weight: weights[i] }));

/** Worst per-texel |gpu − cpu| / max(|cpu|, 1e-3 lx) over the direct and total maps of every receiver. */
function worstRelative(gpu: GpuLitMaps, cpu: LitMaps, read: (t: GpuLitMaps['floor']['direct']) => Float32Array): { relative: number; peakRelative: number } {
  let relative = 0;
  let worst = 0;
  let peak = 0;
  const receivers = [...SURFACE_NAMES.map((n) => [gpu[n], cpu.maps[n]] as const), [gpu.objects!, cpu.maps.objects!] as const];
  for (const [g, c] of receivers) {
    for (const kind of ['direct', 'total'] as const) {
      const a = read(g[kind]);
      const b = c[kind];
      expect(a.length).toBe(b.length);
      for (let i = 0; i < b.length; i++) {
        const d = Math.abs(a[i] - b[i]);
        relative = Math.max(relative, d / Math.max(Math.abs(b[i]), 1e-3));
        worst = Math.max(worst, d);
        peak = Math.max(peak, Math.abs(b[i]));
      }
    }
  }
  return { relative, peakRelative: worst / peak };
}

function compare(terms: IndirectTerm[], precision: 'float' | 'half' = 'float') {
  const gpuRelight = createGpuRelight(gl, precision);
  try {
    const gpu = gpuRelight.relight(parts, terms, byName, atlas);
    expect(gpuRelight.readbacks.count).toBe(0);
    const cpu = relightMaps(parts, terms, atlas, emptyLitMaps(layouts));
    return { ...worstRelative(gpu, cpu, (t) => gpuRelight.read(t)), gpuRelight };
  } finally {
    gpuRelight.dispose();
  }
}

describe('GPU relight = CPU relight (relightMaps) on the same bases', () => {
  it('direct only (no indirect term) and an exact solve: within 1e-5 relative per texel', () => {
    expect(compare([]).relative).toBeLessThan(1e-5);
    expect(compare([{ solution: solution('a'), scale: [1, 1, 1] }]).relative).toBeLessThan(1e-5);
  });

  it('a crossfade between two solved weightings (indirectTerms: (1 − e)·I_A + e·I_B)', () => {
    const cache = createSolutionCache();
    const a = solution('A');
    const b = solution('B');
    cache.remember(a);
    cache.remember(b);
    const terms = indirectTerms('mid', parts, cache, null, { fromKey: 'A', toKey: 'B', e: 0.37 });
    expect(terms.map((t) => t.scale[0])).toEqual([1 - 0.37, 0.37]);
    expect(compare(terms).relative).toBeLessThan(1e-5);
  });

  it('the interim Φ_now/Φ_solve scale between a weight change and the re-solve (per channel)', () => {
    const latest = solution('old');
    const terms = indirectTerms('new', parts, createSolutionCache(), latest, null);
    expect(terms).toHaveLength(1);
    expect(terms[0].scale[0]).not.toBeCloseTo(terms[0].scale[2], 3);
    expect(compare(terms).relative).toBeLessThan(1e-5);
  });

  it('makes no read-back while relighting, and a weight change reuses the uploaded bases', () => {
    const gpuRelight = createGpuRelight(gl);
    try {
      const terms = [{ solution: solution('a'), scale: [1, 1, 1] as Rgb }];
      gpuRelight.relight(parts, terms, byName, atlas);
      const bytes = gpuRelight.textureBytes();
      for (let k = 1; k <= 10; k++)
        gpuRelight.relight(
          parts.map((p) => ({ ...p, weight: p.weight.map((w) => w * (k / 10)) as Rgb })),
          terms,
          byName,
          atlas,
        );
      expect(gpuRelight.readbacks).toEqual({ count: 0, bytes: 0 });
      expect(gpuRelight.textureBytes()).toBe(bytes);
      // 12 bases: two draws for each direct map (8 + 4; the off module skipped), one for each total map.
      expect(gpuRelight.draws).toBe(11 * 7 * 3);
    } finally {
      gpuRelight.dispose();
    }
  });

  it('half-float (RGBA16F) bases add at most 0.1 % of the peak and halve their memory', () => {
    const terms = [{ solution: solution('a'), scale: [1, 1, 1] as Rgb }];
    const full = compare(terms, 'float');
    const half = compare(terms, 'half');
    // binary16 rounded to nearest errs at most u = 2^-11 of each value (halfFloat.ts); a weighted sum of positive
    // values then errs at most u of its own size, hence of the peak: 0.049 %, under the 0.1 % the issue allows.
    expect(half.peakRelative).toBeLessThanOrEqual(2 ** -11);
    expect(half.peakRelative).toBeGreaterThan(full.peakRelative);
    const texels = layouts.reduce((s, l) => s + texelsOf(l), 0) + atlas.width * atlas.height;
    // 11 bases lit (the off module is never uploaded) and one indirect solution, 8 bytes less per texel each.
    const mapTexels = texels * 12;
    const g32 = createGpuRelight(gl, 'float');
    const g16 = createGpuRelight(gl, 'half');
    try {
      g32.relight(parts, terms, byName, atlas);
      g16.relight(parts, terms, byName, atlas);
      expect(g32.textureBytes() - g16.textureBytes()).toBe(mapTexels * 8);
      expect(g16.textureBytes()).toBeGreaterThan(mapTexels * 8);
    } finally {
      g32.dispose();
      g16.dispose();
    }
  });
});
