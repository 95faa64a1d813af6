/**
 * Which renderers count as software (softwareRenderer.ts) and where the bright patches are chosen
 * (brightPatchOptions.ts selectOnGpu): unset on the GPU except on a software rasteriser; an
 * explicit setting wins everywhere.
 */
import { describe, expect, it } from 'vitest';
import { brightPatchOptions, selectOnGpu } from '../../../src/engines/bake/brightPatchOptions';
import { softwareRenderer, unmaskedRenderer } from '../../../src/engines/bake/softwareRenderer';

/** A context answering only what the detection asks, with `renderer` as its unmasked string (or masked: no extension). */
function contextWith(renderer: string, unmasked = true): WebGL2RenderingContext {
  const info = { UNMASKED_RENDERER_WEBGL: 0x9246 };
  return {
    RENDERER: 0x1f01,
    getExtension: (name: string) => (unmasked && name === 'WEBGL_debug_renderer_info' ? info : null),
    getParameter: (pname: number) => (pname === 0x9246 ? renderer : pname === 0x1f01 ? 'WebKit WebGL' : null),
  } as unknown as WebGL2RenderingContext;
}

describe('softwareRenderer', () => {
  it.each([
    ['ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero) (0x0000C0DE)), SwiftShader driver)', true],
    ['ANGLE (Mesa/X.org, llvmpipe (LLVM 15.0.6 256 bits), OpenGL 4.5)', true],
    ['ANGLE (Mesa, llvmpipe (LLVM 15.0.6, 256 bits), Vulkan 1.3.255 (lavapipe))', true],
    ['softpipe', true],
    ['ANGLE (NVIDIA, NVIDIA H100 80GB HBM3/PCIe/SSE2, OpenGL 4.5.0)', false],
    ['Apple GPU', false],
    ['Adreno (TM) 740', false],
  ])('%s → %s', (renderer, software) => {
    expect(unmaskedRenderer(contextWith(renderer))).toBe(renderer);
    expect(softwareRenderer(contextWith(renderer))).toBe(software);
  });

  it('a masked string (no debug extension) counts as hardware', () => {
    expect(softwareRenderer(contextWith('llvmpipe', false))).toBe(false);
  });
});

describe('selectOnGpu', () => {
  it('unset: the GPU on hardware, the CPU on a software renderer; an explicit choice is kept on both', () => {
    expect(selectOnGpu(undefined, false)).toBe(true);
    expect(selectOnGpu(undefined, true)).toBe(false);
    for (const software of [false, true]) {
      expect(selectOnGpu('gpu', software)).toBe(true);
      expect(selectOnGpu('cpu', software)).toBe(false);
    }
    expect(brightPatchOptions({ brightPatches: 64 }, false, true).onGpu).toBe(false);
    expect(brightPatchOptions({ brightPatches: 64, brightSelection: 'gpu' }, true, true).onGpu).toBe(true);
  });
});
