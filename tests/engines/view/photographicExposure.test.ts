import { headlessRenderer } from './headlessRenderer';
import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../../src/core/model/lightingScene/lightingScene';
import { surfaceLayouts } from '../../../src/engines/bake/surfaceLayout';
import { emptyLitMaps } from '../../../src/engines/relight/relightMaps';
import { autoExposure } from '../../../src/engines/view/autoExposure';
import { createMapDisplay } from '../../../src/engines/view/createMapDisplay';
import { ev100FromExposure, exposureFromEv100, isEv100, saturationLuminance } from '../../../src/engines/view/photographicExposure';
import { appliedExposure, presentMaps } from '../../../src/engines/view/presentMaps';
import { createRoomView, type RoomView } from '../../../src/engines/view/roomView';
import { displayColor } from '../../../src/engines/view/toneMap';

/**
 * Absolute exposure (photographicExposure.ts): the saturation-based formula
 * L_max = 78/(S·q) · 2^EV100 at S = 100, q = 0.65 (ISO 12232:2006; Lagarde & de
 * Rousiers 2014, §5.1.2), and what it does to a room of uniform luminance.
 */
const room = { width: 4, height: 2.5, depth: 3 };
const grey = Object.fromEntries(SURFACE_NAMES.map((n) => [n, [0.5, 0.5, 0.5]])) as Record<SurfaceName, Rgb>;

function uniformRoom(lux: number) {
  const lit = emptyLitMaps(surfaceLayouts(room, 0.25, 64));
  for (const name of SURFACE_NAMES) {
    lit.maps[name].total.fill(lux);
    lit.maps[name].direct.fill(lux);
  }
  return lit;
}

describe('EV100 → exposure (saturation-based)', () => {
  it('hand-computed reference points: EV100 0 → 1.2 cd/m², 5 → 38.4, −2 → 0.3; exposure is 1/L_max; the inverse round-trips', () => {
    expect(saturationLuminance(0)).toBeCloseTo(78 / 65, 12);
    expect(saturationLuminance(0)).toBeCloseTo(1.2, 12);
    expect(saturationLuminance(5)).toBeCloseTo(38.4, 10);
    expect(saturationLuminance(-2)).toBeCloseTo(0.3, 12);
    expect(exposureFromEv100(5)).toBeCloseTo(1 / 38.4, 14);
    // One stop more light needed to saturate = half the exposure.
    expect(exposureFromEv100(8) / exposureFromEv100(7)).toBeCloseTo(0.5, 14);
    for (const ev of [-6, -1.5, 0, 3.25, 12, 20]) expect(ev100FromExposure(exposureFromEv100(ev))).toBeCloseTo(ev, 10);
    expect([isEv100(5), isEv100(-6), isEv100(20), isEv100(20.5), isEv100(Number.NaN), isEv100('5')]).toEqual([true, true, true, false, false, false]);
  });

  it('presentMaps: a fixed EV100 ignores the compensation and the maps; auto exposure follows them; ev100 reports the one applied', () => {
    const calls: number[] = [];
    const view = { setMaps() {}, setObjectLight() {}, setMode() {}, setAdaptation() {}, setExposure: (x: number) => calls.push(x) } as unknown as RoomView;
    const bright = uniformRoom(400);
    const dim = uniformRoom(100);
    const fixedBright = presentMaps(view, bright, grey, { exposureEv: 2, ev100: 5, mode: 'light' });
    const fixedDim = presentMaps(view, dim, grey, { exposureEv: 2, ev100: 5, mode: 'light' });
    expect(fixedBright.exposure).toBeCloseTo(1 / 38.4, 14);
    expect(fixedDim.exposure).toBe(fixedBright.exposure);
    expect(fixedBright.ev100).toBeCloseTo(5, 10);
    // Auto: the key 0.18 over the log-average luminance ρE/π of a uniform room, times 2^compensation.
    const autoDim = presentMaps(view, dim, grey, { exposureEv: 1, mode: 'light' });
    expect(autoDim.autoExposure).toBeCloseTo(0.18 / ((0.5 * 100) / Math.PI), 6);
    expect(autoDim.exposure).toBeCloseTo(2 * autoDim.autoExposure, 12);
    expect(autoDim.ev100).toBeCloseTo(ev100FromExposure(autoDim.exposure), 12);
    expect(calls).toEqual([fixedBright.exposure, fixedDim.exposure, autoDim.exposure]);
    expect(appliedExposure(autoExposure(dim, grey), { exposureEv: 0, ev100: null })).toBeCloseTo(autoExposure(dim, grey), 14);
  });

  it('map display: lock at the current value keeps the exposure when the light changes (dimmed maps then show darker)', () => {
    let lastExposure = 0;
    const view = { setMaps() {}, setObjectLight() {}, setMode() {}, setAdaptation() {}, setExposure: (x: number) => (lastExposure = x) } as unknown as RoomView;
    const heard: number[] = [];
    let now = 0;
    const display = createMapDisplay(
      () => view,
      (_lit, info) => heard.push(info.ev100),
      () => now,
    );
    const room = { white: null, key: 'room', done: true };
    display.show(uniformRoom(400), grey, 0, room);
    const autoAt400 = lastExposure;
    // Lock: the EV100 of what auto chose for 400 lx.
    const locked = display.currentEv100();
    expect(locked).toBeCloseTo(ev100FromExposure(autoAt400), 12);
    display.setEv100(locked);
    expect(lastExposure).toBeCloseTo(autoAt400, 12);
    display.show(uniformRoom(100), grey, 0, room);
    expect(lastExposure).toBeCloseTo(autoAt400, 12); // not re-exposed for a quarter of the light
    // Back to auto: the same room only dimmed (a relight), so the eye still holds what it adapted to.
    display.setEv100(null);
    expect(lastExposure).toBeCloseTo(autoAt400, 12);
    // Re-adapt: after 10 τ the 100 lx room gets 4× the exposure (log-average luminance ÷ 4).
    display.reAdapt();
    now = 4000;
    expect(display.advance(now)).toBe(false);
    expect(lastExposure / autoAt400).toBeCloseTo(4, 6);
    expect(heard.at(-1)).toBeCloseTo(locked - 2, 6);
  });
});

describe('uniform room on screen (three.js on headless-gl)', () => {
  const W = 32;
  const H = 24;
  const renderer = headlessRenderer(W, H);
  const gl = renderer.getContext();

  function centrePixel(lux: number, ev100: number): number[] {
    const view = createRoomView(renderer);
    // One pixel against ρE/π: without the finish's texture (its mean is ρ over a period, not at one pixel: finishTextureRender.test.ts).
    view.setFinishTextures(false);
    presentMaps(view, uniformRoom(lux), grey, { exposureEv: 0, ev100, mode: 'light' });
    // Looking at the north wall from the middle of the room.
    view.setCamera({ position: [2, 1.25, 2.5], target: [2, 1.25, 0], fov: 40 }, W / H);
    view.render(renderer);
    const px = new Uint8Array(4);
    gl.readPixels(W / 2, H / 2, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
    view.dispose();
    return [px[0], px[1], px[2]];
  }

  it('E = 100 lx, ρ = 0.5: L = ρE/π = 15.92 cd/m²; at EV100 4 (L_max 19.2) the pixel is AgX+sRGB of 0.829 (no white lamp: no adaptation)', () => {
    const L = (0.5 * 100) / Math.PI;
    const x = L / (1.2 * 2 ** 4);
    expect(x).toBeCloseTo(0.82893, 4);
    const want = displayColor([x, x, x], 1).map((v) => v * 255);
    // AgX's grey at 0.829 (log2 encoding (log2 0.829 + 12.47393)/16.5 = 0.73953, sigmoid, outset, 2.2 power, back to sRGB):
    // linear 0.5455, sRGB 194.97 of 255, recomputed independently of toneMap.ts.
    expect(want[1]).toBeCloseTo(194.96, 1);
    const got = centrePixel(100, 4);
    for (let k = 0; k < 3; k++) expect(Math.abs(got[k] - want[k])).toBeLessThanOrEqual(1.01);
    // A stop less light at a stop lower EV100: the same pixel (L·exposure unchanged).
    const half = centrePixel(50, 3);
    for (let k = 0; k < 3; k++) expect(Math.abs(half[k] - got[k])).toBeLessThanOrEqual(1);
    // And at the same EV100 it is darker.
    expect(centrePixel(50, 4)[1]).toBeLessThan(got[1] - 20);
  });
});
