import createGL from 'gl';
import { InputError } from '../../core/inputError';

/** Thrown when no WebGL2 context can be made (no X display, missing driver). */
export class NoWebGLError extends InputError {
  override name = 'NoWebGLError';
}

/** One line saying which back end failed and what it needs (glBackend.ts). */
export function noContextMessage(what: string): string {
  if (process.env.ANGLE_DEFAULT_PLATFORM === 'vulkan') {
    return `could not create ${what} through Vulkan (no working Vulkan device: apt-get install mesa-vulkan-drivers, or set VK_DRIVER_FILES; or use --gl glx)`;
  }
  return `could not create ${what}${process.env.DISPLAY ? ` on display ${process.env.DISPLAY}` : ' (no X display: run under xvfb-run -a, or use --gl vulkan)'}`;
}

/**
 * A headless WebGL2 context (headless-gl 9, ANGLE). With GLX it needs an X
 * display (the CLI re-executes itself under `xvfb-run -a`, see prepareGl);
 * with ANGLE_DEFAULT_PLATFORM=vulkan it needs none. The drawing buffer is
 * 1×1: the baker renders only into its own float framebuffers.
 */
export function createHeadlessGL(): WebGL2RenderingContext & { destroy(): void } {
  const gl = createGL(1, 1, { createWebGL2Context: true, preserveDrawingBuffer: false, antialias: false });
  if (!gl || !('texStorage2D' in gl)) {
    throw new NoWebGLError(noContextMessage('a headless WebGL2 context'));
  }
  const gl2 = gl as WebGL2RenderingContext & ReturnType<typeof createGL>;
  return Object.assign(gl2, {
    destroy() {
      gl2.getExtension('STACKGL_destroy_context')?.destroy();
    },
  });
}
