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
  offerRendererInfo(gl2);
  return Object.assign(gl2, {
    destroy() {
      gl2.getExtension('STACKGL_destroy_context')?.destroy();
    },
  });
}

/** WEBGL_debug_renderer_info's enums (the WebGL extension registry). */
const UNMASKED_VENDOR_WEBGL = 0x9245;
const UNMASKED_RENDERER_WEBGL = 0x9246;

/**
 * headless-gl answers RENDERER with a bare "ANGLE" and offers no WEBGL_debug_renderer_info, so
 * nothing could tell llvmpipe from a GPU (softwareRenderer.ts). Offer the extension as browsers
 * do, its two enums answered with ANGLE's own strings (headless-gl's `_getParameterDirect` asks
 * the native context, e.g. "ANGLE (Mesa/X.org, llvmpipe (LLVM 15.0.6 256 bits), OpenGL 4.5)").
 */
function offerRendererInfo(gl: WebGL2RenderingContext): void {
  const direct = (gl as unknown as { _getParameterDirect?: (pname: number) => unknown })._getParameterDirect;
  if (typeof direct !== 'function') return;
  const getExtension = gl.getExtension.bind(gl);
  const getParameter = gl.getParameter.bind(gl);
  const info = Object.freeze({ UNMASKED_VENDOR_WEBGL, UNMASKED_RENDERER_WEBGL });
  Object.assign(gl, {
    getExtension: (name: string) => (name === 'WEBGL_debug_renderer_info' ? info : getExtension(name)),
    getParameter: (pname: number) => {
      if (pname === UNMASKED_RENDERER_WEBGL) return direct.call(gl, gl.RENDERER);
      if (pname === UNMASKED_VENDOR_WEBGL) return direct.call(gl, gl.VENDOR);
      return getParameter(pname);
    },
  });
}
