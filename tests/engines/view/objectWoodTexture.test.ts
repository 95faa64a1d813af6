/**
 * The veneers' wood grain on furniture in the 3D view (headless-gl WebGL2): a dining table under a
 * spot pool (300 lx around, about 9 300 lx at its centre), seen straight down. With the grain the
 * mean displayed linear level over the top is the untextured ρ·E/π's within 1 % (the pattern
 * modulates ρ around its mean: docs/viewer.md "Surface textures", docs/furniture.md), the grain
 * shows (per-pixel ratio to the untextured picture varies), and after the tone curve the pool's
 * centre keeps the grain visible instead of burning to a flat colour (measured: means equal to
 * 1e-4, per-pixel ratio sd 7.6 %, in the pool an sd of 1.0/255 with the brightest pixel at 204/255).
 */
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { headlessRenderer } from './headlessRenderer';
import { furnitureMesh } from '../../../src/core/model/objects/furniture/furnitureLibrary';
import { prepareObjects } from '../../../src/engines/bake/objects/prepareObjects';
import { createRoomObjects } from '../../../src/engines/view/createRoomObjects';
import { createRoomSurfaces } from '../../../src/engines/view/createRoomSurfaces';

const W = 360;
const H = 180; // 5 mm pixels over the 1.8 × 0.9 m top
const renderer = headlessRenderer(W, H);

/** Spot pool: 300 lx plus a Gaussian of 9 000 lx and σ 0.3 m about the table's centre (2.5, 2). */
const poolE = (x: number, z: number) => 300 + 9000 * Math.exp(-((x - 2.5) ** 2 + (z - 2) ** 2) / (2 * 0.3 ** 2));

function tableScene() {
  const scene = new THREE.Scene();
  const surfaces = createRoomSurfaces(scene, renderer);
  const objects = createRoomObjects(surfaces.display, renderer);
  const prepared = prepareObjects([{ id: 'table', mesh: furnitureMesh('dining-table'), position: [2.5, 0, 2], yaw: 0, scale: 1 }], { texelSize: 0.05 });
  const { atlas } = prepared;
  const total = new Float32Array(atlas.width * atlas.height * 3);
  for (let t = 0; t < atlas.width * atlas.height; t++) total.fill(poolE(atlas.position[4 * t], atlas.position[4 * t + 2]), 3 * t, 3 * t + 3);
  objects.setGeometry(prepared);
  objects.setLight({ atlas, total });
  scene.add(objects.group);
  const camera = new THREE.OrthographicCamera(-0.9, 0.9, 0.45, -0.45, 0.1, 5);
  camera.position.set(2.5, 2, 2);
  camera.up.set(0, 0, -1);
  camera.lookAt(2.5, 0, 2);
  return { scene, surfaces, objects, camera };
}

/** One frame into a float target: mode 2 is the exposed linear radiance, mode 0 the display value in [0, 1]. */
function render(t: ReturnType<typeof tableScene>, mode: number, textures: boolean): Float32Array {
  t.objects.setFinishTextures(textures);
  t.surfaces.display.uMode.value = mode;
  const target = new THREE.WebGLRenderTarget(W, H, { type: THREE.FloatType });
  renderer.setRenderTarget(target);
  renderer.render(t.scene, t.camera);
  renderer.setRenderTarget(null);
  const out = new Float32Array(W * H * 4);
  renderer.readRenderTargetPixels(target, 0, 0, W, H, out);
  target.dispose();
  return out;
}

describe('wood grain on a table under a spot', () => {
  const t = tableScene();
  // Exposed for 300 lx on ρ 0.5: the pool's centre is about 30 times brighter than the room's key.
  t.surfaces.setExposure(0.18 / ((0.5 * 300) / Math.PI));

  it('mean linear level over the top = the untextured ρ·E/π mean within 1 % per channel; the grain varies it pixel to pixel', () => {
    const plain = render(t, 2, false);
    const grain = render(t, 2, true);
    const ratios: number[] = [];
    for (let c = 0; c < 3; c++) {
      let a = 0;
      let b = 0;
      for (let k = 0; k < W * H; k++) {
        a += grain[4 * k + c];
        b += plain[4 * k + c];
        if (c === 1) ratios.push(grain[4 * k + 1] / plain[4 * k + 1]);
      }
      console.info(`channel ${c}: textured/plain mean ${(a / b).toFixed(4)}`);
      expect(Math.abs(a / b - 1)).toBeLessThan(0.01);
    }
    const mean = ratios.reduce((s, r) => s + r, 0) / ratios.length;
    const sd = Math.sqrt(ratios.reduce((s, r) => s + (r - mean) ** 2, 0) / ratios.length);
    console.info(`per-pixel textured/plain ratio: sd ${sd.toFixed(4)}`);
    expect(sd).toBeGreaterThan(0.03);
  });

  it('after the tone curve, the pool (E ≥ 5 000 lx) keeps the grain: the textured minus the plain display value varies by more than half a level (sd, of 255), unclipped', () => {
    const plain = render(t, 0, false);
    const grain = render(t, 0, true);
    const inPool: number[] = [];
    const difference: number[] = [];
    for (let row = 0; row < H; row++) {
      for (let col = 0; col < W; col++) {
        // Pixel centre in world x, z (row 0 is the bottom of the image: +z, the camera's up is −z).
        const x = 1.6 + ((col + 0.5) / W) * 1.8;
        const z = 2.45 - ((row + 0.5) / H) * 0.9;
        if (poolE(x, z) < 5000) continue;
        inPool.push(grain[4 * (row * W + col) + 1]);
        difference.push(grain[4 * (row * W + col) + 1] - plain[4 * (row * W + col) + 1]);
      }
    }
    const sd = (v: number[]) => {
      const m = v.reduce((s, x) => s + x, 0) / v.length;
      return Math.sqrt(v.reduce((s, x) => s + (x - m) ** 2, 0) / v.length);
    };
    console.info(`pool pixels ${inPool.length}: sd of textured − plain ${(255 * sd(difference)).toFixed(2)}/255, brightest ${(255 * Math.max(...inPool)).toFixed(1)}/255`);
    expect(inPool.length).toBeGreaterThan(1000);
    expect(Math.max(...inPool)).toBeLessThan(1); // not clipped to white
    expect(255 * sd(difference)).toBeGreaterThan(0.5);
  });
});
