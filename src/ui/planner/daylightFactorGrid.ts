import { DAYLIGHT_FACTOR_SKY_ILLUMINANCE, daylightFactor, daylightFactorLuxLevels } from '../../core/daylight/daylightFactor';
import type { BakeScene } from '../../engines/bake/bakeScene';
import { WORK_PLANE_SPACING } from '../../engines/bake/daylight/workPlaneDaylight';
import { daylightFactorDaylight, workPlaneDaylightRun } from '../../engines/bake/daylight/workPlaneDaylightFactor';
import type { PreparedObjects } from '../../engines/bake/objects/preparedObjects';
import type { LitMaps } from '../../engines/relight/relightMaps';
import { legendPosition, turbo } from '../../engines/view/falseColorScale';
import { daylightFactorValuesOf, type DaylightFactorValues } from '../viewer/useDaylightFactorView';

/**
 * The work plane's daylight factor as the plan draws it (issue 30, docs/daylight.md "The
 * daylight-factor map on the plan"): the grid of the report's and the 3D view's work plane
 * (workPlaneDaylightRun: EN 17037's reference plane at 0.85 m, 0.5 m from the walls, 0.25 m
 * apart), each point's DF in %, and the statistics of the same function the 3D view's table shows.
 */
export interface DaylightFactorGrid {
  /** The engine version whose maps the grid was computed from. */
  version: number;
  /** Distance between neighbouring points, metres (each point stands for spacing² of the plane). */
  spacing: number;
  /** Plan coordinates (x, z) of the points, metres. */
  points: readonly (readonly [number, number])[];
  /** Illuminance under the overcast sky of DAYLIGHT_FACTOR_SKY_ILLUMINANCE at each point, lux. */
  lux: Float64Array;
  /** The daylight factor at each point, %. */
  values: Float64Array;
  statistics: DaylightFactorValues;
}

/** Points lit per slice: a slice stays well under a frame's budget on a phone (256 gather rays each). */
export const GRID_SLICE_POINTS = 24;

/** Schedules the next slice (default: a macrotask, so input and drawing run between slices). */
export type SliceScheduler = (next: () => void) => () => void;

const nextTask: SliceScheduler = (next) => {
  const id = setTimeout(next, 0);
  return () => clearTimeout(id);
};

/**
 * Lights the work plane of `scene` from the engine's 'daylight-factor' maps (`lit`: the overcast
 * basis alone, lux under DAYLIGHT_FACTOR_SKY_ILLUMINANCE) in slices of GRID_SLICE_POINTS, and hands
 * the grid to `done` (null: the scene has no daylight or no shaped room, or the maps no atlas).
 * Returns a cancel. `prepared`: the enclosed scene's objects the maps were baked on (the service's).
 */
export function computeDaylightFactorGrid(scene: BakeScene, lit: LitMaps, prepared: PreparedObjects | null, version: number, done: (grid: DaylightFactorGrid | null) => void, schedule: SliceScheduler = nextTask): () => void {
  const light = lit.maps.objects;
  const run = scene.daylight && prepared && light && light.total.length > 0 ? workPlaneDaylightRun(scene, prepared, light, daylightFactorDaylight(scene.daylight)) : null;
  if (!run || run.points.length === 0) {
    done(null);
    return () => undefined;
  }
  const lux = new Float64Array(run.points.length);
  let cancelled = false;
  let cancelNext: () => void = () => undefined;
  const step = (from: number) => {
    if (cancelled) return;
    const to = Math.min(run.points.length, from + GRID_SLICE_POINTS);
    lux.set(run.illuminance(from, to), from);
    if (to < run.points.length) {
      cancelNext = schedule(() => step(to));
      return;
    }
    const values = lux.map((e) => daylightFactor(e, DAYLIGHT_FACTOR_SKY_ILLUMINANCE));
    done({ version, spacing: WORK_PLANE_SPACING, points: run.points.map((p) => [p[0], p[2]] as const), lux, values, statistics: daylightFactorValuesOf(lux)! });
  };
  cancelNext = schedule(() => step(0));
  return () => {
    cancelled = true;
    cancelNext();
  };
}

/** The grid as an image: one pixel per point, row-major from (x0, z0) (the first point's centre), transparent where the plane has no point. */
export interface DaylightFactorImage {
  x0: number;
  z0: number;
  columns: number;
  rows: number;
  /** RGBA, 8 bits a channel. */
  rgba: Uint8ClampedArray<ArrayBuffer>;
}

/** A DF point's colour: the 3D view's false colour at the daylight-factor levels (the shader's turbo polynomial at legendPosition), sRGB 0 … 255. */
export function daylightFactorColour(lux: number): [number, number, number] {
  const [r, g, b] = turbo(legendPosition(lux, daylightFactorLuxLevels()));
  return [Math.round(r * 255), Math.round(g * 255), Math.round(b * 255)];
}

export function daylightFactorImage(grid: Pick<DaylightFactorGrid, 'points' | 'lux' | 'spacing'>): DaylightFactorImage {
  const xs = grid.points.map((p) => p[0]);
  const zs = grid.points.map((p) => p[1]);
  const x0 = Math.min(...xs);
  const z0 = Math.min(...zs);
  const columns = Math.round((Math.max(...xs) - x0) / grid.spacing) + 1;
  const rows = Math.round((Math.max(...zs) - z0) / grid.spacing) + 1;
  const rgba = new Uint8ClampedArray(4 * columns * rows);
  grid.points.forEach((p, i) => {
    const k = 4 * (Math.round((p[1] - z0) / grid.spacing) * columns + Math.round((p[0] - x0) / grid.spacing));
    rgba.set([...daylightFactorColour(grid.lux[i]), 255], k);
  });
  return { x0, z0, columns, rows, rgba };
}
