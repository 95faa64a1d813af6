/**
 * The 3D view's relight in its own context (docs/viewer.md, "Relighting on the GPU"): the relight
 * engine bakes on one headless-gl context (the bake service's), the view draws with three.js on
 * another; the engine's parts (bases read back once, the indirect terms) are combined by
 * createViewRelight in the view's context and drawn through THREE.ExternalTexture. Against the CPU
 * relight of the same engine (engine.maps(), uploaded as today): the display maps, the drawn
 * radiance and the floor statistics agree; a crossfade and a dimming make no map read-back, no CPU
 * relight and upload nothing after the first relight.
 */
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { reflectanceRgb } from '../../../src/engines/bake/bakeScene';
import { readRgb } from '../../../src/engines/bake/floatTarget';
import { createRelightEngine } from '../../../src/engines/relight/createRelightEngine';
import { createRoomSurfaces } from '../../../src/engines/view/createRoomSurfaces';
import { createViewRelight, LOW_MEMORY_RELIGHT_BYTES } from '../../../src/engines/view/createViewRelight';
import { floorStats, type IlluminanceStats } from '../../../src/engines/view/lightStats';
import { withHeadlessGL } from '../bake/withHeadlessGL';
import { relightTestRoom, relightTestSettings, threeLampScenes, fadeScenes } from '../relight/threeLampScenes';
import { COMPLETION_STATUS_KHR } from '../../../src/engines/bake/glResources';
import { headlessRenderer } from './headlessRenderer';

const bakeGl = withHeadlessGL();
const W = 96;
const renderer = headlessRenderer(W, W);
const viewGl = renderer.getContext() as WebGL2RenderingContext;
const SETTINGS = relightTestSettings(9);
const room = relightTestRoom;
/** Three spots with per-lamp dimming and colour (a light scene's look as toLightingScene hands it over). */
const scene = threeLampScenes({ flux: [1200, 300], beamDegrees: 35, pitchStep: 10, x: [0.8, 1.2], z: [0.9, 0.5] });
const { A, B } = fadeScenes(scene);

/** The floor seen straight down by an orthographic camera framing it exactly, drawn as exposed linear radiance (mode 2, before the tone curve). */
function drawFloor(surfaces: ReturnType<typeof createRoomSurfaces>, scene3: THREE.Scene): Float32Array {
  const camera = new THREE.OrthographicCamera(-room.width / 2, room.width / 2, room.depth / 2, -room.depth / 2, 0.1, 20);
  camera.position.set(room.width / 2, 2, room.depth / 2);
  camera.up.set(0, 0, -1);
  camera.lookAt(room.width / 2, 0, room.depth / 2);
  surfaces.display.uMode.value = 2;
  const target = new THREE.WebGLRenderTarget(W, W, { type: THREE.FloatType });
  renderer.setRenderTarget(target);
  renderer.render(scene3, camera);
  renderer.setRenderTarget(null);
  const out = new Float32Array(W * W * 4);
  renderer.readRenderTargetPixels(target, 0, 0, W, W, out);
  target.dispose();
  return out;
}

const worst = (a: ArrayLike<number>, b: ArrayLike<number>) => {
  let d = 0;
  let peak = 0;
  for (let i = 0; i < a.length; i++) {
    d = Math.max(d, Math.abs(a[i] - b[i]));
    peak = Math.max(peak, Math.abs(b[i]));
  }
  return { d, peak };
};

function settled(p: { poll(): IlluminanceStats | null }): IlluminanceStats {
  for (let i = 0; i < 10000; i++) {
    const s = p.poll();
    if (s) return s;
  }
  throw new Error('the statistics fence never signalled');
}

describe('the view relights on its own GPU', () => {
  const engine = createRelightEngine(bakeGl, SETTINGS);
  engine.setScene(A);
  engine.finish();
  engine.setScene(B);
  engine.finish();

  it.each([
    ['float', 1e-5],
    ['half', 1e-3],
  ] as const)('%s bases: a crossfade and a dimming show the CPU relight (floor map within %s of the peak), with no map read back and every map uploaded once at most', (precision, tolerance) => {
    const relight = createViewRelight(renderer, precision, null);
    try {
      const relightsBefore = engine.counters.relights;
      const fractions = [0, 0.1, 0.25, 0.4, 0.5, 0.6, 0.75, 0.9, 1];
      let measured = 0;
      for (const e of fractions) {
        engine.setFade({ from: A, e });
        const parts = engine.relightParts()!;
        const maps = relight.relight(parts);
        // The reference: the CPU relight of the same engine. Reading the display map back is the test's own read (not the view's counter).
        const gpuFloor = readRgb(viewGl, maps.floor);
        const cpu = engine.maps();
        const { d, peak } = worst(gpuFloor, cpu.maps.floor.total);
        measured = Math.max(measured, d / peak);
        expect(d).toBeLessThanOrEqual(tolerance * peak);
      }
      engine.setFade(null);
      // Each map uploaded once at most: 3 bases and the 2 solutions, 6 receivers each.
      const uploadsAfterFade = relight.counters.uploads.count;
      expect(uploadsAfterFade).toBeLessThanOrEqual(5 * 6);
      // Dimming the second module: a relight (no basis bake); the indirect light is the Φ-scaled interim until the re-solve.
      engine.setScene(
        scene([
          [0.2, [1, 0.8, 0.6]],
          [0.45, [0.9, 0.95, 1]],
          [0.8, [1, 0.7, 0.4]],
        ]),
      );
      const maps = relight.relight(engine.relightParts()!);
      const { d, peak } = worst(readRgb(viewGl, maps.floor), engine.maps().maps.floor.total);
      expect(d).toBeLessThanOrEqual(tolerance * peak);
      // Only the engine.maps() calls of the references summed on the CPU (one each), never the GPU relights.
      expect(engine.counters.relights - relightsBefore).toBeLessThanOrEqual(fractions.length + 1);
      expect(relight.counters.mapReadbacks.count).toBe(0);
      expect(relight.counters.uploads.count).toBe(uploadsAfterFade);
      expect(relight.counters.relights).toBe(fractions.length + 1);
      console.info(
        `view relight (${precision} bases): worst floor texel ${(measured * 100).toExponential(2)} % of the peak; ${relight.counters.uploads.count} maps uploaded once (${relight.counters.uploads.bytes} B); texture memory ${relight.textureBytes()} B`,
      );
      engine.setScene(B);
      engine.finish();
    } finally {
      relight.dispose();
    }
  });

  it('three draws the relight textures as it draws the uploaded CPU maps (exposed radiance within 1e-5 of the peak), and the floor statistics come from the GPU reduction', () => {
    const relight = createViewRelight(renderer, 'float', null);
    const scene3 = new THREE.Scene();
    const surfaces = createRoomSurfaces(scene3, renderer);
    try {
      surfaces.setExposure(0.01);
      surfaces.setFinishTextures(false);
      engine.setFade({ from: A, e: 0.3 });
      const cpu = engine.maps();
      surfaces.setMaps(cpu, reflectanceRgb(room));
      const drawnCpu = drawFloor(surfaces, scene3);
      const cpuStats = floorStats(cpu);
      // Another fraction on the CPU first, so that the GPU relight must be what changes the picture back.
      engine.setFade({ from: A, e: 0.8 });
      surfaces.setMaps(engine.maps(), reflectanceRgb(room));
      engine.setFade({ from: A, e: 0.3 });
      const maps = relight.relight(engine.relightParts()!);
      surfaces.setLightTextures(maps.surfaces);
      const drawnGpu = drawFloor(surfaces, scene3);
      const { d, peak } = worst(drawnGpu, drawnCpu);
      expect(peak).toBeGreaterThan(0);
      expect(d).toBeLessThanOrEqual(1e-5 * peak);
      const stats = settled(relight.floorStats(maps, null));
      expect(stats.avg).toBeCloseTo(cpuStats.avg, 3);
      expect(Math.abs(stats.avg / cpuStats.avg - 1)).toBeLessThan(1e-5);
      expect(Math.abs(stats.min - cpuStats.min)).toBeLessThanOrEqual(1e-6 * cpuStats.max);
      expect(Math.abs(stats.max - cpuStats.max)).toBeLessThanOrEqual(1e-6 * cpuStats.max);
      expect(stats.points).toBe(cpuStats.points);
      // The statistics cost one 16-byte texel, no map.
      expect(relight.counters.statsReadbacks).toEqual({ count: 1, bytes: 16 });
      expect(relight.counters.mapReadbacks.count).toBe(0);
      engine.setFade(null);
    } finally {
      surfaces.dispose();
      relight.dispose();
    }
  });

  it('the relight waits for its programs where KHR_parallel_shader_compile says they are still compiling (the CPU path shows meanwhile), and never on headless-gl, which has no such extension', () => {
    expect(viewGl.getExtension('KHR_parallel_shader_compile')).toBeNull();
    expect(createViewRelight(renderer, 'half', null).ready()).toBe(true);
    // A driver that compiles in parallel: the extension present, COMPLETION_STATUS_KHR false until the compile is done.
    // A proxy is another key for the per-context program cache: the programs are compiled anew for it.
    let compiled = false;
    const parallel = new Proxy(viewGl, {
      get(target, key) {
        if (key === 'getExtension') return (name: string) => (name === 'KHR_parallel_shader_compile' ? {} : target.getExtension(name));
        if (key === 'getProgramParameter') return (p: WebGLProgram, pname: number) => (pname === COMPLETION_STATUS_KHR ? compiled : target.getProgramParameter(p, pname));
        const value = Reflect.get(target, key) as unknown;
        return typeof value === 'function' ? (value as (...a: unknown[]) => unknown).bind(target) : value;
      },
    }) as WebGL2RenderingContext;
    const fakeRenderer = { getContext: () => parallel, resetState() {} } as unknown as THREE.WebGLRenderer;
    const relight = createViewRelight(fakeRenderer, 'half', null);
    expect(relight.ready()).toBe(false);
    compiled = true;
    expect(relight.ready()).toBe(true);
    relight.dispose();
  });

  it('on a low-memory device a configuration over the budget is refused (the CPU path shows it)', () => {
    const parts = engine.relightParts()!;
    expect(createViewRelight(renderer, 'half', LOW_MEMORY_RELIGHT_BYTES).fits(parts)).toBe(true);
    // Bases, solutions and display targets of this room: 3 bases + 1 solution at 8 B, 48 B of targets per texel.
    const texels = Object.values(parts.layouts).reduce((n, l) => n + l.width * l.height, 0);
    const need = (parts.parts.length + parts.terms.length) * texels * 8 + texels * 48;
    expect(createViewRelight(renderer, 'half', need).fits(parts)).toBe(true);
    expect(createViewRelight(renderer, 'half', need - 1).fits(parts)).toBe(false);
  });
});
