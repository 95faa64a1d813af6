import * as THREE from 'three';
import { glareCompositeFragment, glareDownFragment, glareUpFragment, glareVertex } from '../../../../shaders/glarePass.glsl';
import { glareLevels, glareWeights } from './veilingGlarePsf';

/**
 * The veiling-glare post pass (docs/viewer.md, "Glare"): the caller draws the room into the pass's
 * linear HDR target (half float: exposed, adapted light before the display curve), then `finish`
 * convolves it with the eye's PSF (veilingGlarePsf.ts) through a pyramid of 2×-smaller levels and
 * writes the display image to `output` (null: the canvas). Cost per frame: one full-size
 * composite plus the levels' passes, each a quarter of the previous (about ⅓ of a full-size
 * pass in all, twice): cheap enough for phones, where a direct convolution with a 100-pixel PSF is not.
 */
export interface GlarePass {
  /** Size the targets for a drawing buffer of width × height pixels (no-op when unchanged). */
  setSize(width: number, height: number): void;
  /** Where the room is drawn: linear HDR with alpha 1, a flat display colour with alpha ¼; cleared to 0 (the background). */
  readonly target: THREE.WebGLRenderTarget;
  /** Scatter and display: `pixelDeg` is the angle one pixel subtends (vertical field / height). `linear`: write the linear sum (tests). */
  finish(renderer: THREE.WebGLRenderer, pixelDeg: number, output: THREE.WebGLRenderTarget | null, linear?: boolean): { core: number; levels: number[] };
  dispose(): void;
}

/** Whether a renderer can draw into half-float targets (WebGL2 needs EXT_color_buffer_float or EXT_color_buffer_half_float). */
export function canRenderGlare(renderer: THREE.WebGLRenderer): boolean {
  const ext = renderer.extensions;
  return ext.has('EXT_color_buffer_float') || ext.has('EXT_color_buffer_half_float');
}

function material(fragmentShader: string, uniforms: Record<string, THREE.IUniform>): THREE.ShaderMaterial {
  return new THREE.ShaderMaterial({ glslVersion: THREE.GLSL3, vertexShader: glareVertex, fragmentShader, uniforms, depthTest: false, depthWrite: false });
}

/** `background`: the display colour (sRGB 0…1) of pixels nothing was drawn on; `samples`: the HDR target's multisampling. */
export function createGlarePass(options: { samples?: number; background?: [number, number, number] } = {}): GlarePass {
  // Mirrored edges: a filter's taps beyond the border read the image reflected about it, so the light a
  // symmetric kernel would carry out of the picture comes back in and none is lost or doubled (clamping
  // to the edge would count the border pixels several times).
  const hdrOptions = {
    type: THREE.HalfFloatType,
    format: THREE.RGBAFormat,
    minFilter: THREE.LinearFilter,
    magFilter: THREE.LinearFilter,
    wrapS: THREE.MirroredRepeatWrapping,
    wrapT: THREE.MirroredRepeatWrapping,
    generateMipmaps: false,
    depthBuffer: false,
  } as const;
  const target = new THREE.WebGLRenderTarget(1, 1, { ...hdrOptions, depthBuffer: true, samples: options.samples ?? 0 });
  let down: THREE.WebGLRenderTarget[] = [];
  let up: THREE.WebGLRenderTarget[] = [];
  let size = { width: 0, height: 0 };
  const camera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0, 1);
  const quad = new THREE.Mesh(new THREE.PlaneGeometry(2, 2));
  quad.frustumCulled = false;
  const scene = new THREE.Scene();
  scene.add(quad);
  const downMaterial = material(glareDownFragment, { uSource: { value: null }, uTexel: { value: new THREE.Vector2() } });
  const upMaterial = material(glareUpFragment, { uLevel: { value: null }, uCoarser: { value: null }, uCoarserTexel: { value: new THREE.Vector2() }, uWeight: { value: 0 }, uHasCoarser: { value: 0 } });
  const compositeMaterial = material(glareCompositeFragment, {
    uHdr: { value: null },
    uScattered: { value: null },
    uScatteredTexel: { value: new THREE.Vector2() },
    uCore: { value: 1 },
    uHasScattered: { value: 0 },
    uLinear: { value: 0 },
    uBackground: { value: new THREE.Vector3(...(options.background ?? [0, 0, 0])) },
  });
  const draw = (renderer: THREE.WebGLRenderer, m: THREE.ShaderMaterial, out: THREE.WebGLRenderTarget | null) => {
    quad.material = m;
    renderer.setRenderTarget(out);
    renderer.render(scene, camera);
  };
  const disposeLevels = () => {
    for (const t of [...down, ...up]) t.dispose();
    down = [];
    up = [];
  };
  return {
    target,
    setSize(width, height) {
      if (width === size.width && height === size.height) return;
      size = { width, height };
      target.setSize(width, height);
      disposeLevels();
      const n = glareLevels(width, height);
      for (let k = 1; k <= n; k++) {
        const w = Math.max(1, Math.ceil(width / 2 ** k));
        const h = Math.max(1, Math.ceil(height / 2 ** k));
        down.push(new THREE.WebGLRenderTarget(w, h, hdrOptions));
        up.push(new THREE.WebGLRenderTarget(w, h, hdrOptions));
      }
    },
    finish(renderer, pixelDeg, output, linear = false) {
      const previous = renderer.getRenderTarget();
      const weights = glareWeights(pixelDeg, down.length, Math.hypot(size.width, size.height));
      // Down: the HDR image, then each level from the one before.
      let source: THREE.WebGLRenderTarget = target;
      down.forEach((level) => {
        downMaterial.uniforms.uSource.value = source.texture;
        downMaterial.uniforms.uTexel.value.set(1 / source.width, 1 / source.height);
        draw(renderer, downMaterial, level);
        source = level;
      });
      // Up: from the coarsest, each level's share of the PSF plus the coarser sum.
      for (let k = down.length - 1; k >= 0; k--) {
        upMaterial.uniforms.uLevel.value = down[k].texture;
        upMaterial.uniforms.uWeight.value = weights.levels[k];
        const coarser = up[k + 1];
        upMaterial.uniforms.uHasCoarser.value = coarser ? 1 : 0;
        upMaterial.uniforms.uCoarser.value = coarser ? coarser.texture : null;
        if (coarser) upMaterial.uniforms.uCoarserTexel.value.set(1 / coarser.width, 1 / coarser.height);
        draw(renderer, upMaterial, up[k]);
      }
      const u = compositeMaterial.uniforms;
      u.uHdr.value = target.texture;
      u.uHasScattered.value = up.length > 0 ? 1 : 0;
      u.uScattered.value = up[0]?.texture ?? null;
      if (up[0]) u.uScatteredTexel.value.set(1 / up[0].width, 1 / up[0].height);
      u.uCore.value = weights.core;
      u.uLinear.value = linear ? 1 : 0;
      draw(renderer, compositeMaterial, output);
      renderer.setRenderTarget(previous);
      return weights;
    },
    dispose() {
      disposeLevels();
      target.dispose();
      quad.geometry.dispose();
      downMaterial.dispose();
      upMaterial.dispose();
      compositeMaterial.dispose();
    },
  };
}
