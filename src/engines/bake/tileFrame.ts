/**
 * What the bright-patch search tiles (docs/baker.md, "Stiff scenes: bright patches" and "Rooms of
 * any shape"): a plane with a texel grid, either a room surface of the box (its own map) or a chart
 * of the objects' atlas (its texels in the atlas's map). Tile (iu, iv) of a frame covers
 * u ∈ [iu·tile·du, …), v ∈ [iv·tile·dv, …) from `origin` along the unit `axisU`, `axisV`.
 */
import type { Rgb, Vec3 } from '../../core/model/lightingScene/lightingScene';
import type { PreparedObjects } from './objects/preparedObjects';
import { axisVector, type SurfaceLayout } from './surfaceLayout';

/** Patch sources from this index on are charts of the objects' atlas: chart c is ATLAS_SOURCE + c (the atlas is receiver 6 of the bounces). */
export const ATLAS_SOURCE = 6;

export interface TileFrame {
  /** The patches' source index: a room surface 0–5, or ATLAS_SOURCE + chart. */
  index: number;
  origin: Vec3;
  axisU: Vec3;
  axisV: Vec3;
  /** Half edge v of a patch is written along `axisV · vSign`, so that cross(hu, hv) is the front normal of a chart (one-sided emitters); 1 on room surfaces, whose patches emit both ways into the box. */
  vSign: 1 | -1;
  /** Extent of the texel grid along u and v, metres. */
  lengthU: number;
  lengthV: number;
  /** Texels along u and v. */
  width: number;
  height: number;
  /** Emitting area, m² (a room surface's rectangle; a chart's triangles). */
  area: number;
  /** ρ the tile sums are multiplied by: the surface's; (1, 1, 1) for charts, whose sums carry each texel's own ρ. */
  reflectance: Rgb;
  /** A chart: its id and the atlas texel of its chart-local (0, 0). */
  chart?: { id: number; x: number; y: number };
}

/** A room surface of the box as a frame (origin on 0 along u and v, so origin + u·axisU is the CPU's old centre to the bit). */
export function layoutTileFrame(layout: SurfaceLayout, reflectance: Rgb): TileFrame {
  return {
    index: layout.index,
    origin: layout.origin,
    axisU: axisVector(layout.uAxisIndex, 1),
    axisV: axisVector(layout.vAxisIndex, 1),
    vSign: 1,
    lengthU: layout.lengthU,
    lengthV: layout.lengthV,
    width: layout.width,
    height: layout.height,
    area: layout.lengthU * layout.lengthV,
    reflectance,
  };
}

/** Every chart of the objects' atlas as a frame, in chart order. */
export function chartTileFrames(prepared: PreparedObjects): TileFrame[] {
  const s = prepared.atlas.texelSize;
  return prepared.charts.map((chart, c): TileFrame => {
    const { origin, axisU, axisV, normal, area } = chart.frame;
    const n = [axisU[1] * axisV[2] - axisU[2] * axisV[1], axisU[2] * axisV[0] - axisU[0] * axisV[2], axisU[0] * axisV[1] - axisU[1] * axisV[0]];
    return {
      index: ATLAS_SOURCE + c,
      origin,
      axisU,
      axisV,
      vSign: n[0] * normal[0] + n[1] * normal[1] + n[2] * normal[2] >= 0 ? 1 : -1,
      lengthU: chart.columns * s,
      lengthV: chart.rows * s,
      width: chart.columns,
      height: chart.rows,
      area,
      reflectance: [1, 1, 1],
      chart: { id: c, x: chart.x, y: chart.y },
    };
  });
}
