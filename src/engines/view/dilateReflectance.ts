import type { ObjectAtlas } from '../bake/objects/preparedObjects';

/** Texels around each chart that get a reflectance: the baker dilates the light two texels into the gutters (docs/baker.md). */
export const REFLECTANCE_DILATION = 2;

/**
 * The atlas reflectance (RGBA: ρ, a = object index + 1) with empty texels within
 * REFLECTANCE_DILATION texels of a chart filled from a covered neighbour, one ring per round
 * (the first covered or already filled 8-neighbour in a fixed order): a fragment at a chart's
 * border whose nearest texel is a gutter texel then shows its own chart's ρ instead of black.
 */
export function dilateReflectance(atlas: ObjectAtlas): Float32Array {
  const { width, height } = atlas;
  const out = new Float32Array(atlas.reflectance);
  const filled = new Uint8Array(width * height);
  for (let i = 0; i < filled.length; i++) filled[i] = atlas.position[4 * i + 3] > 0 ? 1 : 0;
  const offsets = [
    [-1, 0],
    [1, 0],
    [0, -1],
    [0, 1],
    [-1, -1],
    [1, -1],
    [-1, 1],
    [1, 1],
  ];
  for (let round = 0; round < REFLECTANCE_DILATION; round++) {
    const before = filled.slice();
    for (let j = 0; j < height; j++) {
      for (let i = 0; i < width; i++) {
        const t = j * width + i;
        if (before[t]) continue;
        for (const [di, dj] of offsets) {
          const x = i + di;
          const y = j + dj;
          if (x < 0 || y < 0 || x >= width || y >= height) continue;
          const s = y * width + x;
          if (!before[s]) continue;
          out.set(out.subarray(4 * s, 4 * s + 4), 4 * t);
          filled[t] = 1;
          break;
        }
      }
    }
  }
  return out;
}
