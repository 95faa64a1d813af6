/**
 * The library's thumbnails (docs/furniture.md, "Thumbnails"): the committed sprite sheet is what
 * the meshes give now (regenerated here, pixel for pixel), the rasteriser draws a known solid as
 * its analytic projection and shading, and no two items look alike.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { PNG } from 'pngjs';
import { describe, expect, it } from 'vitest';
import { FURNITURE_LIBRARY } from '../../../src/core/model/objects/furniture/furnitureLibrary';
import { boxPart, composeParts } from '../../../src/core/model/objects/furniture/meshParts';
import { FURNITURE_THUMBNAIL_PIXELS, FURNITURE_THUMBNAIL_SHEET, furnitureThumbnailSheet } from '../../../src/hosts/node/furnitureThumbnails';
import { THUMBNAIL_VIEW, meshThumbnail } from '../../../src/hosts/node/meshThumbnail';

const encode = (c: number) => Math.round(255 * (c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055));

describe('furniture thumbnails', () => {
  const sheet = furnitureThumbnailSheet();

  it('the committed sheet is the one the meshes draw now (run scripts/furnitureThumbnails.ts after changing an item)', () => {
    const committed = PNG.sync.read(readFileSync(join(__dirname, '../../..', FURNITURE_THUMBNAIL_SHEET)));
    expect([committed.width, committed.height]).toEqual([FURNITURE_THUMBNAIL_PIXELS * FURNITURE_LIBRARY.length, FURNITURE_THUMBNAIL_PIXELS]);
    expect([sheet.width, sheet.height]).toEqual([committed.width, committed.height]);
    let differing = 0;
    for (let i = 0; i < sheet.data.length; i++) if (sheet.data[i] !== committed.data[i]) differing++;
    expect(differing).toBe(0);
  });

  it('a 1 m cube of ρ 0.5: covers its analytic projected area (|d·x| + |d·y| + |d·z| m²) within 1.5 %, its top shows ρ × the stated shading', () => {
    const cube = composeParts([boxPart('body', [-0.5, 0, -0.5], [0.5, 1, 0.5])], () => [0.5, 0.5, 0.5]);
    const size = 200;
    const image = meshThumbnail(cube, size);
    const a = (THUMBNAIL_VIEW.azimuth * Math.PI) / 180;
    const e = (THUMBNAIL_VIEW.elevation * Math.PI) / 180;
    const toward = [Math.sin(a) * Math.cos(e), Math.sin(e), Math.cos(a) * Math.cos(e)];
    const right = [Math.cos(a), 0, -Math.sin(a)];
    const up = [-Math.sin(a) * Math.sin(e), Math.cos(e), -Math.cos(a) * Math.sin(e)];
    // The image fits the larger side of the projected bounds into (1 − 2 · 0.06) of its width.
    const extent = (axis: number[]) => {
      const values = [];
      for (let k = 0; k < 8; k++) values.push(axis[0] * (k & 1 ? 0.5 : -0.5) + axis[1] * (k & 2 ? 1 : 0) + axis[2] * (k & 4 ? 0.5 : -0.5));
      return Math.max(...values) - Math.min(...values);
    };
    const metresPerPixel = Math.max(extent(right), extent(up)) / (size * 0.88);
    let covered = 0;
    for (let i = 3; i < image.data.length; i += 4) covered += image.data[i] / 255;
    const analytic = (Math.abs(toward[0]) + Math.abs(toward[1]) + Math.abs(toward[2])) / metresPerPixel ** 2;
    expect(Math.abs(covered / analytic - 1)).toBeLessThan(0.015);
    // The top face's centre (0, 1, 0) seen on screen; its normal (0, 1, 0) in view axes is (0, cos e, sin e).
    const l = THUMBNAIL_VIEW.light;
    const ll = Math.hypot(l[0], l[1], l[2]);
    const shade = THUMBNAIL_VIEW.ambient + (1 - THUMBNAIL_VIEW.ambient) * Math.max(0, (Math.cos(e) * l[1] + Math.sin(e) * l[2]) / ll);
    const topCentreY = Math.cos(e); // the top's centre on the view's up axis
    const minY = Math.min(...[0, 1].flatMap((y) => [-0.5, 0.5].flatMap((x) => [-0.5, 0.5].map((z) => up[0] * x + up[1] * y + up[2] * z))));
    const heightPixels = extent(up) / metresPerPixel;
    const row = Math.floor(size - (size - heightPixels) / 2 - (topCentreY - minY) / metresPerPixel);
    const pixel = image.data.subarray(4 * (row * size + size / 2), 4 * (row * size + size / 2) + 4);
    expect(Array.from(pixel)).toEqual([encode(0.5 * shade), encode(0.5 * shade), encode(0.5 * shade), 255]);
  });

  it('no two items look alike: every pair differs by more than 32 of 255 levels in more than 15 % of the cell (shape and colour, over white)', () => {
    const n = FURNITURE_THUMBNAIL_PIXELS;
    const overWhite = (index: number) => {
      const out = new Float64Array(n * n * 3);
      for (let k = 0; k < n * n; k++) {
        const o = 4 * (Math.floor(k / n) * sheet.width + index * n + (k % n));
        const alpha = sheet.data[o + 3] / 255;
        for (let c = 0; c < 3; c++) out[3 * k + c] = sheet.data[o + c] * alpha + 255 * (1 - alpha);
      }
      return out;
    };
    const cells = FURNITURE_LIBRARY.map((_, i) => overWhite(i));
    for (let i = 0; i < cells.length; i++) {
      for (let j = i + 1; j < cells.length; j++) {
        let differing = 0;
        for (let k = 0; k < n * n; k++) {
          const d = Math.max(...[0, 1, 2].map((c) => Math.abs(cells[i][3 * k + c] - cells[j][3 * k + c])));
          if (d > 32) differing++;
        }
        expect(differing / (n * n), `${FURNITURE_LIBRARY[i].id} vs ${FURNITURE_LIBRARY[j].id}`).toBeGreaterThan(0.15);
      }
    }
  });
});
