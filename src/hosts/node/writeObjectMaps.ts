import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import type { LightingObject } from '../../core/model/lightingScene/lightingScene';
import { luxOf, type ObjectMaps } from '../../engines/bake/bakedMaps';
import { falseColorPng } from './falseColorPng';
import { encodePfmGrey, writePfm } from './writePfm';

/** One object's entry in objects.json. */
export interface ObjectAtlasEntry {
  id: string;
  /** Index in the scene's `objects`; the mask stores index + 1. */
  index: number;
  /** The mesh path as the scene gives it. */
  mesh: string;
  /** Atlas texels covered by this object's charts. */
  texels: number;
  /** Inclusive texel bounds of its covered texels (i along the atlas width, j along its height, row 0 first); other objects' charts may lie inside the rectangle: the mask tells texels apart. */
  rect: { i0: number; j0: number; i1: number; j1: number } | null;
}

/**
 * The objects' light maps as `luxbox bake` writes them (docs/scene-format.md, "Command-line
 * contract"): objects.direct/.indirect/.total.pfm (RGB lux per atlas texel, like the wall maps),
 * objects.png (false colour of total lux on the walls' scale), objects.mask.pfm (grey: object
 * index + 1 per covered texel, 0 empty) and objects.json (atlas size, texel size, per-object
 * texel rectangles). Returns the objects.json content.
 */
export function writeObjectMaps(out: string, maps: ObjectMaps, objects: readonly LightingObject[], ids: readonly string[], scaleMax: number) {
  const { atlas } = maps;
  const { width, height } = atlas;
  writePfm(join(out, 'objects.direct.pfm'), width, height, maps.direct);
  writePfm(join(out, 'objects.indirect.pfm'), width, height, maps.indirect);
  writePfm(join(out, 'objects.total.pfm'), width, height, maps.total);
  writeFileSync(join(out, 'objects.png'), falseColorPng(luxOf(maps.total), width, height, scaleMax));
  const mask = new Float32Array(width * height);
  const entries: ObjectAtlasEntry[] = objects.map((o, index) => ({ id: ids[index] ?? `objects[${index}]`, index, mesh: o.mesh, texels: 0, rect: null }));
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const k = j * width + i;
      // G-buffer: position.a = coverage, reflectance.a = object index + 1 (preparedObjects.ts).
      if (!(atlas.position[4 * k + 3] > 0)) continue;
      const object = Math.round(atlas.reflectance[4 * k + 3]) - 1;
      const e = entries[object];
      if (!e) continue;
      mask[k] = object + 1;
      e.texels++;
      e.rect = e.rect ? { i0: Math.min(e.rect.i0, i), j0: Math.min(e.rect.j0, j), i1: Math.max(e.rect.i1, i), j1: Math.max(e.rect.j1, j) } : { i0: i, j0: j, i1: i, j1: j };
    }
  }
  writeFileSync(join(out, 'objects.mask.pfm'), encodePfmGrey(width, height, mask));
  const json = {
    atlas: { width, height, texel_size_m: atlas.texelSize },
    files: { direct: 'objects.direct.pfm', indirect: 'objects.indirect.pfm', total: 'objects.total.pfm', png: 'objects.png', mask: 'objects.mask.pfm' },
    objects: entries,
  };
  writeFileSync(join(out, 'objects.json'), JSON.stringify(json, null, 2) + '\n');
  return json;
}
