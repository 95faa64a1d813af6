import createGL from 'gl';
import { PNG } from 'pngjs';
import * as THREE from 'three';
import { resolveBakeSettings, type BakeSettings } from '../../engines/bake/bakeSettings';
import { reflectanceRgb, type BakeScene } from '../../engines/bake/bakeScene';
import { createBaker } from '../../engines/bake/createBaker';
import { daylightBakeInput } from '../../engines/bake/daylight/daylightBakeInput';
import type { LitMaps } from '../../engines/relight/relightMaps';
import { prepareObjects } from '../../engines/bake/objects/prepareObjects';
import { encloseShapedRoom } from '../../engines/bake/shapedRoom/encloseShapedRoom';
import { createRelightEngine, VIEWER_BAKE_SETTINGS } from '../../engines/relight/createRelightEngine';
import type { CameraPose } from '../../engines/view/cameraPresets';
import { floorStats, type IlluminanceStats } from '../../engines/view/lightStats';
import { presentMaps } from '../../engines/view/presentMaps';
import { adoptedWhite } from '../../engines/view/adoptedWhite';
import type { AdaptationSetting } from '../../engines/view/adaptationSetting';
import { createRoomView, type RoomView, type ViewMode } from '../../engines/view/roomView';
import { fullscreenVertex } from '../../../shaders/fullscreen.glsl';
import { noContextMessage, NoWebGLError } from './createHeadlessGL';
import type { RenderInput } from './renderInput';
import { bakedAsLitMaps } from './bakedAsLitMaps';

export interface RenderOptions {
  width: number;
  height: number;
  camera: CameraPose;
  /** Exposure compensation in stops (EV) on top of the automatic exposure. */
  exposureEv: number;
  /** Absolute exposure (EV100, photographicExposure.ts) instead of the automatic one; null/absent: automatic. */
  ev100?: number | null;
  mode: ViewMode;
  /** Chromatic adaptation (chromaticAdaptation.ts); default eye. */
  adaptation?: AdaptationSetting;
  /** Veiling glare round bright sources in light mode (glare/createGlarePass.ts); default on. */
  glare?: boolean;
  settings: Partial<BakeSettings>;
}

export interface RenderResult {
  png: Buffer;
  /** RGBA, top row first. */
  pixels: Uint8Array;
  exposure: number;
  /** EV100 of the exposure applied (the fixed one, or the automatic one's). */
  ev100: number;
  floor: IlluminanceStats;
  timings_ms: { bake: number; render: number };
}

export interface ProgramsLinked {
  baker: number;
  view: number;
}

/** Several renders on one headless-gl context: the baker's and three's shader programs are compiled once for all. */
export interface RenderSession {
  /** Bake the scene once, then draw it from each camera (options.camera is ignored; results in camera order). */
  renderViews(input: RenderInput, options: RenderOptions, cameras: CameraPose[]): RenderResult[];
  /**
   * Shader programs linked on this context so far: the baker's (their vertex shader is the
   * fullscreen triangle; specialised per scene layout, e.g. per lamp source count, and cached per
   * context) and the view's (three.js). A batch of scenes of one kind links them for its first only.
   */
  programsLinked(): ProgramsLinked;
  destroy(): void;
}

/** A headless-gl WebGL2 context, the canvas-like object three.js reads, and the program-link counter. */
interface SessionContext {
  gl: WebGL2RenderingContext & { getExtension(name: 'STACKGL_destroy_context'): { destroy(): void } | null };
  canvas: HTMLCanvasElement;
  linked: ProgramsLinked;
}

function createSessionContext(width: number, height: number): SessionContext {
  const gl = createGL(width, height, { createWebGL2Context: true, preserveDrawingBuffer: true, antialias: false }) as unknown as SessionContext['gl'] | null;
  if (!gl || !('texStorage2D' in gl)) throw new NoWebGLError(noContextMessage(`a ${width}×${height} headless WebGL2 context`));
  const canvas = { width, height, style: {}, addEventListener() {}, removeEventListener() {} } as unknown as HTMLCanvasElement;
  // headless-gl contexts have no canvas; three reads gl.canvas for the default scissor and viewport.
  Object.defineProperty(gl, 'canvas', { value: canvas, configurable: true });
  // Count program links (every compile of a vertex + fragment pair ends in one) for the batch summary and its test.
  const linked: ProgramsLinked = { baker: 0, view: 0 };
  const linkProgram = gl.linkProgram.bind(gl);
  gl.linkProgram = (program: WebGLProgram) => {
    const baker = (gl.getAttachedShaders(program) ?? []).some((shader) => gl.getShaderSource(shader) === fullscreenVertex);
    linked[baker ? 'baker' : 'view']++;
    linkProgram(program);
  };
  return { gl, canvas, linked };
}

/** The lit maps of one scene, the settings they were baked with, and what frees their GL resources. */
interface ViewBake {
  lit: LitMaps;
  settings: BakeSettings;
  ms: number;
  dispose(): void;
}

/**
 * Bake a scene for the view. Electric light: the relight engine, as the browser viewer bakes.
 * Daylight through windows (docs/daylight.md): the relight engine keeps no sky or sun basis yet,
 * so the scene is baked whole by the baker (sky, ground and sun through the windows, then the
 * bounces, with the viewer's quality settings) and its maps shown as they are.
 */
function bakeForView(gl: WebGL2RenderingContext, scene: BakeScene, given: Partial<BakeSettings>): ViewBake {
  const settings = resolveBakeSettings({ ...VIEWER_BAKE_SETTINGS, ...given });
  const t0 = performance.now();
  if (daylightBakeInput(scene, encloseShapedRoom(scene))) {
    const baker = createBaker(gl);
    try {
      const { maps } = baker.bake(scene, settings);
      return { lit: bakedAsLitMaps(maps), settings, ms: performance.now() - t0, dispose: () => baker.dispose() };
    } catch (error) {
      baker.dispose();
      throw error;
    }
  }
  const engine = createRelightEngine(gl, { ...VIEWER_BAKE_SETTINGS, ...given });
  try {
    engine.setScene(scene);
    engine.finish();
    return { lit: engine.maps(), settings: engine.settings, ms: performance.now() - t0, dispose: () => engine.dispose() };
  } catch (error) {
    engine.dispose();
    throw error;
  }
}

/** The drawing buffer as RGBA rows top first, and as a PNG. */
function readImage(gl: WebGL2RenderingContext, width: number, height: number): { pixels: Uint8Array; png: Buffer } {
  const raw = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, raw);
  // GL rows run bottom-up; images top-down.
  const pixels = new Uint8Array(raw.length);
  const row = width * 4;
  for (let y = 0; y < height; y++) pixels.set(raw.subarray((height - 1 - y) * row, (height - y) * row), y * row);
  const png = new PNG({ width, height });
  png.data = Buffer.from(pixels);
  return { pixels, png: PNG.sync.write(png) };
}

/** The room view of a baked scene: geometry on the atlas the baker lit, maps, exposure, fixtures and glare set. */
function composeView(renderer: THREE.WebGLRenderer, input: RenderInput, bake: ViewBake, options: RenderOptions): { view: RoomView; exposure: number; ev100: number; floor: IlluminanceStats } {
  const view = createRoomView(renderer);
  // The objects' geometry on the atlas the baker lit (same objects, same texel size and limit).
  // A room of any shape: its surfaces are the first objects of the enclosure the engine lit (encloseShapedRoom), the box hidden.
  const objects = encloseShapedRoom(input.bakeScene).objects ?? [];
  const prepared = objects.length > 0 ? prepareObjects(objects, { texelSize: bake.settings.texelSize, maxAtlasSize: bake.settings.maxTextureSize }) : null;
  view.setRoomShape(input.bakeScene.room.shape ?? null);
  view.setObjects(prepared);
  const { exposure, ev100 } = presentMaps(view, bake.lit, reflectanceRgb(input.bakeScene.room), {
    exposureEv: options.exposureEv,
    ev100: options.ev100,
    mode: options.mode,
    adaptation: options.adaptation,
    white: adoptedWhite(input.bakeScene.luminaires),
  });
  view.setFixtures(input.fixtures);
  view.setGlare(options.glare ?? true);
  // The floor a person sees: texels under furniture standing on it left out (docs/viewer.md).
  return { view, exposure, ev100, floor: floorStats(bake.lit, prepared) };
}

/**
 * Bake and draw rooms with three.js on a headless-gl WebGL2 context: the
 * same RoomView, shaders and relight engine as the browser viewer (three's
 * WebGLRenderer accepts an existing context plus a canvas-like object). One
 * context serves the baker and three; three's state cache is reset after each
 * bake touched the context. Every render of a session has the session's size.
 */
export function createRenderSession(width: number, height: number): RenderSession {
  const { gl, canvas, linked } = createSessionContext(width, height);
  let renderer: THREE.WebGLRenderer | null = null;
  // The last scene's view is disposed only after the next one has drawn: three.js frees a program when
  // no material uses it, so disposing first would make every scene compile the same programs again.
  let previousView: RoomView | null = null;
  const rendererOnce = (): THREE.WebGLRenderer => {
    if (!renderer) {
      renderer = new THREE.WebGLRenderer({ canvas, context: gl, antialias: false });
      renderer.setPixelRatio(1);
      renderer.setSize(width, height, false);
    }
    return renderer;
  };
  return {
    renderViews(input, options, cameras) {
      if (options.width !== width || options.height !== height) throw new Error(`render session is ${width}×${height}, asked for ${options.width}×${options.height}`);
      const bake = bakeForView(gl, input.bakeScene, options.settings);
      try {
        const three = rendererOnce();
        three.resetState();
        const { view, exposure, ev100, floor } = composeView(three, input, bake, options);
        const results = cameras.map((camera): RenderResult => {
          const t2 = performance.now();
          view.setCamera(camera, width / height);
          view.render(three);
          const image = readImage(gl, width, height);
          return { ...image, exposure, ev100, floor, timings_ms: { bake: bake.ms, render: performance.now() - t2 } };
        });
        previousView?.dispose();
        previousView = view;
        return results;
      } finally {
        bake.dispose();
      }
    },
    programsLinked() {
      return { ...linked };
    },
    destroy() {
      previousView?.dispose();
      previousView = null;
      renderer?.dispose();
      gl.getExtension('STACKGL_destroy_context')?.destroy();
    },
  };
}

/** One render on its own context (see createRenderSession). */
export function renderImage(input: RenderInput, options: RenderOptions): RenderResult {
  const session = createRenderSession(options.width, options.height);
  try {
    return session.renderViews(input, options, [options.camera])[0];
  } finally {
    session.destroy();
  }
}
