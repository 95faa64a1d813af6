import { InputError } from '../../core/inputError';
import { MAX_STORED_MESH_CHARS, MIN_STORED_CHARS_PER_TRIANGLE } from '../../core/model/files/storedMeshSize';

/**
 * Most triangles an imported model may have: what a saved configuration can hold at the fewest
 * characters a triangle takes (MAX_STORED_MESH_CHARS / MIN_STORED_CHARS_PER_TRIANGLE ≈ 48 200,
 * rounded down). A model above it could never be saved and reopened, so it is refused before any
 * geometry is built; one below it is still checked for its real stored size (checkStorable.ts).
 * Real furniture needs a few thousand (docs/scene-format.md, "Importing meshes").
 */
export const MAX_IMPORT_TRIANGLES = Math.floor(MAX_STORED_MESH_CHARS / MIN_STORED_CHARS_PER_TRIANGLE / 1000) * 1000;

/** 312450 → "312 450" (groups of three digits, as the messages print counts). */
export function formatCount(n: number): string {
  return String(Math.round(n)).replace(/\B(?=(\d{3})+(?!\d))/g, ' ');
}

/** Refuse a model above MAX_IMPORT_TRIANGLES with a message saying what to do; `atLeast`: counting stopped at the cap. */
export function checkTriangleBudget(file: string, triangles: number, atLeast = false): void {
  if (triangles > MAX_IMPORT_TRIANGLES) {
    throw new InputError(
      `${file} has ${atLeast ? 'more than ' : ''}${formatCount(atLeast ? MAX_IMPORT_TRIANGLES : triangles)} triangles; the limit is ${formatCount(MAX_IMPORT_TRIANGLES)} (what a saved configuration holds) — simplify the model (e.g. Blender's Decimate) and import again`,
    );
  }
}
