/**
 * The 3D view's daylight-factor statistics (issue 30; docs/viewer.md "Daylight factor",
 * docs/daylight.md "The daylight-factor view"): the relight engine's 'daylight-factor' maps (the
 * overcast basis alone) through the view's daylightFactorOfView against (1) `luxbox bake`'s report
 * function on the baker's full bake of the same windows under the same overcast sky — one
 * definition, so equal up to the engine-vs-baker difference of the maps (1e-6 relative) — and (2)
 * the independent daylight reference (src/reference/solveDaylightReference.ts, a patch radiosity
 * with its own sky integration) at the same points, within the CLI test's tolerances.
 */
import { afterAll, describe, expect, it } from 'vitest';
import { DAYLIGHT_FACTOR_SKY_ILLUMINANCE, daylightFactorStatistics } from '../../../src/core/daylight/daylightFactor';
import { glazingFrom } from '../../../src/core/daylight/glazing';
import { cieGeneralSky, CIE_CLEAR_SKY_TYPE, cieOvercastSky, groundLuminance } from '../../../src/core/daylight/skies';
import { sunDirection } from '../../../src/core/daylight/solarPosition';
import type { Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import type { RoomInput } from '../../../src/core/room/roomInput';
import { daylightBox } from '../../../src/hosts/bench/daylightBox';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { resolveBakeSettings } from '../../../src/engines/bake/bakeSettings';
import { createBaker } from '../../../src/engines/bake/createBaker';
import type { BakeDaylight } from '../../../src/engines/bake/daylight/bakeDaylight';
import { workPlanePoints } from '../../../src/engines/bake/daylight/workPlaneDaylight';
import { prepareObjectsCached } from '../../../src/engines/bake/objects/prepareObjectsCached';
import { encloseShapedRoom } from '../../../src/engines/bake/shapedRoom/encloseShapedRoom';
import { createRelightEngine } from '../../../src/engines/relight/createRelightEngine';
import { workPlaneDaylightFactorOfBake } from '../../../src/hosts/node/daylightReport';
import { daylightIlluminanceAt, solveDaylightReference } from '../../../src/reference/solveDaylightReference';
import { daylightFactorOfView } from '../../../src/ui/viewer/useDaylightFactorView';
import { shapedBakeRoom } from '../bake/shapedRoomKit';
import { withHeadlessGL } from '../bake/withHeadlessGL';

const gl = withHeadlessGL();
const SETTINGS = { texelSize: 0.1, maxTextureSize: 128, samples: 32, bounces: 4, samplesPerDraw: 8, blurRadius: 1, seed: 30 };
const baker = createBaker(gl);
afterAll(() => baker.dispose());

// The daylight tests' box: 5 × 4 m, 2.8 m high, a 1.5 × 1.4 m double-glazed window in the south wall at sill 0.9 m.
const ROOM: RoomInput = daylightBox();
const room = shapedBakeRoom(ROOM);
const glazing = new Map([[0, glazingFrom('double')]]);

/** The scene's own daylight: a clear sky with the sun at 40° / 200° (the DF mode must not depend on it), ground ρ 0.2. */
function clearDaylight(): BakeDaylight {
  const s = sunDirection(40, 200) as Vec3;
  return { sky: cieGeneralSky(CIE_CLEAR_SKY_TYPE, s, 12_000), sun: { direction: s, normalIlluminance: 60_000 }, groundLuminance: groundLuminance(12_000, 60_000 * s[1], 0.2), glazing };
}

const relative = (a: number, b: number) => Math.abs(a / b - 1);

describe('the 3D view’s daylight-factor statistics', () => {
  it('equal the bake report’s and are within the reference’s tolerance for the box under the CIE overcast sky', () => {
    const scene: BakeScene = { room, luminaires: [], daylight: clearDaylight() };
    const engine = createRelightEngine(gl, SETTINGS);
    try {
      engine.setScene(scene);
      engine.setLightSources('daylight-factor');
      engine.finish();
      const prepared = prepareObjectsCached(encloseShapedRoom(scene).objects ?? [], { texelSize: SETTINGS.texelSize, maxAtlasSize: SETTINGS.maxTextureSize });
      const view = daylightFactorOfView(scene, engine.maps(), prepared)!;

      // The report's function on the baker's full bake of the windows under the 10 klx overcast sky (as `luxbox bake` bakes it).
      const overcast: BakeDaylight = { sky: cieOvercastSky(DAYLIGHT_FACTOR_SKY_ILLUMINANCE), sun: null, groundLuminance: groundLuminance(DAYLIGHT_FACTOR_SKY_ILLUMINANCE, 0, 0.2), glazing };
      const bakeScene: BakeScene = { room, luminaires: [], daylight: overcast };
      const cli = workPlaneDaylightFactorOfBake(bakeScene, baker.bake(bakeScene, SETTINGS).maps, overcast, resolveBakeSettings(SETTINGS), DAYLIGHT_FACTOR_SKY_ILLUMINANCE)!;

      const reference = solveDaylightReference(ROOM, { sky: cieOvercastSky(DAYLIGHT_FACTOR_SKY_ILLUMINANCE), sun: null, groundReflectance: 0.2, glazing: { 0: glazingFrom('double') } }, { patchSize: 0.25 });
      const points = workPlanePoints(room.shape);
      const expected = daylightFactorStatistics(points.map((p) => daylightIlluminanceAt(reference, p, [0, 1, 0]).total / 100));
      console.info(
        `DF view: ${view.points} points, mean ${view.mean.toFixed(4)} % (report ${cli.average.toFixed(4)}, reference ${expected.average.toFixed(4)}), min ${view.min.toFixed(4)} (${cli.minimum.toFixed(4)}, ${expected.minimum.toFixed(4)}), U0 ${view.u0.toFixed(4)} (${cli.uniformity.toFixed(4)}, ${expected.uniformity.toFixed(4)}), share ≥ 2 % ${view.shareAbove2.toFixed(3)} (${cli.shareAtTarget.toFixed(3)}, ${expected.shareAtTarget.toFixed(3)}); |Δ mean| vs report ${relative(view.mean, cli.average).toExponential(2)}`,
      );
      expect(view.points).toBe(points.length);
      // One definition: the view's numbers are the report's on the same light.
      expect(relative(view.mean, cli.average)).toBeLessThan(1e-6);
      expect(relative(view.min, cli.minimum)).toBeLessThan(1e-6);
      expect(relative(view.max, cli.maximum)).toBeLessThan(1e-6);
      expect(relative(view.u0, cli.uniformity)).toBeLessThan(1e-6);
      expect(relative(view.median, cli.median)).toBeLessThan(1e-6);
      expect(view.shareAbove2).toBe(cli.shareAtTarget);
      expect(view.shareAbove07).toBe(cli.shareAtMinimumTarget);
      // Against the independent reference: the CLI test's bars (docs/daylight.md, "The report").
      expect(relative(view.mean, expected.average)).toBeLessThan(0.03);
      expect(relative(view.median, expected.median)).toBeLessThan(0.03);
      expect(relative(view.min, expected.minimum)).toBeLessThan(0.05);
      expect(Math.abs(view.shareAbove2 - expected.shareAtTarget)).toBeLessThan(0.05);
    } finally {
      engine.dispose();
    }
  });
});
