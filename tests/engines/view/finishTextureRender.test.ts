/**
 * The finishes' patterns as the 3D view draws them (headless-gl WebGL2): the rendered linear
 * radiance over a textured floor has the untextured mean within 1 % (the mean-ρ rule, docs/viewer.md
 * "Surface textures"), and lux mode's pixels do not change with the patterns.
 */
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { headlessRenderer } from './headlessRenderer';
import { defaultSurfaceFinishes } from '../../../src/core/catalog/surfaceFinishes';
import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../../src/core/model/lightingScene/lightingScene';
import { surfaceLayouts } from '../../../src/engines/bake/surfaceLayout';
import { emptyLitMaps } from '../../../src/engines/relight/relightMaps';
import { createRoomSurfaces } from '../../../src/engines/view/createRoomSurfaces';
import { finishModulation } from '../../../src/engines/view/finishTexture';
import { FINISH_TEXTURE_OF } from '../../../src/engines/view/finishTextureKinds';

const W = 192;
const renderer = headlessRenderer(W, W);
const rgb = (r: number | Rgb): Rgb => (typeof r === 'number' ? [r, r, r] : r);

/** A square room whose floor spans a whole number of the pattern's periods, lit 300 lx everywhere, seen straight down by an orthographic camera framing the floor exactly. */
function floorScene(floor: Rgb, side: number) {
  const scene = new THREE.Scene();
  const surfaces = createRoomSurfaces(scene, renderer);
  const layouts = surfaceLayouts({ width: side, height: 2.5, depth: side }, 0.1, 64);
  const lit = emptyLitMaps(layouts);
  for (const name of SURFACE_NAMES) lit.maps[name].total.fill(300);
  const reflectance = Object.fromEntries(SURFACE_NAMES.map((n) => [n, n === 'floor' ? floor : ([0.8, 0.8, 0.8] as Rgb)])) as Record<SurfaceName, Rgb>;
  surfaces.setMaps(lit, reflectance);
  surfaces.setExposure(0.01);
  const camera = new THREE.OrthographicCamera(-side / 2, side / 2, side / 2, -side / 2, 0.1, 20);
  camera.position.set(side / 2, 2, side / 2);
  camera.up.set(0, 0, -1);
  camera.lookAt(side / 2, 0, side / 2);
  return { scene, surfaces, camera };
}

/** The exposed linear radiance (mode 2: the glare pass's HDR input, before the tone curve), per pixel RGBA. */
function renderLinear(scene: THREE.Scene, camera: THREE.Camera, surfaces: ReturnType<typeof createRoomSurfaces>): Float32Array {
  surfaces.display.uMode.value = 2;
  const target = new THREE.WebGLRenderTarget(W, W, { type: THREE.FloatType });
  renderer.setRenderTarget(target);
  renderer.render(scene, camera);
  renderer.setRenderTarget(null);
  const out = new Float32Array(W * W * 4);
  renderer.readRenderTargetPixels(target, 0, 0, W, W, out);
  target.dispose();
  return out;
}

const channelStats = (px: Float32Array | Uint8Array, c: number) => {
  let s = 0;
  let s2 = 0;
  const n = px.length / 4;
  for (let k = 0; k < n; k++) {
    s += px[k * 4 + c];
    s2 += px[k * 4 + c] ** 2;
  }
  return { mean: s / n, sd: Math.sqrt(Math.max(s2 / n - (s / n) ** 2, 0)) };
};

describe('surface textures in the 3D view', () => {
  const floors = defaultSurfaceFinishes.filter((f) => FINISH_TEXTURE_OF[f.id] && f.uses.includes('floor'));
  it.each(floors.map((f) => [f.id, f] as const))('%s: the textured floor renders the untextured mean within 1 %', (_, finish) => {
    const rho = rgb(finish.reflectance);
    const period = finishModulation(FINISH_TEXTURE_OF[finish.id], rho).period;
    const side = period * Math.max(1, Math.round(3 / period));
    const { scene, surfaces, camera } = floorScene(rho, side);
    const textured = renderLinear(scene, camera, surfaces);
    surfaces.setFinishTextures(false);
    const plain = renderLinear(scene, camera, surfaces);
    for (let c = 0; c < 3; c++) {
      const t = channelStats(textured, c);
      const p = channelStats(plain, c);
      // Untextured: ρ·E/π·exposure everywhere (the adaptation is the identity here).
      expect(p.mean).toBeCloseTo((rho[c] * 300 * 0.01) / Math.PI, 4);
      expect(Math.abs(t.mean / p.mean - 1)).toBeLessThan(0.01);
      // The pattern shows: a spread of at least 1 % of the mean.
      expect(t.sd / t.mean).toBeGreaterThan(0.01);
    }
    surfaces.dispose();
  });

  it('lux mode: identical pixels with and without the patterns', () => {
    const { scene, surfaces, camera } = floorScene(rgb(defaultSurfaceFinishes.find((f) => FINISH_TEXTURE_OF[f.id] === 'wood')!.reflectance), 2.88);
    const shot = () => {
      surfaces.setMode('lux', [100, 200, 300, 500]);
      renderer.render(scene, camera);
      const gl = renderer.getContext();
      const px = new Uint8Array(W * W * 4);
      gl.readPixels(0, 0, W, W, gl.RGBA, gl.UNSIGNED_BYTE, px);
      return px;
    };
    const withTextures = shot();
    surfaces.setFinishTextures(false);
    const without = shot();
    expect(channelStats(withTextures, 0).mean).toBeGreaterThan(0);
    expect(Buffer.from(withTextures).equals(Buffer.from(without))).toBe(true);
    surfaces.dispose();
  });
});
