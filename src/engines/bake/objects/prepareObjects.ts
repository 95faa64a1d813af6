/**
 * The geometry side of objects in the bake (docs/baker.md, "Objects: geometry"): all objects'
 * triangles placed in world space, grouped into planar charts, packed into one light-map atlas with
 * its G-buffer computed here on the CPU, and one BVH over all triangles flattened into RGBA32F
 * textures for shaders/bvhTraversal.glsl.ts.
 */
import type { BakeObject } from '../bakeScene';
import { buildBvhTextures } from './buildBvhTextures';
import { buildCharts } from './buildCharts';
import { collectWorldTriangles } from './collectWorldTriangles';
import { chartFrame } from './chartFrame';
import { layoutAtlas } from './layoutAtlas';
import type { PreparedObjects } from './preparedObjects';
import { rasterizeAtlas } from './rasterizeAtlas';

/** Largest atlas side, texels, unless the caller says otherwise. */
export const DEFAULT_MAX_ATLAS_SIZE = 2048;

export interface PrepareObjectsOptions {
  /** Wanted metres per texel; the atlas's own texelSize is larger when the charts would not fit at this one. */
  texelSize: number;
  /** Largest atlas side, texels (default 2048). */
  maxAtlasSize?: number;
}

export function prepareObjects(objects: BakeObject[], options: PrepareObjectsOptions): PreparedObjects {
  const tris = collectWorldTriangles(objects);
  const charts = buildCharts(tris);
  const layout = layoutAtlas(charts, options.texelSize, options.maxAtlasSize ?? DEFAULT_MAX_ATLAS_SIZE);
  const raster = rasterizeAtlas(tris, charts, layout);
  const bvh = buildBvhTextures(tris, raster.uvOfTriangle, raster.chartOfTriangle);
  const min: [number, number, number] = [Infinity, Infinity, Infinity];
  const max: [number, number, number] = [-Infinity, -Infinity, -Infinity];
  for (const o of tris.objects) {
    for (let a = 0; a < 3; a++) {
      min[a] = Math.min(min[a], o.bounds.min[a]);
      max[a] = Math.max(max[a], o.bounds.max[a]);
    }
  }
  return {
    atlas: raster.atlas,
    bvh: { width: bvh.width, nodes: bvh.nodes, nodesHeight: bvh.nodesHeight, triangles: bvh.triangles, trianglesHeight: bvh.trianglesHeight },
    objects: tris.objects.map((o, k) => ({ id: o.id, triangleCount: o.triangleCount, area: o.area, texelCount: raster.texelCount[k], bounds: o.bounds })),
    charts: charts.map((chart, c) => ({
      object: chart.object,
      x: layout.x[c],
      y: layout.y[c],
      columns: layout.columns[c],
      rows: layout.rows[c],
      triangleCount: chart.triangles.length,
      frame: chartFrame(chart, tris),
    })),
    triangleCount: tris.count,
    bounds: { min, max },
  };
}
