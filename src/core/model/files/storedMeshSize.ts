/**
 * How much of a saved configuration an imported mesh takes (issue 32: imports were accepted whose
 * file then exceeded the 1 MB limit, so "Open file…" refused it). A mesh is stored as base64 of
 * its typed arrays (meshCodec.ts): 4 characters per 3 bytes of Float32 positions (12 bytes a
 * vertex), Uint32 indices (12 bytes a triangle) and Uint16 material slots (2 bytes a triangle).
 */
import type { TriangleMesh } from '../../mesh/triangleMesh';
import { INPUT_LIMITS } from '../../untrustedJson';

/**
 * Characters all imported meshes of one configuration may take in its file: 90 % of the file limit
 * (INPUT_LIMITS.maxTextLength, 1 000 000), leaving 100 000 for the room, the rail systems, the
 * objects and the JSON indentation (the furnished presets take under 40 000).
 */
export const MAX_STORED_MESH_CHARS = Math.floor(INPUT_LIMITS.maxTextLength * 0.9);

/** Longest name the scene file's schema accepts for a mesh or a material (sceneFile.ts: `z.string().max(200)`). */
export const MAX_STORED_NAME_LENGTH = 200;

/** Fewest characters one triangle can take: its indices and material slot (14 bytes as base64), vertices shared with others. */
export const MIN_STORED_CHARS_PER_TRIANGLE = (14 * 4) / 3;

const base64Length = (bytes: number): number => 4 * Math.ceil(bytes / 3);

/**
 * Characters an imported mesh named `name` takes in a saved configuration (pretty-printed as
 * serializeConfiguration writes it), counted from the array lengths without encoding anything;
 * within a few hundred characters of the real text (keys, indentation, escapes in names), which
 * the 100 000 characters MAX_STORED_MESH_CHARS leaves free absorb.
 */
export function storedMeshChars(name: string, mesh: TriangleMesh): number {
  const materials = mesh.materials.reduce((sum, m) => sum + JSON.stringify(m.name).length + 3 * 24 + 160, 0);
  return base64Length(mesh.positions.length * 4) + base64Length(mesh.indices.length * 4) + base64Length(mesh.materialOfTriangle.length * 2) + materials + JSON.stringify(name).length + 300;
}
