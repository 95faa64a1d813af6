import createGL from 'gl';
import { PNG } from 'pngjs';
import * as THREE from 'three';
import type { BakeSettings } from '../../engines/bake/bakeSettings';
import { reflectanceRgb, type BakeScene } from '../../engines/bake/bakeScene';
import type { LitMaps } from '../../engines/relight/relightMaps';
import { prepareObjects } from '../../engines/bake/objects/prepareObjects';
import { encloseShapedRoom } from '../../engines/bake/shapedRoom/encloseShapedRoom';
import { createRelightEngine, VIEWER_BAKE_SETTINGS } from '../../engines/relight/createRelightEngine';
import type { CameraPose } from '../../engines/view/cameraPresets';
import { floorStats, type IlluminanceStats } from '../../engines/view/lightStats';
import { presentMaps } from '../../engines/view/presentMaps';
import { sceneAdoptedWhite } from '../../engines/view/adoptedWhite';
import type { AdaptationSetting } from '../../engines/view/adaptationSetting';
import { createRoomView, type RoomView, type ViewMode } from '../../engines/view/roomView';
import { fullscreenVertex } from '../../../shaders/fullscreen.glsl';
import { noContextMessage, NoWebGLError } from './createHeadlessGL';
import type { RenderInput } from './renderInput';

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
  /** Also read the exposed linear value before the tone curve (the glare pass's HDR input, uMode 2) into RenderResult.hdr. */
  hdr?: boolean;
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
  /** With options.hdr: RGBA floats, top row first, luminance × exposure after the chromatic adaptation and before the tone curve (0 where nothing is drawn). */
  hdr?: Float32Array;
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
 * Bake a scene for the view with the relight engine, as the browser viewer bakes: the luminaire
 * groups and, for a room whose windows see a sky or a sun, the daylight's sky and sun bases
 * (docs/daylight.md, "Daylight in the relight engine"), bounced in the one shared solve.
 */
function bakeForView(gl: WebGL2RenderingContext, scene: BakeScene, given: Partial<BakeSettings>): ViewBake {
  const t0 = performance.now();
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

/**
 * The view's exposed linear value before the tone curve, as the glare pass receives it (uMode 2:
 * luminance × exposure, adapted), drawn into a float target and read back top row first.
 */
function readHdr(renderer: THREE.WebGLRenderer, view: RoomView, width: number, height: number): Float32Array {
  const target = new THREE.WebGLRenderTarget(width, height, { type: THREE.FloatType });
  const mode = view.display.uMode.value;
  const background = view.scene.background;
  const clearColor = renderer.getClearColor(new THREE.Color());
  const clearAlpha = renderer.getClearAlpha();
  try {
    view.display.uMode.value = 2;
    view.scene.background = null;
    renderer.setRenderTarget(target);
    renderer.setClearColor(0x000000, 0);
    renderer.clear();
    renderer.render(view.scene, view.camera);
    const raw = new Float32Array(width * height * 4);
    renderer.readRenderTargetPixels(target, 0, 0, width, height, raw);
    const rows = new Float32Array(raw.length);
    const row = width * 4;
    for (let y = 0; y < height; y++) rows.set(raw.subarray((height - 1 - y) * row, (height - y) * row), y * row);
    return rows;
  } finally {
    renderer.setRenderTarget(null);
    view.display.uMode.value = mode;
    view.scene.background = background;
    renderer.setClearColor(clearColor, clearAlpha);
    target.dispose();
  }
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
    white: sceneAdoptedWhite(input.bakeScene),
  });
  view.setFixtures(input.fixtures);
  // The windows as the browser shows them with both light sources (viewerSceneApi.ts syncWindows): the scene's daylight, or the night sky without one.
  const daylight = input.bakeScene.daylight ?? null;
  view.setWindows(input.bakeScene.room.shape ?? null, daylight, daylight?.glazing ?? new Map());
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
          const hdr = options.hdr ? { hdr: readHdr(three, view, width, height) } : {};
          return { ...image, ...hdr, exposure, ev100, floor, timings_ms: { bake: bake.ms, render: performance.now() - t2 } };
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
