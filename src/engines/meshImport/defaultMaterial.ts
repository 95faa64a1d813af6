import type { Rgb } from '../../core/model/lightingScene/lightingScene';

/** Grey of a material no file defines (missing MTL, undefined `usemtl`, glTF primitive without material): docs/scene-format.md. */
export const DEFAULT_REFLECTANCE: Rgb = [0.5, 0.5, 0.5];

/** Name of that material (OBJ faces before any `usemtl`, glTF primitives without a material). */
export const DEFAULT_MATERIAL_NAME = 'default';
