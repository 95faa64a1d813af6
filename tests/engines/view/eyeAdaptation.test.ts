import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../../src/core/model/lightingScene/lightingScene';
import { surfaceLayouts } from '../../../src/engines/bake/surfaceLayout';
import { emptyLitMaps, type LitMaps } from '../../../src/engines/relight/relightMaps';
import { cctToLinearRgb } from '../../../src/core/photometry/cct';
import { createMapDisplay } from '../../../src/engines/view/createMapDisplay';
import type { Mat3 } from '../../../src/engines/view/colourMatrices';
import { ADAPTATION_TAU_S, AUTO_EV100_MAX, AUTO_EV100_MIN, createEyeAdaptation, limitAutoExposure } from '../../../src/engines/view/eyeAdaptation';
import { ev100FromExposure, exposureFromEv100 } from '../../../src/engines/view/photographicExposure';
import type { RoomView } from '../../../src/engines/view/roomView';
import { adaptedLinear, displayColor } from '../../../src/engines/view/toneMap';

const room = { width: 4, height: 2.5, depth: 3 };
const grey = Object.fromEntries(SURFACE_NAMES.map((n) => [n, [0.5, 0.5, 0.5]])) as Record<SurfaceName, Rgb>;
const warm = cctToLinearRgb(3000);

/** A room whose texel i of each surface has warm light of (1 + i mod 7) × `lux` lux. */
function roomAt(lux: number): LitMaps {
  const lit = emptyLitMaps(surfaceLayouts(room, 0.25, 64));
  for (const name of SURFACE_NAMES) {
    const t = lit.maps[name].total;
    for (let i = 0; i < t.length / 3; i++) for (let k = 0; k < 3; k++) t[3 * i + k] = (1 + (i % 7)) * lux * warm[k];
  }
  return lit;
}

function fakeView() {
  const state = { exposure: 0, adapt: null as Mat3 | null };
  const view = { setMaps() {}, setObjectLight() {}, setMode() {}, setExposure: (x: number) => (state.exposure = x), setAdaptation: (m: Mat3) => (state.adapt = m) } as unknown as RoomView;
  return { view, state };
}

describe('eye adaptation: slow, within limits, held on relights', () => {
  it('moves in log luminance with τ = 0.4 s: after τ, 1 − 1/e of the way; settles (snaps) within 10 τ', () => {
    const eye = createEyeAdaptation();
    // Exposures inside the limits (EV100 ≈ 5.4 and 7.4).
    eye.update({ auto: 0.02, white: null }, 'a', true, 0);
    expect(eye.state(0)!.auto).toBeCloseTo(0.02, 12);
    eye.update({ auto: 0.005, white: null }, 'b', false, 1000);
    expect(eye.state(1000)!.auto).toBeCloseTo(0.02, 12);
    const tau = ADAPTATION_TAU_S * 1000;
    expect(Math.log(eye.state(1000 + tau)!.auto / 0.02)).toBeCloseTo(Math.log(0.25) * (1 - Math.exp(-1)), 9);
    expect(eye.moving(1000 + tau)).toBe(true);
    expect(eye.state(1000 + 10 * tau)!.auto).toBeCloseTo(0.005, 12);
    expect(eye.moving(1000 + 10 * tau)).toBe(false);
  });

  it('limits: the automatic exposure stays within EV100 0..15', () => {
    expect(ev100FromExposure(limitAutoExposure(exposureFromEv100(-3)))).toBeCloseTo(AUTO_EV100_MIN, 10);
    expect(ev100FromExposure(limitAutoExposure(exposureFromEv100(18)))).toBeCloseTo(AUTO_EV100_MAX, 10);
    expect(limitAutoExposure(exposureFromEv100(6))).toBeCloseTo(exposureFromEv100(6), 14);
    expect(Number.isFinite(limitAutoExposure(Number.NaN))).toBe(true);
    expect(Number.isFinite(limitAutoExposure(0))).toBe(true);
  });

  it("held: dimming to 50 % halves every pixel's scene value before the tone curve, the exposure and adaptation stay, the mean screen level falls", () => {
    const { view, state } = fakeView();
    const display = createMapDisplay(
      () => view,
      () => {},
      () => 0,
    );
    const white = warm;
    const full = roomAt(300);
    display.show(full, grey, 0, { white, key: 'room', done: true });
    const exposure = state.exposure;
    const adapt = state.adapt!;
    expect(display.held()).toBe(true);
    display.show(roomAt(150), grey, 0, { white, key: 'room', done: false });
    expect(state.exposure).toBe(exposure);
    expect(state.adapt).toEqual(adapt);
    let meanFull = 0;
    let meanHalf = 0;
    const t = full.maps.floor.total;
    const n = t.length / 3;
    for (let i = 0; i < n; i++) {
      const L: Rgb = [(0.5 * t[3 * i]) / Math.PI, (0.5 * t[3 * i + 1]) / Math.PI, (0.5 * t[3 * i + 2]) / Math.PI];
      const half: Rgb = [L[0] / 2, L[1] / 2, L[2] / 2];
      const a = adaptedLinear(L, state.exposure, state.adapt!);
      const b = adaptedLinear(half, state.exposure, state.adapt!);
      for (let k = 0; k < 3; k++) expect(b[k]).toBeCloseTo(a[k] / 2, 12);
      meanFull += displayColor(L, state.exposure, state.adapt!)[1] / n;
      meanHalf += displayColor(half, state.exposure, state.adapt!)[1] / n;
    }
    expect(meanHalf).toBeLessThan(meanFull - 0.05);
  });

  it('follows the maps of a configuration until its light is done; a new room, a camera cut (reAdapt) adapt again', () => {
    const { view, state } = fakeView();
    let now = 0;
    const display = createMapDisplay(
      () => view,
      () => {},
      () => now,
    );
    // Progressive bake of the first room: not done yet, the exposure follows (first maps: at once).
    display.show(roomAt(100), grey, 0, { white: warm, key: 'a', done: false });
    const first = state.exposure;
    display.show(roomAt(200), grey, 0, { white: warm, key: 'a', done: true });
    now = 10_000;
    display.advance(now);
    expect(state.exposure).toBeCloseTo(first / 2, 9);
    // A relight of the finished room: held.
    display.show(roomAt(50), grey, 0, { white: warm, key: 'a', done: false });
    display.advance((now += 10_000));
    expect(state.exposure).toBeCloseTo(first / 2, 9);
    // Re-adapt (the button, a camera preset): slowly to the dimmed light.
    display.reAdapt();
    expect(display.advance(now + 100)).toBe(true);
    expect(state.exposure).toBeGreaterThan(first / 2);
    expect(state.exposure).toBeLessThan(first * 2);
    expect(display.advance((now += 10_000))).toBe(false);
    expect(state.exposure).toBeCloseTo(first * 2, 9);
    // Another room: adapts again.
    display.show(roomAt(400), grey, 0, { white: warm, key: 'b', done: true });
    display.advance((now += 10_000));
    expect(state.exposure).toBeCloseTo(first / 4, 9);
  });
});
