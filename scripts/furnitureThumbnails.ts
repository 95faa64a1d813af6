/**
 * Draws the furniture library's thumbnails from the meshes (src/hosts/node/furnitureThumbnails.ts)
 * and writes the sprite sheet the library panel shows. Run it after changing an item's geometry or
 * finishes; tests/hosts/node/furnitureThumbnails.test.ts fails until the committed sheet matches.
 *
 *   npx tsx scripts/furnitureThumbnails.ts
 */
import { writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { PNG } from 'pngjs';
import { FURNITURE_THUMBNAIL_SHEET, furnitureThumbnailSheet } from '../src/hosts/node/furnitureThumbnails';

const sheet = furnitureThumbnailSheet();
const png = new PNG({ width: sheet.width, height: sheet.height });
png.data.set(sheet.data);
const bytes = PNG.sync.write(png, { deflateLevel: 9 });
writeFileSync(join(dirname(fileURLToPath(import.meta.url)), '..', FURNITURE_THUMBNAIL_SHEET), bytes);
console.info(`${FURNITURE_THUMBNAIL_SHEET}: ${sheet.width} × ${sheet.height} px, ${bytes.length} bytes`);
