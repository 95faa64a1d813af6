/**
 * Windows in the 3D view (issue 30, docs/daylight.md "Windows in the 3D view"), drawn by three.js on
 * headless-gl: the exposed luminance of each pane pixel before the tone curve (mode 2, the glare
 * pass's HDR value) against L_outside(d) · τ(θ) · exposure computed on the CPU with the core's sky
 * and glazing (skies.ts, glazing.ts: not the shader's code) along the pixel's own view ray; sky
 * above the horizon, ground ρ_g E_h / π below; the night sky without daylight.
 */
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { glazingFrom, glazingTransmittance, type Glazing } from '../../../src/core/daylight/glazing';
import { cieGeneralSky, cieOvercastSky, CIE_CLEAR_SKY_TYPE, groundLuminance, uniformSky, type Sky } from '../../../src/core/daylight/skies';
import { sunDirection } from '../../../src/core/daylight/solarPosition';
import type { BakeDaylight } from '../../../src/engines/bake/daylight/bakeDaylight';
import { createWindowPanes } from '../../../src/engines/view/createWindowPanes';
import type { SharedDisplayUniforms } from '../../../src/engines/view/createRoomSurfaces';
import { NIGHT_SKY_LUMINANCE, WINDOW_FRAME_WIDTH } from '../../../src/engines/view/windowPaneUniforms';
import { shapedBakeRoom } from '../bake/shapedRoomKit';
import { headlessRenderer } from './headlessRenderer';
import { daylightBox } from '../../../src/hosts/bench/daylightBox';

const W = 96;
const H = 96;
const renderer = headlessRenderer(W, H);
const EXPOSURE = 0.01;

// 5 × 4 m, a 1.5 × 1.4 m window in the south wall (z = 4) from x = 1.75 to 3.25, sill 0.9 m.
const room = shapedBakeRoom(daylightBox());
const WINDOW = { x: [1.75, 3.25], y: [0.9, 2.3], z: 4 };

function display(): SharedDisplayUniforms {
  return { uExposure: { value: EXPOSURE }, uAdapt: { value: new THREE.Matrix3() }, uMode: { value: 2 }, uLevels: { value: [1] }, uLevelCount: { value: 0 } };
}

/** Renders the panes seen from inside the room (mode 2) and compares each pane pixel clear of the frame with the CPU's L·τ·exposure; returns the worst relative error and the pixels compared. */
function compare(daylight: BakeDaylight | null, glazing: Glazing, outsideAt: (d: THREE.Vector3) => number): { worst: number; sky: number; ground: number } {
  const scene = new THREE.Scene();
  const panes = createWindowPanes(display());
  panes.set(room.shape, daylight, new Map([[0, glazing]]));
  scene.add(panes.group);
  const camera = new THREE.PerspectiveCamera(70, W / H, 0.05, 50);
  camera.position.set(2.3, 1.4, 2.6);
  camera.lookAt(2.5, 1.5, 4);
  camera.updateMatrixWorld();
  const target = new THREE.WebGLRenderTarget(W, H, { type: THREE.FloatType });
  renderer.setRenderTarget(target);
  renderer.setClearColor(0x000000, 0);
  renderer.clear();
  renderer.render(scene, camera);
  renderer.setRenderTarget(null);
  const px = new Float32Array(W * H * 4);
  renderer.readRenderTargetPixels(target, 0, 0, W, H, px);
  target.dispose();
  panes.dispose();
  const margin = WINDOW_FRAME_WIDTH + 0.02;
  let worst = 0;
  let sky = 0;
  let ground = 0;
  for (let j = 0; j < H; j++) {
    for (let i = 0; i < W; i++) {
      const d = new THREE.Vector3(((i + 0.5) / W) * 2 - 1, ((j + 0.5) / H) * 2 - 1, 0.5).unproject(camera).sub(camera.position).normalize();
      // Where the pixel's ray crosses the window's plane: only rays through the glass, clear of the frame.
      const t = (WINDOW.z - camera.position.z) / d.z;
      const x = camera.position.x + t * d.x;
      const y = camera.position.y + t * d.y;
      if (x < WINDOW.x[0] + margin || x > WINDOW.x[1] - margin || y < WINDOW.y[0] + margin || y > WINDOW.y[1] - margin) continue;
      const expected = outsideAt(d) * glazingTransmittance(glazing, d.z) * EXPOSURE;
      const got = px[(j * W + i) * 4];
      expect(px[(j * W + i) * 4 + 1]).toBeCloseTo(got, 6);
      worst = Math.max(worst, Math.abs(got / expected - 1));
      if (d.y > 0) sky++;
      else ground++;
    }
  }
  return { worst, sky, ground };
}

const dir = (d: THREE.Vector3): [number, number, number] => [d.x, d.y, d.z];

describe('a window shows the sky and the ground through its glazing (exposed luminance before the tone curve)', () => {
  const cases: { name: string; sky: Sky; sunH: number; glazing: Glazing }[] = [
    { name: 'CIE overcast, double glazing', sky: cieOvercastSky(10_000), sunH: 0, glazing: glazingFrom('double') },
    { name: 'CIE clear (type 12), sun at 35° azimuth 200°, single glazing', sky: cieGeneralSky(CIE_CLEAR_SKY_TYPE, sunDirection(35, 200), 15_000), sunH: 60_000 * Math.sin((35 * Math.PI) / 180), glazing: glazingFrom('single') },
    { name: 'uniform sky, an open window', sky: uniformSky(8_000), sunH: 0, glazing: glazingFrom(1) },
  ];
  for (const c of cases) {
    it(`${c.name}: every pane pixel within 1 % of L·τ(θ)·exposure`, () => {
      const lg = groundLuminance(c.sky.horizontalIlluminance, c.sunH, 0.2);
      const daylight: BakeDaylight = { sky: c.sky, sun: null, groundLuminance: lg, glazing: new Map([[0, c.glazing]]) };
      const r = compare(daylight, c.glazing, (d) => (d.y > 0 ? c.sky.luminance(dir(d)) : lg));
      console.log(`${c.name}: ${r.sky} sky and ${r.ground} ground pixels, worst ${(100 * r.worst).toFixed(3)} %`);
      expect(r.sky).toBeGreaterThan(200);
      expect(r.ground).toBeGreaterThan(100);
      expect(r.worst).toBeLessThan(0.01);
    });
  }

  it('without daylight: the night sky, 0.001 cd/m² through the glass', () => {
    const g = glazingFrom('double');
    const r = compare(null, g, () => NIGHT_SKY_LUMINANCE);
    expect(r.sky + r.ground).toBeGreaterThan(300);
    expect(r.worst).toBeLessThan(0.01);
  });
});
