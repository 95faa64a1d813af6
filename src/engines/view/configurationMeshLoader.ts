import { InputError } from '../../core/inputError';
import type { TriangleMesh } from '../../core/mesh/triangleMesh';
import type { Configuration } from '../../core/model/configuration/configuration';
import { objectMesh } from '../../core/model/objects/objectGeometry';
import { OBJECT_MESH_PREFIX } from '../../core/model/files/toLightingScene';

/**
 * The app's mesh loader for resolveBakeScene: a configuration's lighting scene names each object's
 * mesh `object:<id>` (toLightingScene), resolved here from the configuration itself (the library
 * item or imported mesh with the object's finishes, objectMesh). Any other path is refused: the
 * configurator reads no mesh files while baking. The browser's 3D view and `luxbox render` of a
 * configuration file both use it.
 */
export function configurationMeshLoader(config: Configuration): (path: string) => TriangleMesh {
  return (path) => {
    if (!path.startsWith(OBJECT_MESH_PREFIX)) throw new InputError(`${path}: a configuration's objects are named '${OBJECT_MESH_PREFIX}<id>'`);
    return objectMesh(config, path.slice(OBJECT_MESH_PREFIX.length));
  };
}
