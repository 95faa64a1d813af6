import createGL from 'gl';
import { PNG } from 'pngjs';
import * as THREE from 'three';
import type { BakeSettings } from '../bake/bakeSettings';
import { toRgb } from '../bake/bakeScene';
import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../model/lightingScene';
import { createRelightEngine, VIEWER_BAKE_SETTINGS } from '../relight/createRelightEngine';
import { autoExposure } from '../viewer/autoExposure';
import type { CameraPose } from '../viewer/cameraPresets';
import { luxLevels } from '../viewer/falseColorScale';
import { luxScaleTop } from '../viewer/luxScaleTop';
import { floorStats, type IlluminanceStats } from '../viewer/lightStats';
import { createRoomView, type ViewMode } from '../viewer/roomView';
import { NoWebGLError } from './createHeadlessGL';
import type { RenderInput } from './renderInput';

export interface RenderOptions {
  width: number;
  height: number;
  camera: CameraPose;
  /** Exposure compensation in stops (EV) on top of the automatic exposure. */
  exposureEv: number;
  mode: ViewMode;
  settings: Partial<BakeSettings>;
}

export interface RenderResult {
  png: Buffer;
  /** RGBA, top row first. */
  pixels: Uint8Array;
  exposure: number;
  floor: IlluminanceStats;
  timings_ms: { bake: number; render: number };
}

/**
 * Bake and draw a room with three.js on a headless-gl WebGL2 context: the
 * same RoomView, shaders and relight engine as the browser viewer (three's
 * WebGLRenderer accepts an existing context plus a canvas-like object). One
 * context serves the baker and three; three's state cache is reset after the
 * bake touched the context.
 */
export function renderImage(input: RenderInput, options: RenderOptions): RenderResult {
  const { width, height } = options;
  const gl = createGL(width, height, { createWebGL2Context: true, preserveDrawingBuffer: true, antialias: false }) as unknown as (WebGL2RenderingContext & { getExtension(name: 'STACKGL_destroy_context'): { destroy(): void } | null }) | null;
  if (!gl || !('texStorage2D' in gl)) throw new NoWebGLError(`could not create a ${width}×${height} headless WebGL2 context${process.env.DISPLAY ? '' : ' (no X display: run under xvfb-run -a)'}`);
  const engine = createRelightEngine(gl, { ...VIEWER_BAKE_SETTINGS, ...options.settings });
  let renderer: THREE.WebGLRenderer | null = null;
  try {
    const t0 = performance.now();
    engine.setScene(input.bakeScene);
    engine.finish();
    const lit = engine.maps();
    const t1 = performance.now();
    const canvas = { width, height, style: {}, addEventListener() {}, removeEventListener() {} } as unknown as HTMLCanvasElement;
    // headless-gl contexts have no canvas; three reads gl.canvas for the default scissor and viewport.
    Object.defineProperty(gl, 'canvas', { value: canvas, configurable: true });
    renderer = new THREE.WebGLRenderer({ canvas, context: gl, antialias: false });
    renderer.resetState();
    renderer.setPixelRatio(1);
    renderer.setSize(width, height, false);
    const view = createRoomView(renderer);
    const reflectance = Object.fromEntries(SURFACE_NAMES.map((n) => [n, toRgb(input.bakeScene.room.reflectance[n])])) as Record<SurfaceName, Rgb>;
    view.setMaps(lit, reflectance);
    const exposure = autoExposure(lit, reflectance) * 2 ** options.exposureEv;
    view.setExposure(exposure);
    const floor = floorStats(lit);
    view.setMode(options.mode, luxLevels(luxScaleTop(lit)));
    view.setFixtures(input.fixtures);
    view.setCamera(options.camera, width / height);
    view.render(renderer);
    const raw = new Uint8Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, raw);
    const t2 = performance.now();
    view.dispose();
    // GL rows run bottom-up; images top-down.
    const pixels = new Uint8Array(raw.length);
    const row = width * 4;
    for (let y = 0; y < height; y++) pixels.set(raw.subarray((height - 1 - y) * row, (height - y) * row), y * row);
    const png = new PNG({ width, height });
    png.data = Buffer.from(pixels);
    return { png: PNG.sync.write(png), pixels, exposure, floor, timings_ms: { bake: t1 - t0, render: t2 - t1 } };
  } finally {
    engine.dispose();
    renderer?.dispose();
    gl.getExtension('STACKGL_destroy_context')?.destroy();
  }
}
