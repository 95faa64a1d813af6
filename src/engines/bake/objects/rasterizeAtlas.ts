/**
 * The objects' atlas G-buffer, computed on the CPU (docs/baker.md, "Objects: geometry"). Per texel:
 * coverage = the exact fraction of the texel inside its chart's triangles (triangle ∩ square
 * clipping, summed over the chart's triangles, which do not overlap); the sample point = the texel
 * centre when it lies in a triangle of the chart, else the nearest point of the chart's triangles,
 * so every covered texel has a point ON the surface; a partly covered texel whose point would lie
 * on the chart's outline takes the centroid of its covered part instead (pointsOffTheOutline);
 * that triangle's front normal and reflectance.
 * Points are mapped to world space with the triangle's own barycentric weights, so they lie on the
 * triangle's plane even where a chart is only nearly planar.
 */
import type { ObjectAtlas } from './preparedObjects';
import type { Chart } from './buildCharts';
import type { WorldTriangles } from './collectWorldTriangles';
import type { AtlasLayout } from './layoutAtlas';
import { barycentric, closestOnTriangle, overlapCentroidWithTexel, overlapWithTexel } from './planarTriangle';

/** Coverage at or below this fraction counts as an empty texel (a float hair of a neighbouring edge). */
const MIN_COVERAGE = 1e-9;

export interface RasterizedAtlas {
  atlas: ObjectAtlas;
  /** Atlas uv (normalised, texel centres at (i + 0.5)/width) of each world triangle's 3 corners: 6 numbers per triangle. */
  uvOfTriangle: Float64Array;
  /** Chart index per world triangle. */
  chartOfTriangle: Uint32Array;
  /** Covered texels per object. */
  texelCount: number[];
}

/** What the whole atlas collects while its charts are rasterized one by one. */
interface AtlasOutput {
  width: number;
  height: number;
  position: Float32Array;
  normal: Float32Array;
  reflectance: Float32Array;
  uvOfTriangle: Float64Array;
  chartOfTriangle: Uint32Array;
  texelCount: number[];
}

/** Scratch space for the largest chart, reused by every chart (many small charts: no garbage). */
interface ChartScratch {
  /** Chart triangles in chart-local texel units, 6 numbers per triangle. */
  local: Float64Array;
  /** Their bounding boxes (min x, min y, max x, max y), 4 numbers per triangle. */
  boxes: Float64Array;
  /** Per chart texel: covered fraction, owning triangle (−1: none), its barycentric weights, and the squared distance of the nearest point found so far. */
  coverage: Float64Array;
  owner: Int32Array;
  weights: Float64Array;
  nearest: Float64Array;
}

/** One chart's place in the atlas: its size in texels (cols × rows) and its corner (x0, y0). */
interface ChartPlace {
  c: number;
  cols: number;
  rows: number;
  x0: number;
  y0: number;
}

export function rasterizeAtlas(tris: WorldTriangles, charts: readonly Chart[], layout: AtlasLayout): RasterizedAtlas {
  const { width, height, texelSize: s } = layout;
  const out: AtlasOutput = {
    width,
    height,
    position: new Float32Array(width * height * 4),
    normal: new Float32Array(width * height * 4),
    reflectance: new Float32Array(width * height * 4),
    uvOfTriangle: new Float64Array(tris.count * 6),
    chartOfTriangle: new Uint32Array(tris.count),
    texelCount: tris.objects.map(() => 0),
  };
  const scratch = allocateScratch(charts, layout);
  charts.forEach((chart, c) => {
    const place: ChartPlace = { c, cols: layout.columns[c], rows: layout.rows[c], x0: layout.x[c], y0: layout.y[c] };
    placeChartTriangles(chart, place, s, scratch, out);
    coverChart(chart.triangles.length, place, scratch);
    snapOutsideTexels(chart.triangles.length, place, scratch);
    pointsOffTheOutline(chart.triangles.length, place, scratch);
    writeChartTexels(tris, chart, place, scratch, out);
  });
  const { position, normal, reflectance, uvOfTriangle, chartOfTriangle, texelCount } = out;
  return { atlas: { width, height, texelSize: s, position, normal, reflectance }, uvOfTriangle, chartOfTriangle, texelCount };
}

function allocateScratch(charts: readonly Chart[], layout: AtlasLayout): ChartScratch {
  let maxTexels = 0;
  let maxTriangles = 0;
  charts.forEach((chart, c) => {
    maxTexels = Math.max(maxTexels, layout.columns[c] * layout.rows[c]);
    maxTriangles = Math.max(maxTriangles, chart.triangles.length);
  });
  return {
    local: new Float64Array(maxTriangles * 6),
    boxes: new Float64Array(maxTriangles * 4),
    coverage: new Float64Array(maxTexels),
    owner: new Int32Array(maxTexels),
    weights: new Float64Array(maxTexels * 3),
    nearest: new Float64Array(maxTexels),
  };
}

/** The chart's triangles in chart-local texel units with their boxes, and each world triangle's atlas uv and chart. */
function placeChartTriangles(chart: Chart, place: ChartPlace, s: number, scratch: ChartScratch, out: AtlasOutput): void {
  const { local, boxes } = scratch;
  const m = chart.triangles.length;
  for (let i = 0; i < m * 6; i++) local[i] = chart.uv[i] / s;
  chart.triangles.forEach((t, i) => {
    out.chartOfTriangle[t] = place.c;
    for (let k = 0; k < 3; k++) {
      out.uvOfTriangle[6 * t + 2 * k] = (place.x0 + local[6 * i + 2 * k]) / out.width;
      out.uvOfTriangle[6 * t + 2 * k + 1] = (place.y0 + local[6 * i + 2 * k + 1]) / out.height;
    }
  });
  for (let i = 0; i < m; i++) {
    const o = 6 * i;
    boxes[4 * i] = Math.min(local[o], local[o + 2], local[o + 4]);
    boxes[4 * i + 1] = Math.min(local[o + 1], local[o + 3], local[o + 5]);
    boxes[4 * i + 2] = Math.max(local[o], local[o + 2], local[o + 4]);
    boxes[4 * i + 3] = Math.max(local[o + 1], local[o + 3], local[o + 5]);
  }
}

/** Exact coverage of every chart texel, and the triangle holding each texel centre (with its weights) where one does. */
function coverChart(m: number, place: ChartPlace, scratch: ChartScratch): void {
  const { cols, rows } = place;
  const { local, boxes, coverage, owner, weights, nearest } = scratch;
  coverage.fill(0, 0, cols * rows);
  owner.fill(-1, 0, cols * rows);
  nearest.fill(Infinity, 0, cols * rows);
  for (let i = 0; i < m; i++) {
    const tri = local.subarray(6 * i, 6 * i + 6);
    const [minX, minY, maxX, maxY] = boxes.subarray(4 * i, 4 * i + 4);
    const i0 = Math.max(0, Math.floor(minX)),
      i1 = Math.min(cols - 1, Math.ceil(maxX) - 1);
    const j0 = Math.max(0, Math.floor(minY)),
      j1 = Math.min(rows - 1, Math.ceil(maxY) - 1);
    for (let j = j0; j <= j1; j++) {
      for (let ii = i0; ii <= i1; ii++) {
        const a = overlapWithTexel(tri, ii, j);
        if (a <= 0) continue;
        const k = j * cols + ii;
        coverage[k] += a;
        if (owner[k] >= 0) continue;
        const w = barycentric(tri, ii + 0.5, j + 0.5);
        if (w[0] >= -1e-12 && w[1] >= -1e-12 && w[2] >= -1e-12) {
          owner[k] = i;
          weights.set(w, 3 * k);
        }
      }
    }
  }
}

/**
 * Covered texels whose centre lies outside the chart take the nearest point of the chart's
 * triangles. It lies within half a texel diagonal of the centre, so only triangles whose box
 * reaches within one texel qualify: one more sweep over the triangles' widened boxes.
 */
function snapOutsideTexels(m: number, place: ChartPlace, scratch: ChartScratch): void {
  const { cols, rows } = place;
  const { local, boxes, coverage, owner, weights, nearest } = scratch;
  let outside = 0;
  for (let k = 0; k < cols * rows; k++) if (coverage[k] > MIN_COVERAGE && owner[k] < 0) outside++;
  for (let i = 0; i < m && outside > 0; i++) {
    const [minX, minY, maxX, maxY] = boxes.subarray(4 * i, 4 * i + 4);
    const i0 = Math.max(0, Math.floor(minX) - 1),
      i1 = Math.min(cols - 1, Math.ceil(maxX));
    const j0 = Math.max(0, Math.floor(minY) - 1),
      j1 = Math.min(rows - 1, Math.ceil(maxY));
    for (let j = j0; j <= j1; j++) {
      for (let ii = i0; ii <= i1; ii++) {
        const k = j * cols + ii;
        if (!(coverage[k] > MIN_COVERAGE) || (owner[k] >= 0 && nearest[k] === Infinity)) continue;
        const hit = closestOnTriangle(local.subarray(6 * i, 6 * i + 6), ii + 0.5, j + 0.5);
        if (hit.distanceSq < nearest[k]) {
          nearest[k] = hit.distanceSq;
          owner[k] = i;
          weights.set(hit.weights, 3 * k);
        }
      }
    }
  }
}

/** A point this close to an edge of its triangle (texels) counts as on it: float32 vertices put a corner a few 1e-7 texels off. */
const ON_EDGE = 1e-3;

/**
 * A partly covered texel whose point (its centre, or the snapped nearest point) lies on an edge of
 * its triangle, which for a partly covered texel is the chart's outline (or, harmlessly, an inner
 * edge through it). Distance to the edge opposite corner i = w_i · h_i, h_i = 2·area / |edge i|.
 */
function pointOnOutline(k: number, tri: ArrayLike<number>, scratch: ChartScratch): boolean {
  const { coverage, weights, nearest } = scratch;
  if (!(coverage[k] > MIN_COVERAGE) || coverage[k] >= 1 - 1e-9) return false;
  if (nearest[k] < Infinity) return true;
  const twiceArea = Math.abs((tri[2] - tri[0]) * (tri[5] - tri[1]) - (tri[4] - tri[0]) * (tri[3] - tri[1]));
  const edge = (a: number, b: number) => Math.hypot(tri[2 * b] - tri[2 * a], tri[2 * b + 1] - tri[2 * a + 1]);
  const lengths = [edge(1, 2), edge(2, 0), edge(0, 1)];
  return lengths.some((l, i) => (weights[3 * k + i] * twiceArea) / l < ON_EDGE);
}

/**
 * A point on the chart's outline lies, where the outline is a room's inner corner, in the other
 * surface's plane too: a gather from there starts on that surface, so half its rays pass it into
 * the enclosure's sinks. That is how a wall strip ending half a texel into a corner (the strips a
 * window cuts a wall into are rarely whole texels) gathered half its light: issue 30 measured 0.08 %
 * of every bounce's flux lost in the daylight box, most of the −0.6 % flux balance at ρ 0.95.
 * Such texels take the centroid of their covered part (area-weighted over the chart's triangles:
 * overlapCentroidWithTexel), inside the chart and the point that represents the texel's mean
 * best; kept where the centroid lies in none of the triangles that cover the texel most.
 */
function pointsOffTheOutline(m: number, place: ChartPlace, scratch: ChartScratch): void {
  const { cols, rows } = place;
  const { local, boxes, owner, weights } = scratch;
  const moved = new Map<number, { area: number; x: number; y: number; best: number; bestArea: number }>();
  for (let k = 0; k < cols * rows; k++) {
    if (owner[k] >= 0 && pointOnOutline(k, local.subarray(6 * owner[k], 6 * owner[k] + 6), scratch)) moved.set(k, { area: 0, x: 0, y: 0, best: -1, bestArea: 0 });
  }
  if (moved.size === 0) return;
  for (let i = 0; i < m; i++) {
    const [minX, minY, maxX, maxY] = boxes.subarray(4 * i, 4 * i + 4);
    for (let j = Math.max(0, Math.floor(minY)); j <= Math.min(rows - 1, Math.ceil(maxY) - 1); j++) {
      for (let ii = Math.max(0, Math.floor(minX)); ii <= Math.min(cols - 1, Math.ceil(maxX) - 1); ii++) {
        const acc = moved.get(j * cols + ii);
        if (!acc) continue;
        const part = overlapCentroidWithTexel(local.subarray(6 * i, 6 * i + 6), ii, j);
        acc.area += part.area;
        acc.x += part.area * part.x;
        acc.y += part.area * part.y;
        if (part.area > acc.bestArea) [acc.best, acc.bestArea] = [i, part.area];
      }
    }
  }
  for (const [k, acc] of moved) {
    if (acc.best < 0 || !(acc.area > 0)) continue;
    const w = barycentric(local.subarray(6 * acc.best, 6 * acc.best + 6), acc.x / acc.area, acc.y / acc.area);
    if (w[0] < -1e-12 || w[1] < -1e-12 || w[2] < -1e-12) continue;
    owner[k] = acc.best;
    weights.set(w, 3 * k);
  }
}

/** Every covered texel of the chart into the atlas: its world point (the owner's barycentric weights), normal, reflectance, coverage, chart and object. */
function writeChartTexels(tris: WorldTriangles, chart: Chart, place: ChartPlace, scratch: ChartScratch, out: AtlasOutput): void {
  const { c, cols, rows, x0, y0 } = place;
  const { coverage, owner, weights } = scratch;
  const { position, normal, reflectance, width } = out;
  const P = tris.positions;
  for (let j = 0; j < rows; j++) {
    for (let ii = 0; ii < cols; ii++) {
      const k = j * cols + ii;
      if (coverage[k] <= MIN_COVERAGE) continue;
      const t = chart.triangles[owner[k]];
      // Clamp the weights of a centre a float hair outside its triangle back onto it.
      let w0 = Math.max(0, weights[3 * k]),
        w1 = Math.max(0, weights[3 * k + 1]),
        w2 = Math.max(0, weights[3 * k + 2]);
      const sum = w0 + w1 + w2;
      w0 /= sum;
      w1 /= sum;
      w2 /= sum;
      const g = 4 * ((y0 + j) * width + x0 + ii);
      for (let a = 0; a < 3; a++) {
        position[g + a] = w0 * P[9 * t + a] + w1 * P[9 * t + 3 + a] + w2 * P[9 * t + 6 + a];
        normal[g + a] = tris.normals[3 * t + a];
        reflectance[g + a] = tris.reflectance[3 * t + a];
      }
      position[g + 3] = Math.min(1, coverage[k]);
      normal[g + 3] = c + 1;
      reflectance[g + 3] = chart.object + 1;
      out.texelCount[chart.object]++;
    }
  }
}
