import { InputError } from '../../core/inputError';

/**
 * Most triangles an imported model may have: the baker's BVH and atlas handle far more, but a
 * 200 000-triangle model already costs seconds of CPU preparation and a large atlas, and real
 * furniture needs a few thousand (docs/scene-format.md, "Importing meshes").
 */
export const MAX_IMPORT_TRIANGLES = 200_000;

/** 312450 → "312 450" (groups of three digits, as the messages print counts). */
export function formatCount(n: number): string {
  return String(Math.round(n)).replace(/\B(?=(\d{3})+(?!\d))/g, ' ');
}

/** Refuse a model above MAX_IMPORT_TRIANGLES with a message saying what to do. */
export function checkTriangleBudget(file: string, triangles: number): void {
  if (triangles > MAX_IMPORT_TRIANGLES) {
    throw new InputError(
      `${file} has ${formatCount(triangles)} triangles; the limit is ${formatCount(MAX_IMPORT_TRIANGLES)} — simplify the model (e.g. Blender's Decimate) and import again`,
    );
  }
}
