/**
 * LM-63 TILT data applied to a pitched luminaire (LM-63-2002 §5.11). The
 * fixture tilt_include.ies is an isotropic 100 cd source whose TILT table
 * reads 0.9 at 0°, 0.8 at 45°, 0.5 at 90°: the parser bakes the 0° factor into
 * the grid, so a lamp pitched by t gives factor(t)/factor(0) of the flux.
 * Black room (CIE 171:2006 §5.4): Σ E·A = Φ, so the ratio of the collected
 * fluxes is exactly the tilt multiplier, in the GPU baker and in the CPU
 * reference alike.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { createBaker } from '../../../src/engines/bake/createBaker';
import type { LightingScene } from '../../../src/core/model/lightingScene/lightingScene';
import { parsePhotometry } from '../../../src/core/photometry/parsePhotometry';
import { tiltMultiplier } from '../../../src/core/photometry/tilt';
import { solveBoxReference } from '../../../src/reference/solveBoxReference';
import { totalFlux, uniformRoom } from './bakeTestKit';
import { withHeadlessGL } from './withHeadlessGL';

const ph = parsePhotometry(readFileSync(join(__dirname, '../../fixtures/photometry/tilt_include.ies')), 'tilt_include.ies');
const gl = withHeadlessGL();
const baker = createBaker(gl);

function scene(pitch: number) {
  return { room: uniformRoom(3, 3, 3, 0), luminaires: [{ photometry: ph, position: [1.5, 1.5, 1.5] as [number, number, number], yaw: 30, pitch, roll: 10 }] };
}

describe('TILT=INCLUDE on a pitched luminaire', () => {
  it('tiltMultiplier is factor(tilt)/factor(0), symmetric in the sign of the pitch, 1 without TILT data', () => {
    expect(tiltMultiplier(ph, 0)).toBe(1);
    expect(tiltMultiplier(ph, 45)).toBeCloseTo(0.8 / 0.9, 12);
    expect(tiltMultiplier(ph, -90)).toBeCloseTo(0.5 / 0.9, 12);
    expect(tiltMultiplier(ph, 67.5)).toBeCloseTo(0.65 / 0.9, 12);
    expect(tiltMultiplier({ tilt: null }, 90)).toBe(1);
  });

  it('the baker scales the collected flux by the multiplier (black room, within 0.5 %)', () => {
    const settings = { texelSize: 0.1, samples: 1, bounces: 0 };
    const upright = totalFlux(baker.bake(scene(0), settings).maps, 'direct');
    // 100 cd × factor(0) = 90 cd everywhere: Φ = 4π·90 lm.
    expect(ph.candela[0][0]).toBeCloseTo(90, 9);
    expect(Math.abs(upright - 360 * Math.PI) / (360 * Math.PI)).toBeLessThan(0.005);
    for (const pitch of [45, 90]) {
      const tilted = totalFlux(baker.bake(scene(pitch), settings).maps, 'direct');
      expect(Math.abs(tilted / upright - tiltMultiplier(ph, pitch))).toBeLessThan(0.005);
    }
  });

  it('the CPU reference applies the same multiplier', () => {
    const flux = (pitch: number) => {
      const s: LightingScene = { version: 1, ...scene(pitch), luminaires: [{ ...scene(pitch).luminaires[0], photometry: 'tilt' }] };
      const r = solveBoxReference(s, { tilt: ph }, { targetPatches: 600 });
      return Object.values(r.surfaces).reduce((sum, f) => sum + f.direct.reduce((a, e) => a + e, 0) * f.du * f.dv, 0);
    };
    const upright = flux(0);
    expect(Math.abs(flux(90) / upright - 0.5 / 0.9)).toBeLessThan(0.005);
  });
});
