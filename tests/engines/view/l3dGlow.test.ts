/**
 * An L3D body's light-emitting object glows at its real luminance (docs/gldf.md "L3D in the 3D
 * view"): the hand-made track spot (buildL3dSpot.ts: a Ø 50 mm lens) drawn by the room's hardware on
 * headless-gl, seen from 10 cm below the lens so its face fills the view, and the same for the panel
 * (buildL3dPanel.ts) whose LightEmittingSurface (the housing's bottom faces) glows. Before the tone
 * curve the pixel is L × weight × exposure with L = I(γ)/(A·cos γ) toward the eye (the same rule as
 * the built models, luminaires/viewLuminance.ts), A the area worked out by hand (π·(0.05 m)²/4 for
 * the lens, 0.62 × 0.32 m for the faces) and I the file's intensity toward the eye, 0.3° off the
 * axis; on screen it is the room's display transform of that (displayColor), within one 8-bit step.
 * The downward flux integrated independently checks the view is given the file's light.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { Rgb, Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import { parsePhotometry } from '../../../src/core/photometry/parsePhotometry';
import { intensity } from '../../../src/core/photometry/intensity';
import { hemisphereFlux } from '../../../src/engines/view/luminaires/hemisphereFlux';
import { l3dOpening } from '../../../src/engines/view/luminaires/l3dOpening';
import { readL3dBody } from '../../../src/engines/view/luminaires/readL3dBody';
import { displayColor } from '../../../src/engines/view/toneMap';
import { panelL3d } from '../../core/gldf/buildL3dPanel';
import { spotL3d } from '../../core/gldf/buildL3dSpot';
import { headlessRenderer } from './headlessRenderer';
import { centreViewPixel, linearHardwareShot, oneLuminaire } from './glowShots';

const W = 16;
const H = 16;

/** Downward flux by a midpoint sum over γ < 90° and C (0.25° × 1°) of I·sin γ: independent of integrateFlux. */
function downwardFlux(ph: Parameters<typeof intensity>[0]): number {
  const dg = 0.25;
  const dc = 1;
  let sum = 0;
  for (let g = dg / 2; g < 90; g += dg) {
    for (let c = dc / 2; c < 360; c += dc) sum += intensity(ph, g, c) * Math.sin((g * Math.PI) / 180);
  }
  return sum * ((dg * Math.PI) / 180) * ((dc * Math.PI) / 180);
}

describe.each([
  { what: 'the track spot’s lens (a Circle, Ø 50 mm)', bytes: spotL3d(), area: (Math.PI * 0.05 ** 2) / 4 },
  { what: 'the panel’s LightEmittingSurface (the housing’s 0.62 × 0.32 m bottom, not its 0.6 × 0.3 m object)', bytes: panelL3d({ surfaces: true }), area: 0.62 * 0.32 },
])('$what on screen (three.js on headless-gl)', ({ bytes, area }) => {
  const renderer = headlessRenderer(W, H);
  const body = readL3dBody(bytes, 'test.l3d');
  const ph = parsePhotometry(readFileSync('public/ies/bega_50975_downlight_lm1995_crlf.ies'), 'bega.ies');
  const weight: Rgb = [0.5 * 1.2, 0.5 * 1.0, 0.5 * 0.7];
  const fixtures = oneLuminaire({ id: 's1', kind: 'spot', light: { photometry: ph, opening: l3dOpening(body, 0), flux: hemisphereFlux(ph), weight }, body });
  // 10 cm under the lens (beyond the view's near plane) with a 20° field: the view's half-width there is 17.6 mm, inside the 25 mm radius.
  const pose = { position: [0, 1.9, 0.0005] as Vec3, target: [0, 2, 0] as Vec3, fov: 20 };
  const gammaEye = Math.atan2(0.0005, 0.1);
  const L = intensity(ph, (gammaEye * 180) / Math.PI, 90) / (area * Math.cos(gammaEye));

  it('before the tone curve: the pixel is I(γ)/(A·cos γ) × weight × exposure within 0.5 %', () => {
    // The independent sum and the flux the view is given agree (the file's ≈ 321 lm, all downward).
    expect(Math.abs(downwardFlux(ph) / hemisphereFlux(ph).down - 1)).toBeLessThan(0.005);
    expect(downwardFlux(ph)).toBeGreaterThan(300);
    const shot = linearHardwareShot(renderer, fixtures(true), pose, 0.001, W, H, 2.5e-5);
    const px = shot.render();
    // Every pixel sees the lens.
    for (let i = 0; i < W * H; i++) {
      for (let k = 0; k < 3; k++) expect(Math.abs(px[i * 4 + k] / (L * weight[k] * 2.5e-5) - 1)).toBeLessThan(0.005);
    }
    shot.dispose();
  });

  const centrePixel = (on: boolean, exposure: number) =>
    centreViewPixel(renderer, pose, W, H, (view) => {
      view.setFixtures(fixtures(on));
      view.setExposure(exposure);
    });

  it("on screen: the room's display transform of L × weight; switched off it is dark", () => {
    const exposure = 0.3 / (L * weight[1]);
    const on = centrePixel(true, exposure);
    const want = displayColor([L * weight[0], L * weight[1], L * weight[2]], exposure).map((c) => c * 255);
    for (let k = 0; k < 3; k++) expect(Math.abs(on[k] - want[k])).toBeLessThanOrEqual(1.01);
    expect(centrePixel(false, exposure)).toEqual([0, 0, 0]);
  });
});
