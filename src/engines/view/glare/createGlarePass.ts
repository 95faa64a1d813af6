import * as THREE from 'three';
import { glareCompositeFragment, glareDownFragment, glareExcessFragment, glareUpFragment, glareVertex } from '../../../../shaders/glarePass.glsl';
import { glareLevels, glareWeights } from './veilingGlarePsf';

/**
 * The veiling-glare post pass (docs/viewer.md, "Glare"): the caller draws the room into the pass's
 * linear HDR target (half float: exposed, adapted light before the display curve), then `finish`
 * convolves it with the eye's PSF (veilingGlarePsf.ts) through a pyramid of 2×-smaller levels and
 * writes the display image to `output` (null: the canvas). Only the light above the exposure's
 * white scatters (glarePass.glsl.ts). Cost per frame: two full-size passes (the light above white,
 * the composite) plus the levels' passes, each a quarter of the previous (about ⅓ of a full-size
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

/** Mirrored edges: a filter's taps beyond the border read the image reflected about it, so the light a
 * symmetric kernel would carry out of the picture comes back in and none is lost or doubled (clamping
 * to the edge would count the border pixels several times). */
const HDR_OPTIONS = {
  type: THREE.HalfFloatType,
  format: THREE.RGBAFormat,
  minFilter: THREE.LinearFilter,
  magFilter: THREE.LinearFilter,
  wrapS: THREE.MirroredRepeatWrapping,
  wrapT: THREE.MirroredRepeatWrapping,
  generateMipmaps: false,
  depthBuffer: false,
} as const;

/** What the pass's parts share: the targets of the pyramid, the full-screen quad and the three materials. */
interface GlareCore {
  readonly target: THREE.WebGLRenderTarget;
  /** The light above white of each pixel (full size, single-sampled): the pyramid's input. */
  readonly excess: THREE.WebGLRenderTarget;
  down: THREE.WebGLRenderTarget[];
  up: THREE.WebGLRenderTarget[];
  size: { width: number; height: number };
  readonly camera: THREE.OrthographicCamera;
  readonly quad: THREE.Mesh;
  readonly scene: THREE.Scene;
  readonly excessMaterial: THREE.ShaderMaterial;
  readonly downMaterial: THREE.ShaderMaterial;
  readonly upMaterial: THREE.ShaderMaterial;
  readonly compositeMaterial: THREE.ShaderMaterial;
}

function draw(core: GlareCore, renderer: THREE.WebGLRenderer, m: THREE.ShaderMaterial, out: THREE.WebGLRenderTarget | null) {
  core.quad.material = m;
  renderer.setRenderTarget(out);
  renderer.render(core.scene, core.camera);
}

function disposeLevels(core: GlareCore) {
  for (const t of [...core.down, ...core.up]) t.dispose();
  core.down = [];
  core.up = [];
}

/** The HDR target at full size and the pyramid's levels, each half the previous (rounded up). */
function resize(core: GlareCore, width: number, height: number) {
  if (width === core.size.width && height === core.size.height) return;
  core.size = { width, height };
  core.target.setSize(width, height);
  core.excess.setSize(width, height);
  disposeLevels(core);
  const n = glareLevels(width, height);
  for (let k = 1; k <= n; k++) {
    const w = Math.max(1, Math.ceil(width / 2 ** k));
    const h = Math.max(1, Math.ceil(height / 2 ** k));
    core.down.push(new THREE.WebGLRenderTarget(w, h, HDR_OPTIONS));
    core.up.push(new THREE.WebGLRenderTarget(w, h, HDR_OPTIONS));
  }
}

/** The scattered light: the HDR image's light above white, down the pyramid from it, then up from the coarsest level, each adding its share of the PSF. */
function scatter(core: GlareCore, renderer: THREE.WebGLRenderer, levelWeights: readonly number[]) {
  const { down, up, downMaterial, upMaterial } = core;
  // Per pixel before any filtering, so the light subtracted in the composite is exactly the light scattered.
  core.excessMaterial.uniforms.uHdr.value = core.target.texture;
  draw(core, renderer, core.excessMaterial, core.excess);
  let source: THREE.WebGLRenderTarget = core.excess;
  down.forEach((level) => {
    downMaterial.uniforms.uSource.value = source.texture;
    downMaterial.uniforms.uTexel.value.set(1 / source.width, 1 / source.height);
    draw(core, renderer, downMaterial, level);
    source = level;
  });
  for (let k = down.length - 1; k >= 0; k--) {
    upMaterial.uniforms.uLevel.value = down[k].texture;
    upMaterial.uniforms.uWeight.value = levelWeights[k];
    const coarser = up[k + 1];
    upMaterial.uniforms.uHasCoarser.value = coarser ? 1 : 0;
    upMaterial.uniforms.uCoarser.value = coarser ? coarser.texture : null;
    if (coarser) upMaterial.uniforms.uCoarserTexel.value.set(1 / coarser.width, 1 / coarser.height);
    draw(core, renderer, upMaterial, up[k]);
  }
}

/** The core of the PSF on the sharp image plus the scattered sum, through the display curve (or linear, for tests). */
function composite(core: GlareCore, renderer: THREE.WebGLRenderer, coreWeight: number, output: THREE.WebGLRenderTarget | null, linear: boolean) {
  const { up } = core;
  const u = core.compositeMaterial.uniforms;
  u.uHdr.value = core.target.texture;
  u.uHasScattered.value = up.length > 0 ? 1 : 0;
  u.uScattered.value = up[0]?.texture ?? null;
  if (up[0]) u.uScatteredTexel.value.set(1 / up[0].width, 1 / up[0].height);
  u.uCore.value = coreWeight;
  u.uLinear.value = linear ? 1 : 0;
  draw(core, renderer, core.compositeMaterial, output);
}

/** `background`: the display colour (sRGB 0…1) of pixels nothing was drawn on; `samples`: the HDR target's multisampling. */
export function createGlarePass(options: { samples?: number; background?: [number, number, number] } = {}): GlarePass {
  const quad = new THREE.Mesh(new THREE.PlaneGeometry(2, 2));
  quad.frustumCulled = false;
  const scene = new THREE.Scene();
  scene.add(quad);
  const core: GlareCore = {
    target: new THREE.WebGLRenderTarget(1, 1, { ...HDR_OPTIONS, depthBuffer: true, samples: options.samples ?? 0 }),
    excess: new THREE.WebGLRenderTarget(1, 1, HDR_OPTIONS),
    down: [],
    up: [],
    size: { width: 0, height: 0 },
    camera: new THREE.OrthographicCamera(-1, 1, 1, -1, 0, 1),
    quad,
    scene,
    excessMaterial: material(glareExcessFragment, { uHdr: { value: null } }),
    downMaterial: material(glareDownFragment, { uSource: { value: null }, uTexel: { value: new THREE.Vector2() } }),
    upMaterial: material(glareUpFragment, { uLevel: { value: null }, uCoarser: { value: null }, uCoarserTexel: { value: new THREE.Vector2() }, uWeight: { value: 0 }, uHasCoarser: { value: 0 } }),
    compositeMaterial: material(glareCompositeFragment, {
      uHdr: { value: null },
      uScattered: { value: null },
      uScatteredTexel: { value: new THREE.Vector2() },
      uCore: { value: 1 },
      uHasScattered: { value: 0 },
      uLinear: { value: 0 },
      uBackground: { value: new THREE.Vector3(...(options.background ?? [0, 0, 0])) },
    }),
  };
  return {
    target: core.target,
    setSize: (width, height) => resize(core, width, height),
    finish(renderer, pixelDeg, output, linear = false) {
      const previous = renderer.getRenderTarget();
      const weights = glareWeights(pixelDeg, core.down.length, Math.hypot(core.size.width, core.size.height));
      scatter(core, renderer, weights.levels);
      composite(core, renderer, weights.core, output, linear);
      renderer.setRenderTarget(previous);
      return weights;
    },
    dispose() {
      disposeLevels(core);
      core.target.dispose();
      core.excess.dispose();
      quad.geometry.dispose();
      core.excessMaterial.dispose();
      core.downMaterial.dispose();
      core.upMaterial.dispose();
      core.compositeMaterial.dispose();
    },
  };
}
