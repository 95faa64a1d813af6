import { LUMINANCE_WEIGHTS } from '../bakedMaps';
import type { PreparedObjects } from './preparedObjects';

/** One object's line of the bake report (docs/scene-format.md, report table). */
export interface ObjectReportEntry {
  id: string;
  /** Surface area of the placed mesh, m². */
  area: number;
  /** Covered atlas texels of this object. */
  texels: number;
  /** Area-weighted mean total illuminance (Y), lux: Σ E·c / Σ c over its covered texels (c = coverage). */
  meanLux: number;
  /** Smallest and largest total illuminance (Y) of its covered texels, lux. */
  minLux: number;
  maxLux: number;
  /** Luminous flux arriving on the object, lm: Σ E·c·texel². */
  flux: number;
}

/** Per-object statistics of the atlas's total map (RGB lux per texel, undilated values on covered texels). */
export function objectReport(prepared: PreparedObjects, total: Float32Array): ObjectReportEntry[] {
  const { atlas, objects } = prepared;
  const a2 = atlas.texelSize * atlas.texelSize;
  const acc = objects.map(() => ({ weight: 0, weighted: 0, texels: 0, min: Infinity, max: -Infinity }));
  for (let i = 0; i < atlas.width * atlas.height; i++) {
    const c = atlas.position[4 * i + 3];
    const k = Math.round(atlas.reflectance[4 * i + 3]) - 1;
    if (c <= 0 || k < 0 || k >= acc.length) continue;
    const e = LUMINANCE_WEIGHTS[0] * total[3 * i] + LUMINANCE_WEIGHTS[1] * total[3 * i + 1] + LUMINANCE_WEIGHTS[2] * total[3 * i + 2];
    const o = acc[k];
    o.weight += c;
    o.weighted += e * c;
    o.texels++;
    o.min = Math.min(o.min, e);
    o.max = Math.max(o.max, e);
  }
  return objects.map((info, k) => {
    const o = acc[k];
    return {
      id: info.id,
      area: info.area,
      texels: o.texels,
      meanLux: o.weight > 0 ? o.weighted / o.weight : 0,
      minLux: o.texels > 0 ? o.min : 0,
      maxLux: o.texels > 0 ? o.max : 0,
      flux: o.weighted * a2,
    };
  });
}
