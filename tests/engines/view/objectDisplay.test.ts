/**
 * The objects' shader (shaders/objectSurface.glsl.ts) on a headless-gl three.js renderer draws
 * what the walls' display transform says (toneMap.ts, the TypeScript mirror of the GLSL): seen
 * from above, every pixel of a dining table's top under uniform light is displayColor(ρ·E/π,
 * exposure) within 2/255, right up to the top's outline (0.07 m texels, so the outline falls
 * inside texels): no dark seam, nothing of another chart's colour.
 */
import { headlessRenderer } from './headlessRenderer';
import { describe, expect, it } from 'vitest';
import { furnitureMesh } from '../../../src/core/model/objects/furniture/furnitureLibrary';
import { objectFinishRgb } from '../../../src/core/model/objects/furniture/objectFinishes';
import type { Rgb } from '../../../src/core/model/lightingScene/lightingScene';
import { prepareObjects } from '../../../src/engines/bake/objects/prepareObjects';
import { createRoomView } from '../../../src/engines/view/roomView';
import { displayColor } from '../../../src/engines/view/toneMap';

const W = 160;
const H = 120;
const renderer = headlessRenderer(W, H);
const gl = renderer.getContext();

describe('objects on screen', () => {
  it('the table top from above: displayColor(ρE/π · exposure) on every pixel inside its outline', () => {
    const prepared = prepareObjects([{ id: 'table', mesh: furnitureMesh('dining-table'), position: [2.5, 0, 2], yaw: 0, scale: 1 }], { texelSize: 0.07 });
    const { atlas } = prepared;
    const E: Rgb = [300, 220, 150];
    const total = new Float32Array(atlas.width * atlas.height * 3);
    for (let t = 0; t < atlas.width * atlas.height; t++) total.set(E, 3 * t);
    const view = createRoomView(renderer);
    view.setObjects(prepared);
    view.setObjectLight({ atlas, total });
    const exposure = 0.02;
    view.setExposure(exposure);
    view.setMode('light');
    // The pure map: the veneer's grain (objectWoodTexture.test.ts) would modulate ρ around its mean.
    view.setFinishTextures(false);
    // Straight down from 1.75 m above the top (a hair off vertical so "up" is defined): the top spans every column.
    view.setCamera({ position: [2.5, 2.5, 2.0 + 1e-3], target: [2.5, 0.75, 2.0], fov: 40 }, W / H);
    view.render(renderer);
    const raw = new Uint8Array(W * H * 4);
    gl.readPixels(0, 0, W, H, gl.RGBA, gl.UNSIGNED_BYTE, raw);
    view.dispose();

    const rho = objectFinishRgb('oak-veneer');
    const want = displayColor([(rho[0] * E[0]) / Math.PI, (rho[1] * E[1]) / Math.PI, (rho[2] * E[2]) / Math.PI], exposure).map((c) => c * 255);
    // The top's half depth (0.45 m) at 1.75 m under a 40° field: rows within ±0.45/(1.75·tan 20°) of the centre.
    const halfRows = Math.floor((0.45 / (1.75 * Math.tan((20 * Math.PI) / 180))) * (H / 2)) - 1;
    let worst = 0;
    let pixels = 0;
    for (let y = H / 2 - halfRows; y < H / 2 + halfRows; y++) {
      for (let x = 0; x < W; x++) {
        const o = 4 * (y * W + x);
        for (let c = 0; c < 3; c++) worst = Math.max(worst, Math.abs(raw[o + c] - want[c]));
        pixels++;
      }
    }
    expect(pixels).toBeGreaterThan(W * H * 0.6);
    expect(worst).toBeLessThanOrEqual(2);
  });
});
