/**
 * Software rasterisers by their renderer strings: Google's SwiftShader (Chrome without a GPU, its
 * "SwiftShader Device"), Mesa's llvmpipe (GLX on a CPU-only box), softpipe and lavapipe (Mesa's
 * Vulkan on the CPU, which reports itself as llvmpipe too).
 */
const SOFTWARE = /swiftshader|llvmpipe|softpipe|lavapipe/i;

const known = new WeakMap<WebGL2RenderingContext, boolean>();

/** The context's renderer string, unmasked where WEBGL_debug_renderer_info is offered (headless-gl offers it through createHeadlessGL.ts). */
export function unmaskedRenderer(gl: WebGL2RenderingContext): string {
  const debug = gl.getExtension('WEBGL_debug_renderer_info') as { UNMASKED_RENDERER_WEBGL: number } | null;
  return String(gl.getParameter(debug ? debug.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
}

/**
 * Whether `gl` draws on the CPU. There a read-back is a memcpy with nothing to wait for, so the
 * baker's choices made to spare a GPU its pipeline waits (the bright patches selected on the GPU,
 * docs/baker.md) cost more than they save. A masked string (a browser without the debug
 * extension) counts as hardware: the choice made for GPUs is the safe one there.
 */
export function softwareRenderer(gl: WebGL2RenderingContext): boolean {
  let software = known.get(gl);
  if (software === undefined) {
    software = SOFTWARE.test(unmaskedRenderer(gl));
    known.set(gl, software);
  }
  return software;
}
