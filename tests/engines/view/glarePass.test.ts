/**
 * Veiling glare (docs/viewer.md, "Glare"): the CIE 146 PSF and its discretisation (by hand and by
 * quadrature), then the pass on headless-gl: light is moved, not made (total linear energy within
 * 1 %), a pixel far from the bright source keeps its value (1 %), one near it gains, the source
 * loses what it scatters; a uniform image stays uniform through the display transform; in the
 * room view the pass is on in light mode and off in lux mode.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import type { Rgb, Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import { parsePhotometry } from '../../../src/core/photometry/parsePhotometry';
import type { FixtureModule, Fixtures } from '../../../src/engines/view/fixtures';
import { createGlarePass } from '../../../src/engines/view/glare/createGlarePass';
import { annulusShare, cieGlarePsf, glareLevels, glareWeights } from '../../../src/engines/view/glare/veilingGlarePsf';
import { hemisphereFlux } from '../../../src/engines/view/luminaires/hemisphereFlux';
import { createRoomView } from '../../../src/engines/view/roomView';
import { displayColor } from '../../../src/engines/view/toneMap';
import { headlessRenderer } from './headlessRenderer';

describe('the CIE 146 glare PSF', () => {
  it('by hand at 1° and 10° (age 40, p 0.5)', () => {
    const ageFactor = 1 + (40 / 62.5) ** 4; // 1.16777216
    expect(cieGlarePsf(1)).toBeCloseTo(10 + (5 + 0.05) * ageFactor + 0.00125, 10);
    expect(cieGlarePsf(10)).toBeCloseTo(0.01 + (0.05 + 0.005) * ageFactor + 0.00125, 10);
  });

  it('the annulus share is the integral of PSF · 2πθ dθ (quadrature, 10⁻⁶)', () => {
    const quadrature = (a: number, b: number) => {
      // Midpoint rule in log θ: θ dθ = θ² d(ln θ).
      const n = 200000;
      const la = Math.log(a);
      const step = (Math.log(b) - la) / n;
      let s = 0;
      for (let i = 0; i < n; i++) {
        const t = Math.exp(la + (i + 0.5) * step);
        s += cieGlarePsf(t) * 2 * Math.PI * t * t * step;
      }
      return s * (Math.PI / 180) ** 2;
    };
    for (const [a, b] of [
      [0.1, 0.3],
      [0.5, 2],
      [3, 30],
      [0.1, 100],
    ])
      expect(annulusShare(a, b)).toBeCloseTo(quadrature(a, b), 6);
    // The whole domain scatters about 29 % of the light (young eyes less, old eyes more).
    expect(annulusShare(0.1, 100)).toBeGreaterThan(0.2);
    expect(annulusShare(0.1, 100)).toBeLessThan(0.4);
  });

  it('the discretised PSF integrates to 1: core + levels = 1, every weight ≥ 0', () => {
    for (const [w, h, fov] of [
      [1280, 800, 60],
      [780, 1688, 90],
      [320, 200, 60],
      [64, 64, 30],
    ]) {
      const n = glareLevels(w, h);
      const g = glareWeights(fov / h, n, Math.hypot(w, h));
      expect(g.levels).toHaveLength(n);
      expect(g.core + g.levels.reduce((s, x) => s + x, 0)).toBeCloseTo(1, 12);
      for (const x of [g.core, ...g.levels]) expect(x).toBeGreaterThanOrEqual(0);
    }
    expect(glareLevels(1280, 800)).toBe(7);
    expect(glareLevels(8, 8)).toBe(1);
  });
});

describe('the glare pass (three.js on headless-gl)', () => {
  const W = 128;
  const H = 128;
  const renderer = headlessRenderer(W, H);
  const pixelDeg = 60 / H;

  /** Run the pass over a linear image (RGBA float, alpha 1) and read the result back (linear sum or display bytes). */
  function glare(image: Float32Array, linear: boolean): Float32Array | Uint8Array {
    const pass = createGlarePass();
    pass.setSize(W, H);
    const texture = new THREE.DataTexture(image, W, H, THREE.RGBAFormat, THREE.FloatType);
    texture.needsUpdate = true;
    const copy = new THREE.ShaderMaterial({
      glslVersion: THREE.GLSL3,
      vertexShader: 'void main() { gl_Position = vec4(position.xy, 0.0, 1.0); }',
      fragmentShader: 'precision highp float; uniform sampler2D uImage; out vec4 fragColor; void main() { fragColor = texelFetch(uImage, ivec2(gl_FragCoord.xy), 0); }',
      uniforms: { uImage: { value: texture } },
    });
    const quad = new THREE.Mesh(new THREE.PlaneGeometry(2, 2), copy);
    quad.frustumCulled = false;
    const scene = new THREE.Scene();
    scene.add(quad);
    renderer.setRenderTarget(pass.target);
    renderer.render(scene, new THREE.OrthographicCamera(-1, 1, 1, -1, 0, 1));
    renderer.setRenderTarget(null);
    let out: Float32Array | Uint8Array;
    if (linear) {
      const target = new THREE.WebGLRenderTarget(W, H, { type: THREE.FloatType });
      pass.finish(renderer, pixelDeg, target, true);
      out = new Float32Array(W * H * 4);
      renderer.readRenderTargetPixels(target, 0, 0, W, H, out);
      target.dispose();
    } else {
      pass.finish(renderer, pixelDeg, null);
      out = new Uint8Array(W * H * 4);
      const gl = renderer.getContext();
      gl.readPixels(0, 0, W, H, gl.RGBA, gl.UNSIGNED_BYTE, out);
    }
    renderer.setRenderTarget(null);
    pass.dispose();
    texture.dispose();
    copy.dispose();
    quad.geometry.dispose();
    return out;
  }

  const background = 0.05;
  const source = { x: 40, y: 64 };
  /** A grey background with a 3 × 3 block of `value` round the source point. */
  const imageWith = (value: number) => {
    const image = new Float32Array(W * H * 4);
    for (let i = 0; i < W * H; i++) image.set([background, background, background, 1], i * 4);
    for (let dy = -1; dy <= 1; dy++) for (let dx = -1; dx <= 1; dx++) image.set([value, value, value, 1], ((source.y + dy) * W + source.x + dx) * 4);
    return image;
  };
  const at = (px: ArrayLike<number>, x: number, y: number) => px[(y * W + x) * 4 + 1];
  const total = (px: ArrayLike<number>) => {
    let s = 0;
    for (let i = 0; i < W * H; i++) s += px[i * 4 + 1];
    return s;
  };
  /** The CIE veil at a pixel d pixels from the 3 × 3 block (a point of 9 × value), in the image's units. */
  const veil = (value: number, d: number) => 9 * value * cieGlarePsf(d * pixelDeg) * ((pixelDeg * Math.PI) / 180) ** 2;

  it('energy: the total linear light before and after is the same within 1 % (a source 8000 × the background)', () => {
    const image = imageWith(400);
    const out = glare(image, true) as Float32Array;
    expect(Math.abs(total(out) / total(image) - 1)).toBeLessThan(0.01);
  });

  it('far from a bright source (400 × the background) a pixel keeps its value within 1 %; near it the veil lifts it; the source keeps its core share', () => {
    const value = 20;
    const out = glare(imageWith(value), true) as Float32Array;
    // 60 and more pixels (≥ 28°) away: the CIE veil there is < 0.3 % of the background.
    expect(veil(value, 60) / background).toBeLessThan(0.003);
    for (const [x, y] of [
      [110, 64],
      [100, 120],
      [127, 127],
      [105, 10],
    ])
      expect(Math.abs(at(out, x, y) / background - 1)).toBeLessThan(0.01);
    // 4 px (1.9°) away the CIE veil is ≈ 0.76 × the background: require at least + 30 %.
    expect(veil(value, 4) / background).toBeGreaterThan(0.6);
    expect(at(out, source.x + 4, source.y)).toBeGreaterThan(1.3 * background);
    // The source keeps only what is not scattered (core ≈ 0.9) plus what its neighbours scatter back.
    const { core } = glareWeights(pixelDeg, glareLevels(W, H), Math.hypot(W, H));
    expect(at(out, source.x, source.y)).toBeLessThan(value * (core + 0.06));
    expect(at(out, source.x, source.y)).toBeGreaterThan(value * core);
  });

  it('only the light above white (linear 1) scatters: a picture within the display range is unchanged, a source veils by its excess', () => {
    // Every pixel ≤ 1 (a lit room inside the exposure's range, with a 3 × 3 patch at 0.95): unchanged to half-float precision.
    const inRange = imageWith(0.95);
    const same = glare(inRange, true) as Float32Array;
    for (const [x, y] of [
      [source.x, source.y],
      [source.x + 4, source.y],
      [100, 100],
    ])
      expect(Math.abs(at(same, x, y) / at(inRange, x, y) - 1)).toBeLessThan(0.002);
    // A source of 20 (grey, m = 20) scatters its 19 above white and the background at 0.05 nothing: the
    // lift beside it equals the veil of the same source on black (within 1 %: the HDR target is half
    // float, so 16 px away the lift is below its precision over the background).
    const lit = glare(imageWith(20), true) as Float32Array;
    const onBlack = new Float32Array(W * H * 4);
    for (let dy = -1; dy <= 1; dy++) for (let dx = -1; dx <= 1; dx++) onBlack.set([20, 20, 20, 1], ((source.y + dy) * W + source.x + dx) * 4);
    const alone = glare(onBlack, true) as Float32Array;
    for (const d of [2, 4, 8]) expect(Math.abs((at(lit, source.x + d, source.y) - background) / at(alone, source.x + d, source.y) - 1)).toBeLessThan(0.01);
  });

  it('a uniform image stays uniform and gets the display transform of its value (1/255)', () => {
    const flat = new Float32Array(W * H * 4);
    for (let i = 0; i < W * H; i++) flat.set([0.18, 0.12, 0.3, 1], i * 4);
    const out = glare(flat, false) as Uint8Array;
    const want = displayColor([0.18, 0.12, 0.3], 1).map((c) => c * 255);
    for (const [x, y] of [
      [0, 0],
      [64, 64],
      [127, 5],
      [3, 127],
    ])
      for (let k = 0; k < 3; k++) expect(Math.abs(out[(y * W + x) * 4 + k] - want[k])).toBeLessThanOrEqual(1.01);
  });

  it("in the room view: on in light mode (the emitter's halo lights pixels beside it), off in lux mode (same pixels as without)", () => {
    const ph = parsePhotometry(readFileSync(join(__dirname, '../../../public/ies/bega_50975_downlight_lm1995_crlf.ies')), 'bega');
    const weight: Rgb = [1, 1, 1];
    const module: FixtureModule = {
      id: 'd1',
      centre: [0, 2, 0],
      heading: 0,
      length: 0.15,
      on: true,
      kind: 'downlight',
      orientation: { yaw: 0, pitch: 0, roll: 0 },
      mount: 0,
      light: { photometry: ph, opening: ph.luminousOpening, flux: hemisphereFlux(ph), weight },
    };
    const fixtures: Fixtures = { rails: [], railWidth: 0, connectors: [], cables: [], modules: [module] };
    const pose = { position: [0, 1.0, 0.01] as Vec3, target: [0, 2, 0] as Vec3, fov: 40 };
    const draw = (glareOn: boolean, mode: 'light' | 'lux') => {
      const view = createRoomView(renderer);
      view.setFixtures(fixtures);
      view.setExposure(1 / 50);
      view.setMode(mode, [10, 100]);
      view.setGlare(glareOn);
      view.setCamera(pose, 1);
      view.render(renderer);
      const px = new Uint8Array(W * H * 4);
      const gl = renderer.getContext();
      gl.readPixels(0, 0, W, H, gl.RGBA, gl.UNSIGNED_BYTE, px);
      const shown = view.glareShown();
      view.dispose();
      return { px, shown };
    };
    const off = draw(false, 'light');
    const on = draw(true, 'light');
    expect(off.shown).toBe(false);
    expect(on.shown).toBe(true);
    // A background pixel beside the lamp (the housing is ~ 20 px across at the centre): dark without glare, lit by the halo with it.
    const beside = (px: Uint8Array) => px[(64 * W + 64 + 30) * 4 + 1];
    expect(beside(off.px)).toBeLessThan(40);
    expect(beside(on.px)).toBeGreaterThan(beside(off.px) + 20);
    const luxOff = draw(false, 'lux');
    const luxOn = draw(true, 'lux');
    expect(luxOn.shown).toBe(false);
    expect(Buffer.from(luxOn.px).equals(Buffer.from(luxOff.px))).toBe(true);
  });
});
