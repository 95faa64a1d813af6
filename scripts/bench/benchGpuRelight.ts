/**
 * Relight per frame with 12 modules (docs/benchmarks.md, "Relight on the GPU"): today's CPU relight
 * (relightMaps.ts) against the GPU combine (createGpuRelight.ts), in one run on one headless-gl
 * context. The bases are the viewer's sizes (VIEWER_BAKE_SETTINGS: 5 cm texels, ≤ 256² per wall) of a
 * 5 × 4 × 2.7 m room, with one shared indirect solution; every frame changes all weights (a dimming
 * drag or a DMX stream). The GPU time includes gl.finish() (the wait for the draws), as a frame would
 * wait for them; CPU upload of the bases is once, before the timed frames.
 */
import type { Rgb } from '../../src/core/model/lightingScene/lightingScene';
import { surfaceLayouts, type SurfaceLayout } from '../../src/engines/bake/surfaceLayout';
import { createGpuRelight, type BasisPrecision } from '../../src/engines/relight/createGpuRelight';
import { VIEWER_BAKE_SETTINGS } from '../../src/engines/relight/createRelightEngine';
import { emptyLitMaps, relightMaps, type DirectBasis, type IndirectSolution, type LitMaps, type WeightedBasis } from '../../src/engines/relight/relightMaps';
import { createHeadlessGL } from '../../src/hosts/node/createHeadlessGL';
import createGL from 'gl';
import * as THREE from 'three';
import type { RelightParts } from '../../src/engines/relight/RelightEngine';
import { createViewRelight } from '../../src/engines/view/createViewRelight';
import { floorStats } from '../../src/engines/view/lightStats';

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
  /** Today's view frame in full: the CPU relight, the upload, and the floor's statistics on the CPU (floorStats). */
  cpuViewMs: number;
  /** The view's GPU frame (createViewRelight in a three.js context, RGBA16F bases): the combine, the floor's statistics requested and read after the fence. */
  gpuViewMs: number;
  /** Per frame, CPU path and GPU path: maps and statistics texels read back, bytes read back and uploaded. */
  perFrame: Record<'cpu' | 'gpu', { mapReadbacks: number; readbackBytes: number; uploadBytes: number }>;
  /** The first GPU relight of the view: every basis and the solution uploaded (RGB → RGBA16F on the CPU, then texImage2D), and its bytes. */
  firstRelightMs: number;
  transferBytes: number;
}

/** A three.js renderer on its own headless-gl context, as the 3D view's (tests/engines/view/headlessRenderer.ts). */
function headlessThree(): { renderer: THREE.WebGLRenderer; destroy(): void } {
  const gl = createGL(64, 64, { createWebGL2Context: true, preserveDrawingBuffer: true, antialias: false }) as unknown as WebGL2RenderingContext & { getExtension(n: 'STACKGL_destroy_context'): { destroy(): void } | null };
  const canvas = { width: 64, height: 64, style: {}, addEventListener() {}, removeEventListener() {} } as unknown as HTMLCanvasElement;
  Object.defineProperty(gl, 'canvas', { value: canvas, configurable: true });
  const renderer = new THREE.WebGLRenderer({ canvas, context: gl, antialias: false });
  return {
    renderer,
    destroy() {
      renderer.dispose();
      gl.getExtension('STACKGL_destroy_context')?.destroy();
    },
  };
}

const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

/** The median of `frames` timed calls of `frame(k)`, milliseconds (each call timed alone, performance.now() around it). */
function medianFrameMs(frames: number, frame: (k: number) => void): number {
  const times: number[] = [];
  for (let k = 0; k < frames; k++) {
    const s = performance.now();
    frame(k);
    times.push(performance.now() - s);
  }
  return median(times);
}

/**
 * What the view does today with the CPU relight's result (createRoomSurfaces.ts): one RGBA32F
 * texture per wall, and per frame each wall's total RGB → RGBA and a texSubImage2D.
 */
function wallUploads(gl: WebGL2RenderingContext, layouts: readonly SurfaceLayout[]) {
  const shown = layouts.map((l) => {
    const texture = gl.createTexture()!;
    gl.bindTexture(gl.TEXTURE_2D, texture);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, l.width, l.height, 0, gl.RGBA, gl.FLOAT, null);
    return { layout: l, texture, rgba: new Float32Array(l.width * l.height * 4) };
  });
  return {
    upload(out: LitMaps) {
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
    },
    dispose() {
      for (const { texture } of shown) gl.deleteTexture(texture);
    },
  };
}

/**
 * The view's frame both ways, in one run: today's (relightMaps, the RGBA32F upload, floorStats on the
 * CPU) and the GPU path (createViewRelight's combine, the floor's statistics reduced on the GPU and
 * read after the fence), with what each reads back and uploads per frame.
 */
function benchViewFrames(frames: number, parts: (k: number) => RelightParts, out: ReturnType<typeof emptyLitMaps>, texels: number) {
  const three = headlessThree();
  const gl = three.renderer.getContext() as WebGL2RenderingContext;
  try {
    const walls = wallUploads(gl, Object.values(out.layouts));
    const cpuViewMs = medianFrameMs(frames, (k) => {
      const p = parts(k);
      relightMaps(p.parts, p.terms, null, out);
      walls.upload(out);
      floorStats(out);
      gl.finish();
    });
    walls.dispose();
    const view = createViewRelight(three.renderer, 'half', null);
    // The one transfer into the view's context: every basis and the solution uploaded by the first relight (its programs compiled by then too).
    const first = performance.now();
    view.relight(parts(-1));
    gl.finish();
    const firstRelightMs = performance.now() - first;
    const transferBytes = view.counters.uploads.bytes;
    const before = { uploads: view.counters.uploads.bytes, readbacks: view.counters.mapReadbacks.count };
    const gpuViewMs = medianFrameMs(frames, (k) => {
      const maps = view.relight(parts(k));
      const pending = view.floorStats(maps, null);
      gl.finish();
      if (!pending.poll()) throw new Error('the statistics fence had not signalled after gl.finish()');
    });
    const perFrame = {
      cpu: { mapReadbacks: 0, readbackBytes: 0, uploadBytes: texels * 16 },
      gpu: { mapReadbacks: (view.counters.mapReadbacks.count - before.readbacks) / frames, readbackBytes: view.counters.statsReadbacks.bytes / frames, uploadBytes: (view.counters.uploads.bytes - before.uploads) / frames },
    };
    view.dispose();
    return { cpuViewMs, gpuViewMs, perFrame, firstRelightMs, transferBytes };
  } finally {
    three.destroy();
  }
}

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
  const cpuMs = medianFrameMs(frames, (k) => relightMaps(weightsAt(k), terms, null, out));

  const gl = createHeadlessGL();
  const walls = wallUploads(gl, layouts);
  const cpuUploadMs = medianFrameMs(frames, (k) => {
    relightMaps(weightsAt(k), terms, null, out);
    walls.upload(out);
    gl.finish();
  });
  walls.dispose();
  const gpuMs = {} as Record<BasisPrecision, number>;
  const textureMiB = {} as Record<BasisPrecision, number>;
  let readbacks = 0;
  try {
    for (const precision of ['float', 'half'] as const) {
      const gpu = createGpuRelight(gl, precision);
      gpu.relight(weightsAt(-1), terms, byName, null);
      gl.finish();
      gpuMs[precision] = medianFrameMs(frames, (k) => {
        gpu.relight(weightsAt(k), terms, byName, null);
        gl.finish();
      });
      textureMiB[precision] = gpu.textureBytes() / 2 ** 20;
      readbacks += gpu.readbacks.count;
      gpu.dispose();
    }
  } finally {
    gl.destroy();
  }
  const partsAt = (k: number): RelightParts => ({ parts: weightsAt(k), terms, layouts: byName, atlas: null, version: k, fade: null });
  const view = benchViewFrames(frames, partsAt, out, texels);
  return { modules, texels, frames, cpuMs, cpuUploadMs, gpuMs, readbacks, textureMiB, ...view };
}
