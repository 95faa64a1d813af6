import { InputError } from '../../core/inputError';
import type { TriangleMesh } from '../../core/mesh/triangleMesh';
import { MAX_STORED_MESH_CHARS, storedMeshChars } from '../../core/model/files/storedMeshSize';
import { formatCount } from './triangleBudget';

/**
 * Refuse a model whose mesh would not fit in a saved configuration (a file over 1 MB does not
 * reopen, issue 32): the reason and the numbers, counted after welding, so a model just under the
 * triangle budget with many unshared vertices is refused here with its real size.
 */
export function checkStorable(name: string, mesh: TriangleMesh): void {
  const chars = storedMeshChars(name, mesh);
  if (chars > MAX_STORED_MESH_CHARS) {
    throw new InputError(
      `${name}: ${formatCount(mesh.indices.length / 3)} triangles on ${formatCount(mesh.positions.length / 3)} vertices take ${mb(chars)} MB in a saved configuration; at most ${mb(MAX_STORED_MESH_CHARS)} MB fit — simplify the model and import again`,
    );
  }
}

function mb(chars: number): string {
  return (chars / 1e6).toFixed(2);
}
