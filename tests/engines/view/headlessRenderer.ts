/**
 * A three.js WebGLRenderer on a headless-gl WebGL2 context of W × H pixels, for the tests that draw
 * the real view and read its pixels back; destroyed after the file's (or describe block's) tests.
 */
import createGL from 'gl';
import * as THREE from 'three';
import { afterAll } from 'vitest';

export function headlessRenderer(W: number, H: number): THREE.WebGLRenderer {
  const gl = createGL(W, H, { createWebGL2Context: true, preserveDrawingBuffer: true, antialias: false }) as unknown as WebGL2RenderingContext & {
    getExtension(n: 'STACKGL_destroy_context'): { destroy(): void } | null;
  };
  const canvas = { width: W, height: H, style: {}, addEventListener() {}, removeEventListener() {} } as unknown as HTMLCanvasElement;
  Object.defineProperty(gl, 'canvas', { value: canvas, configurable: true });
  const renderer = new THREE.WebGLRenderer({ canvas, context: gl, antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(W, H, false);
  afterAll(() => {
    renderer.dispose();
    gl.getExtension('STACKGL_destroy_context')?.destroy();
  });
  return renderer;
}
