import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import { attemptAction } from '../../../src/core/model/actions/actionDefinitions';
import { createConfiguration, type Configuration } from '../../../src/core/model/configuration/configuration';
import { deserializeConfiguration, serializeConfiguration } from '../../../src/core/model/files/sceneFile';
import type { ImportedMesh } from '../../../src/engines/meshImport/importedMesh';

/** The largest room the planner allows (ROOM_LIMITS; every model the importer accepts, at most 100 m from its origin, is tried in it). */
const ROOM = { width: 30, depth: 30, height: 8 };

export interface ReopenResult {
  /** What is wrong: a non-finite vertex, a refusal that is the importer's business, a file that does not reopen or reads back different. */
  problems: string[];
  /** Whether addObject placed it (false: the room refused the placement, e.g. a 40 m model). */
  placed: boolean;
}

/**
 * An accepted import, checked the way a user meets it: every vertex finite, `addObject` in an
 * empty room, then "Save" (serializeConfiguration) and "Open file…" (deserializeConfiguration,
 * with its 1 MB limit and the schema's 200-character names) giving back the same mesh bit for
 * bit. A refusal by the room (too large, does not fit) is not a problem; a refusal of the mesh
 * itself (broken data, too large to store) is: the importer should have refused it.
 */
export function saveAndReopen(imported: ImportedMesh): ReopenResult {
  const problems: string[] = [];
  const { mesh } = imported;
  for (let i = 0; i < mesh.positions.length; i++) {
    if (!Number.isFinite(mesh.positions[i])) {
      problems.push(`non-finite vertex: positions[${i}] = ${mesh.positions[i]}`);
      return { problems, placed: false };
    }
  }
  const room = createConfiguration(ROOM);
  const outcome = attemptAction(room, 'addObject', { source: { kind: 'import', name: imported.name, mesh, units: imported.units } }, defaultCatalog);
  if (!outcome.ok) {
    if (outcome.code === 'importedModelBroken') problems.push(`accepted by the importer, refused by addObject: ${outcome.reason}`);
    return { problems, placed: false };
  }
  let text: string;
  let back: Configuration;
  try {
    text = serializeConfiguration(outcome.next, defaultCatalog);
    back = deserializeConfiguration(text, defaultCatalog, 'saved.luxbox.json');
  } catch (error) {
    problems.push(`does not save and reopen: ${error instanceof Error ? error.message : String(error)}`.slice(0, 300));
    return { problems, placed: true };
  }
  const [entry] = Object.values(back.importedMeshes);
  const same = (a: ArrayLike<number>, b: ArrayLike<number>): boolean => a.length === b.length && Array.prototype.every.call(a, (x: number, i: number) => Object.is(x, b[i]));
  if (!entry) problems.push('the reopened file has no imported mesh');
  else {
    if (entry.name !== imported.name) problems.push(`name reads back as ${JSON.stringify(entry.name.slice(0, 40))}`);
    if (!same(entry.mesh.positions, mesh.positions) || !same(entry.mesh.indices, mesh.indices) || !same(entry.mesh.materialOfTriangle, mesh.materialOfTriangle)) problems.push('the mesh reads back different');
    if (JSON.stringify(entry.mesh.materials) !== JSON.stringify(mesh.materials)) problems.push('the materials read back different');
  }
  return { problems, placed: true };
}
