/**
 * Relight per frame with 12 modules (docs/benchmarks.md, "Relight on the GPU"): today's CPU relight
 * (relightMaps.ts) against the GPU combine (createGpuRelight.ts), in one run on one headless-gl
 * context. The bases are the viewer's sizes (VIEWER_BAKE_SETTINGS: 5 cm texels, ≤ 256² per wall) of a
 * 5 × 4 × 2.7 m room, with one shared indirect solution; every frame changes all weights (a dimming
 * drag or a DMX stream). The GPU time includes gl.finish() (the wait for the draws), as a frame would
 * wait for them; CPU upload of the bases is once, before the timed frames.
 */
import type { Rgb } from '../../src/core/model/lightingScene/lightingScene';
import { surfaceLayouts } from '../../src/engines/bake/surfaceLayout';
import { createGpuRelight, type BasisPrecision } from '../../src/engines/relight/createGpuRelight';
import { VIEWER_BAKE_SETTINGS } from '../../src/engines/relight/createRelightEngine';
import { emptyLitMaps, relightMaps, type DirectBasis, type IndirectSolution, type WeightedBasis } from '../../src/engines/relight/relightMaps';
import { createHeadlessGL } from '../../src/hosts/node/createHeadlessGL';

export interface GpuRelightBench {
  modules: number;
  texels: number;
  frames: number;
  cpuMs: number;
  /** The CPU relight plus what the view does with its result today (createRoomSurfaces.ts): RGB → RGBA and an RGBA32F texture upload per wall. */
  cpuUploadMs: number;
  gpuMs: Record<BasisPrecision, number>;
  readbacks: number;
  textureMiB: Record<BasisPrecision, number>;
}

const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

export function benchGpuRelight(modules = 12, frames = 41): GpuRelightBench {
  const layouts = surfaceLayouts({ width: 5, height: 2.7, depth: 4 }, VIEWER_BAKE_SETTINGS.texelSize!, VIEWER_BAKE_SETTINGS.maxTextureSize!);
  const byName = emptyLitMaps(layouts).layouts;
  const texels = layouts.reduce((s, l) => s + l.width * l.height, 0);
  let seed = 1;
  const random = () => ((seed = (seed * 16807) % 2147483647) - 1) / 2147483646;
  const map = (n: number) => Float32Array.from({ length: n * 3 }, () => 500 * random());
  const surfaces = () => Object.fromEntries(layouts.map((l) => [l.name, map(l.width * l.height)])) as DirectBasis['surfaces'];
  const bases: DirectBasis[] = Array.from({ length: modules }, () => ({ surfaces: surfaces(), flux: [1, 1, 1] }));
  const solution: IndirectSolution = { surfaces: surfaces(), flux: [1, 1, 1], key: 'k', final: true };
  const terms = [{ solution, scale: [1, 1, 1] as Rgb }];
  const weightsAt = (k: number): WeightedBasis[] => bases.map((basis, i) => ({ basis, weight: [0.5 + 0.4 * Math.sin(k + i), 0.5, 0.5 + 0.4 * Math.cos(k + i)] }));

  const out = emptyLitMaps(layouts);
  const cpu: number[] = [];
  for (let k = 0; k < frames; k++) {
    const s = performance.now();
    relightMaps(weightsAt(k), terms, null, out);
    cpu.push(performance.now() - s);
  }

  const gl = createHeadlessGL();
  const shown = layouts.map((l) => {
    const texture = gl.createTexture()!;
    gl.bindTexture(gl.TEXTURE_2D, texture);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, l.width, l.height, 0, gl.RGBA, gl.FLOAT, null);
    return { layout: l, texture, rgba: new Float32Array(l.width * l.height * 4) };
  });
  const cpuUpload: number[] = [];
  for (let k = 0; k < frames; k++) {
    const s = performance.now();
    relightMaps(weightsAt(k), terms, null, out);
    for (const { layout, texture, rgba } of shown) {
      const total = out.maps[layout.name].total;
      for (let i = 0, j = 0; i < total.length; i += 3, j += 4) {
        rgba[j] = total[i];
        rgba[j + 1] = total[i + 1];
        rgba[j + 2] = total[i + 2];
        rgba[j + 3] = 1;
      }
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, layout.width, layout.height, gl.RGBA, gl.FLOAT, rgba);
    }
    gl.finish();
    cpuUpload.push(performance.now() - s);
  }
  for (const { texture } of shown) gl.deleteTexture(texture);
  const gpuMs = {} as Record<BasisPrecision, number>;
  const textureMiB = {} as Record<BasisPrecision, number>;
  let readbacks = 0;
  try {
    for (const precision of ['float', 'half'] as const) {
      const gpu = createGpuRelight(gl, precision);
      gpu.relight(weightsAt(-1), terms, byName, null);
      gl.finish();
      const times: number[] = [];
      for (let k = 0; k < frames; k++) {
        const s = performance.now();
        gpu.relight(weightsAt(k), terms, byName, null);
        gl.finish();
        times.push(performance.now() - s);
      }
      gpuMs[precision] = median(times);
      textureMiB[precision] = gpu.textureBytes() / 2 ** 20;
      readbacks += gpu.readbacks.count;
      gpu.dispose();
    }
  } finally {
    gl.destroy();
  }
  return { modules, texels, frames, cpuMs: median(cpu), cpuUploadMs: median(cpuUpload), gpuMs, readbacks, textureMiB };
}
