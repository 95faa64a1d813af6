/**
 * The plan's daylight-factor map (issue 30; docs/daylight.md "The daylight-factor map on the
 * plan"): the grid the overlay draws, lit in slices from the relight engine's 'daylight-factor'
 * maps (the bake service's engine, the one the 3D view's DF mode shows), against
 * (1) the shared work-plane function on the same maps (workPlaneDaylight: the report's and the 3D
 * view's), point by point within 1e-6 %, and (2) `luxbox bake`'s report function on the baker's
 * full bake of the same windows under the same 10 klx overcast sky: the statistics within 1e-6
 * relative (the engine-vs-baker difference of the maps, as tests/engines/relight/daylightFactorView.test.ts).
 * Then the picture: each point's pixel in the 3D legend's colour, nothing outside the work
 * plane, and an L-shaped room coloured only inside its outline.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import { DAYLIGHT_FACTOR_LEVELS, DAYLIGHT_FACTOR_SKY_ILLUMINANCE, daylightFactorLuxLevels } from '../../../src/core/daylight/daylightFactor';
import { glazingFrom } from '../../../src/core/daylight/glazing';
import { cieGeneralSky, CIE_CLEAR_SKY_TYPE, cieOvercastSky, groundLuminance } from '../../../src/core/daylight/skies';
import { sunDirection } from '../../../src/core/daylight/solarPosition';
import type { Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import { pointInsideRoom } from '../../../src/core/room/ceilingHeightAt';
import type { RoomInput } from '../../../src/core/room/roomInput';
import { daylightBox, daylightL } from '../../../src/hosts/bench/daylightBox';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { resolveBakeSettings } from '../../../src/engines/bake/bakeSettings';
import { createBaker } from '../../../src/engines/bake/createBaker';
import type { BakeDaylight } from '../../../src/engines/bake/daylight/bakeDaylight';
import { WALL_BAND, WORK_PLANE_SPACING, workPlanePoints } from '../../../src/engines/bake/daylight/workPlaneDaylight';
import { daylightFactorDaylight, workPlaneDaylight } from '../../../src/engines/bake/daylight/workPlaneDaylightFactor';
import { prepareObjectsCached } from '../../../src/engines/bake/objects/prepareObjectsCached';
import { encloseShapedRoom } from '../../../src/engines/bake/shapedRoom/encloseShapedRoom';
import { createRelightEngine } from '../../../src/engines/relight/createRelightEngine';
import { legendPosition, turbo } from '../../../src/engines/view/falseColorScale';
import { workPlaneDaylightFactorOfBake } from '../../../src/hosts/node/daylightReport';
import { loadLightingSceneFile } from '../../../src/hosts/node/loadLightingSceneFile';
import { computeDaylightFactorGrid, daylightFactorImage, GRID_SLICE_POINTS, type DaylightFactorGrid } from '../../../src/ui/planner/daylightFactorGrid';
import { shapedBakeRoom } from '../../engines/bake/shapedRoomKit';
import { withHeadlessGL } from '../../engines/bake/withHeadlessGL';

const gl = withHeadlessGL();
const SETTINGS = { texelSize: 0.1, maxTextureSize: 128, samples: 32, bounces: 4, samplesPerDraw: 8, blurRadius: 1, seed: 30 };
const baker = createBaker(gl);
afterAll(() => baker.dispose());

// The daylight tests' box (daylightBox.ts), double-glazed, and their L.
const BOX: RoomInput = daylightBox();
const L_ROOM: RoomInput = daylightL();
const glazing = new Map([[0, glazingFrom('double')]]);

/** The scene's own daylight: a clear sky with the sun at 40° / 200° (the daylight factor must not depend on it), ground ρ 0.2. */
function clearDaylight(): BakeDaylight {
  const s = sunDirection(40, 200) as Vec3;
  return { sky: cieGeneralSky(CIE_CLEAR_SKY_TYPE, s, 12_000), sun: { direction: s, normalIlluminance: 60_000 }, groundLuminance: groundLuminance(12_000, 60_000 * s[1], 0.2), glazing };
}

/** Slices run at once, one after another (the browser's scheduler puts a macrotask between them); counts them. */
function synchronousSlices() {
  let slices = 0;
  return {
    schedule: (next: () => void) => {
      slices++;
      next();
      return () => undefined;
    },
    count: () => slices,
  };
}

/** The engine's 'daylight-factor' light of a room, the grid the plan draws from it, and the shared function's lux on the same maps. */
function planGrid(input: RoomInput, settings: typeof SETTINGS) {
  const room = shapedBakeRoom(input);
  return { room, ...planGridOf({ room, luminaires: [], daylight: clearDaylight() }, settings) };
}

function planGridOf(scene: BakeScene, partial: Partial<typeof SETTINGS>) {
  const settings = resolveBakeSettings(partial);
  const engine = createRelightEngine(gl, settings);
  try {
    engine.setScene(scene);
    engine.setLightSources('daylight-factor');
    engine.finish();
    const prepared = prepareObjectsCached(encloseShapedRoom(scene).objects ?? [], { texelSize: settings.texelSize, maxAtlasSize: settings.maxTextureSize });
    const lit = engine.maps();
    let grid: DaylightFactorGrid | null = null;
    const slices = synchronousSlices();
    computeDaylightFactorGrid(scene, lit, prepared, engine.version, (g) => (grid = g), slices.schedule);
    const shared = workPlaneDaylight(scene, prepared, lit.maps.objects!, daylightFactorDaylight(scene.daylight!));
    return { grid: grid as DaylightFactorGrid | null, shared, slices: slices.count() };
  } finally {
    engine.dispose();
  }
}

const relative = (a: number, b: number) => Math.abs(a / b - 1);

describe('the daylight-factor map on the plan', () => {
  it('draws the shared work-plane function’s values, and its statistics are the bake report’s', () => {
    const { room, grid, shared, slices } = planGrid(BOX, SETTINGS);
    expect(grid).not.toBeNull();
    const g = grid!;
    const points = workPlanePoints(room.shape);
    expect(g.points).toEqual(points.map((p) => [p[0], p[2]]));
    expect(slices).toBe(Math.ceil(points.length / GRID_SLICE_POINTS));
    let worst = 0;
    shared.forEach((lux, i) => (worst = Math.max(worst, Math.abs(g.values[i] - (100 * lux) / DAYLIGHT_FACTOR_SKY_ILLUMINANCE))));
    expect(worst).toBeLessThan(1e-6);

    // `luxbox bake`'s report on the baker's full bake of the windows under the 10 klx overcast sky.
    const overcast: BakeDaylight = { sky: cieOvercastSky(DAYLIGHT_FACTOR_SKY_ILLUMINANCE), sun: null, groundLuminance: groundLuminance(DAYLIGHT_FACTOR_SKY_ILLUMINANCE, 0, 0.2), glazing };
    const bakeScene: BakeScene = { room, luminaires: [], daylight: overcast };
    const report = workPlaneDaylightFactorOfBake(bakeScene, baker.bake(bakeScene, SETTINGS).maps, overcast, resolveBakeSettings(SETTINGS), DAYLIGHT_FACTOR_SKY_ILLUMINANCE)!;
    const s = g.statistics;
    console.info(
      `DF plan: ${s.points} points in ${slices} slices, |Δ| vs the shared function ${worst.toExponential(2)} %; mean ${s.mean.toFixed(4)} % (report ${report.average.toFixed(4)}), min ${s.min.toFixed(4)} (${report.minimum.toFixed(4)}), U0 ${s.u0.toFixed(4)} (${report.uniformity.toFixed(4)}), share ≥ 2 % ${s.shareAbove2.toFixed(3)} (${report.shareAtTarget.toFixed(3)})`,
    );
    expect(s.points).toBe(points.length);
    expect(relative(s.mean, report.average)).toBeLessThan(1e-6);
    expect(relative(s.min, report.minimum)).toBeLessThan(1e-6);
    expect(relative(s.max, report.maximum)).toBeLessThan(1e-6);
    expect(relative(s.u0, report.uniformity)).toBeLessThan(1e-6);
    expect(relative(s.median, report.median)).toBeLessThan(1e-6);
    expect(s.shareAbove2).toBe(report.shareAtTarget);
    expect(s.shareAbove07).toBe(report.shareAtMinimumTarget);
    // A daylit room's numbers, and the window's side (z = 4) brighter than the far one.
    expect(s.mean).toBeGreaterThan(0.5);
    expect(s.mean).toBeLessThan(20);
    const nearWindow = g.values.filter((_, i) => g.points[i][1] > 3.3);
    const farSide = g.values.filter((_, i) => g.points[i][1] < 0.7);
    expect(Math.min(...nearWindow)).toBeGreaterThan(Math.max(...farSide));
  });

  it('colours each point as the 3D view’s legend does and leaves the rest of the picture clear', () => {
    // Points on the legend's levels and between them; the picture of a grid with a gap.
    const levels = daylightFactorLuxLevels();
    const points: [number, number][] = [
      [1.125, 1.125],
      [1.375, 1.125],
      [1.625, 1.125],
      [1.125, 1.625],
      [1.625, 1.625],
      [1.375, 1.875],
    ];
    const lux = Float64Array.from([levels[0], levels[2], levels[5], 5, 2_000, 150]);
    const image = daylightFactorImage({ points, lux, spacing: WORK_PLANE_SPACING });
    expect([image.x0, image.z0, image.columns, image.rows]).toEqual([1.125, 1.125, 3, 4]);
    const pixel = (c: number, r: number) => Array.from(image.rgba.slice(4 * (r * image.columns + c), 4 * (r * image.columns + c) + 4));
    points.forEach((p, i) => {
      const [r, g, b] = turbo(legendPosition(lux[i], levels)).map((v) => Math.round(v * 255));
      expect(pixel(Math.round((p[0] - 1.125) / 0.25), Math.round((p[1] - 1.125) / 0.25))).toEqual([r, g, b, 255]);
    });
    // The levels' own colours are the legend's swatches (LuxLegend: turbo at each level's position): lowest and highest ends of the scale.
    expect(pixel(0, 0).slice(0, 3)).toEqual(turbo(0).map((v) => Math.round(v * 255)));
    expect(pixel(2, 0).slice(0, 3)).toEqual(turbo(1).map((v) => Math.round(v * 255)));
    expect(pixel(1, 0).slice(0, 3)).toEqual(turbo(2 / (DAYLIGHT_FACTOR_LEVELS.length - 1)).map((v) => Math.round(v * 255)));
    // Below the lowest level and above the highest the ends' colours; no point: clear.
    expect(pixel(0, 2)).toEqual([...turbo(0).map((v) => Math.round(v * 255)), 255]);
    expect(pixel(2, 2)).toEqual([...turbo(1).map((v) => Math.round(v * 255)), 255]);
    for (const [c, r] of [
      [0, 1],
      [1, 1],
      [2, 1],
      [1, 2],
      [0, 3],
      [2, 3],
    ])
      expect(pixel(c, r)[3]).toBe(0);
  });

  it('works on an L-shaped room: lit only inside its outline, the inner corner’s notch left clear', () => {
    const { room, grid, shared } = planGrid(L_ROOM, { ...SETTINGS, texelSize: 0.2, samples: 16, bounces: 2 });
    const g = grid!;
    expect(g.points.length).toBe(workPlanePoints(room.shape).length);
    shared.forEach((lux, i) => expect(Math.abs(g.values[i] - lux / 100)).toBeLessThan(1e-6));
    const image = daylightFactorImage(g);
    let coloured = 0;
    for (let r = 0; r < image.rows; r++) {
      for (let c = 0; c < image.columns; c++) {
        const [x, z] = [image.x0 + c * g.spacing, image.z0 + r * g.spacing];
        const opaque = image.rgba[4 * (r * image.columns + c) + 3] === 255;
        // A coloured cell's centre is inside the L (never in the notch x, z > 3) and WALL_BAND from its inner corner (3, 3) too.
        if (opaque) {
          coloured++;
          expect(pointInsideRoom(room.shape, [x, 0.85, z])).toBe(true);
          expect(x > 3 && z > 3).toBe(false);
          expect(Math.hypot(x - 3, z - 3)).toBeGreaterThanOrEqual(WALL_BAND);
        }
      }
    }
    expect(coloured).toBe(g.points.length);
    // The notch's cells (x, z both past the inner corner) exist in the picture's rectangle and stay clear.
    const notch = image.rgba.filter((_, k) => k % 4 === 3 && image.x0 + ((k >> 2) % image.columns) * g.spacing > 3.5 && image.z0 + Math.floor((k >> 2) / image.columns) * g.spacing > 3.5);
    expect(notch.length).toBeGreaterThan(20);
    expect(Math.max(...notch)).toBe(0);
    // The west wing's window (wall 4, z = 6) lights its wing more than the far end of the east wing.
    const mean = (pick: (p: readonly [number, number]) => boolean) => {
      const v = g.values.filter((_, i) => pick(g.points[i]));
      return v.reduce((a, b) => a + b, 0) / v.length;
    };
    expect(mean((p) => p[1] > 4.5)).toBeGreaterThan(2 * mean((p) => p[0] > 4.5));
  });

  it('shows the statistics `luxbox bake` reports for the same scene file', () => {
    // The CLI's daylight box (version 2, a clear sky at 10:00 in Zurich in June), baked by the command at 0.1 m texels.
    const root = join(__dirname, '../../..');
    const file = join(root, 'tests/fixtures/scenes/daylight-room.json');
    const out = mkdtempSync(join(tmpdir(), 'luxbox-df-plan-'));
    const run = spawnSync(process.execPath, [join(root, 'bin/luxbox.js'), 'bake', file, '--out', out, '--texel', '0.1'], { cwd: root, encoding: 'utf8' });
    expect(run.stderr).toBe('');
    expect(run.status).toBe(0);
    const reported = JSON.parse(readFileSync(join(out, 'report.json'), 'utf8')).daylight.daylightFactor.workPlane;
    // The same file as the app's bake service gets a scene: the engine at the command's settings, the plan's grid from its 'daylight-factor' maps.
    const { grid } = planGridOf(loadLightingSceneFile(file).bakeScene, { texelSize: 0.1 });
    const s = grid!.statistics;
    // report.json keeps 4 significant digits: the plan's numbers round to them (half a unit of the last, plus the engine-vs-baker 1e-6).
    const asReported = (value: number, report: number) => Math.abs(value - report) <= 0.5 * 10 ** (Math.floor(Math.log10(Math.abs(report))) - 3) + 1e-6 * Math.abs(value);
    console.info(`DF plan vs luxbox bake: mean ${s.mean} (${reported.average}), min ${s.min} (${reported.minimum}), U0 ${s.u0} (${reported.uniformity}), share ≥ 2 % ${s.shareAbove2} (${reported.shareAtTarget})`);
    expect(asReported(s.mean, reported.average)).toBe(true);
    expect(asReported(s.min, reported.minimum)).toBe(true);
    expect(asReported(s.max, reported.maximum)).toBe(true);
    expect(asReported(s.u0, reported.uniformity)).toBe(true);
    expect(asReported(s.median, reported.median)).toBe(true);
    expect(asReported(s.shareAbove2, reported.shareAtTarget)).toBe(true);
    expect(asReported(s.shareAbove07, reported.shareAtMinimumTarget)).toBe(true);
  });
});
