import { FURNITURE_LIBRARY, furnitureMesh } from '../../core/model/objects/furniture/furnitureLibrary';
import { meshThumbnail, spriteSheet, type RgbaImage } from './meshThumbnail';

/** Pixels a side of one thumbnail in the sheet: twice the 48 CSS pixels the library panel shows, for high-density screens. */
export const FURNITURE_THUMBNAIL_PIXELS = 96;

/** Where the committed sheet lives, from the repository root (the library panel imports it). */
export const FURNITURE_THUMBNAIL_SHEET = 'src/ui/planner/furnitureThumbnails.png';

/**
 * Every library item drawn from its own mesh and default finishes (meshThumbnail), side by side
 * in FURNITURE_LIBRARY's order: the sprite sheet the library panel shows its thumbnails from.
 * Written by scripts/furnitureThumbnails.ts; tests/hosts/node/furnitureThumbnails.test.ts checks
 * that the committed sheet is what the meshes give now.
 */
export function furnitureThumbnailSheet(): RgbaImage {
  return spriteSheet(FURNITURE_LIBRARY.map((item) => meshThumbnail(furnitureMesh(item.id), FURNITURE_THUMBNAIL_PIXELS)));
}
