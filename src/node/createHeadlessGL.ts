import createGL from 'gl';
import { InputError } from '../inputError';

/** Thrown when no WebGL2 context can be made (no X display, missing driver). */
export class NoWebGLError extends InputError {
  override name = 'NoWebGLError';
}

/**
 * A headless WebGL2 context (headless-gl 9, ANGLE). It needs an X display:
 * run under `xvfb-run -a` (the CLI re-executes itself that way, see
 * ensureDisplay). The drawing buffer is 1×1: the baker renders only into its
 * own float framebuffers.
 */
export function createHeadlessGL(): WebGL2RenderingContext & { destroy(): void } {
  const gl = createGL(1, 1, { createWebGL2Context: true, preserveDrawingBuffer: false, antialias: false });
  if (!gl || !('texStorage2D' in gl)) {
    throw new NoWebGLError(
      `could not create a headless WebGL2 context${process.env.DISPLAY ? ` on display ${process.env.DISPLAY}` : ' (no X display: run under xvfb-run -a)'}`,
    );
  }
  const gl2 = gl as WebGL2RenderingContext & ReturnType<typeof createGL>;
  return Object.assign(gl2, {
    destroy() {
      gl2.getExtension('STACKGL_destroy_context')?.destroy();
    },
  });
}
