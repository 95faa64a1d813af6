import { LUMINANCE_WEIGHTS } from '../bake/bakedMaps';
import type { PreparedObjects } from '../bake/objects/preparedObjects';
import { texelCentre } from '../bake/surfaceLayout';
import type { LitMaps } from '../relight/relightMaps';
import type { ObjectLight } from './objectLight';

/** Illuminance numbers of one object (lux, photometric Y of the relit total map). */
export interface ObjectLuxStats {
  id: string;
  /** Coverage-weighted mean over all its atlas texels (every face, lit or not). */
  avg: number;
  /** Mean over its top: up-facing texels (normal within 10° of +y) within 1 cm of its highest point; null when it has none (a sphere, a sloped roof). */
  top: number | null;
  /** Mean of the floor map over the texels whose centres lie under the object's plan bounds; null when none does. */
  floorUnder: number | null;
}

/** cos 10°: how close to +y a texel's normal must be to count as the top. */
const UP = Math.cos((10 * Math.PI) / 180);
/** How far below the object's highest point its top may lie, metres. */
const TOP_BAND = 0.01;

const Y = (m: Float32Array, t: number) => LUMINANCE_WEIGHTS[0] * m[3 * t] + LUMINANCE_WEIGHTS[1] * m[3 * t + 1] + LUMINANCE_WEIGHTS[2] * m[3 * t + 2];

/**
 * Per object: the mean illuminance, the mean on its top (a table top, a shelf's top board), and
 * the floor's mean under its plan bounds, what a lighting planner compares first ("is the table
 * lit, and is its shadow deep"). Texels weigh their coverage (exact area share, docs/baker.md).
 */
export function objectStats(lit: LitMaps, prepared: PreparedObjects, light: ObjectLight): ObjectLuxStats[] {
  const { atlas } = prepared;
  const n = atlas.width * atlas.height;
  const sums = prepared.objects.map(() => ({ all: 0, allW: 0, top: 0, topW: 0 }));
  for (let t = 0; t < n; t++) {
    const w = atlas.position[4 * t + 3];
    if (!(w > 0)) continue;
    const k = atlas.reflectance[4 * t + 3] - 1;
    const s = sums[k];
    if (!s) continue;
    const e = Y(light.total, t);
    s.all += e * w;
    s.allW += w;
    if (atlas.normal[4 * t + 1] >= UP && atlas.position[4 * t + 1] >= prepared.objects[k].bounds.max[1] - TOP_BAND) {
      s.top += e * w;
      s.topW += w;
    }
  }
  const floor = lit.layouts.floor;
  const floorMap = lit.maps.floor.total;
  return prepared.objects.map((o, k) => {
    let sum = 0;
    let count = 0;
    for (let j = 0; j < floor.height; j++) {
      for (let i = 0; i < floor.width; i++) {
        const p = texelCentre(floor, i, j);
        if (p[0] < o.bounds.min[0] || p[0] > o.bounds.max[0] || p[2] < o.bounds.min[2] || p[2] > o.bounds.max[2]) continue;
        sum += Y(floorMap, j * floor.width + i);
        count++;
      }
    }
    const s = sums[k];
    return { id: o.id, avg: s.allW > 0 ? s.all / s.allW : 0, top: s.topW > 0 ? s.top / s.topW : null, floorUnder: count > 0 ? sum / count : null };
  });
}
