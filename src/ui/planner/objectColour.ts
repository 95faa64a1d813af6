import type { Configuration } from '../../core/model/configuration/configuration';
import { objectMesh } from '../../core/model/objects/objectGeometry';
import type { TriangleMesh } from '../../core/mesh/triangleMesh';
import { rgbColour } from './finishColour';

/** Per mesh (by its shared index array): each material's area facing up, seen from above. */
const upAreas = new WeakMap<Uint32Array, Float64Array>();

/**
 * Each material's projected area on the floor plane from the triangles that face up (normal
 * y > 0): what a look from above sees most of. Half |cross| of the x-z edge vectors is the
 * projected area of a triangle; its sign (counterclockwise seen from above = facing up, with
 * counterclockwise front faces) tells up from down.
 */
export function materialAreasFromAbove(mesh: TriangleMesh): Float64Array {
  const hit = upAreas.get(mesh.indices);
  if (hit && hit.length === mesh.materials.length) return hit;
  const areas = new Float64Array(mesh.materials.length);
  const p = mesh.positions;
  const idx = mesh.indices;
  for (let t = 0; t < idx.length / 3; t++) {
    const a = idx[3 * t] * 3;
    const b = idx[3 * t + 1] * 3;
    const c = idx[3 * t + 2] * 3;
    // Normal y = (b − a) × (c − a) in the z-x components: (bz − az)(cx − ax) − (bx − ax)(cz − az).
    const ny = (p[b + 2] - p[a + 2]) * (p[c] - p[a]) - (p[b] - p[a]) * (p[c + 2] - p[a + 2]);
    if (ny > 0) areas[mesh.materialOfTriangle[t]] += ny / 2;
  }
  upAreas.set(mesh.indices, areas);
  return areas;
}

/**
 * The plan's fill colour for an object: its main finish (the material seen most from above,
 * with the object's finishes applied), as sRGB. Grey when the mesh has no upward face.
 */
export function objectFillColour(config: Configuration, objectId: string): string {
  const mesh = objectMesh(config, objectId);
  const areas = materialAreasFromAbove(mesh);
  let best = -1;
  for (let i = 0; i < areas.length; i++) if (areas[i] > 0 && (best < 0 || areas[i] > areas[best])) best = i;
  return best < 0 ? '#9aa0a8' : rgbColour(mesh.materials[best].reflectance);
}
