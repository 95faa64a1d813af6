import { basename, dirname, resolve } from 'node:path';
import { InputError } from '../../core/inputError';
import { oneLine } from '../../core/untrustedJson';
import type { TriangleMesh } from '../../core/mesh/triangleMesh';
import type { ImportedMesh, MeshFile } from '../../engines/meshImport/importedMesh';
import { importMesh } from '../../engines/meshImport/importMesh';
import { importObjMesh } from '../../engines/meshImport/importObjMesh';
import { readRegularFile } from './readRegularFile';
import { MODEL_BYTE_CAPS } from '../../engines/meshImport/byteCaps';

/**
 * Largest model file read (bytes): the importer's largest byte cap (a .glb or an external buffer,
 * MODEL_BYTE_CAPS.glb, 64 MB); the importer then applies each format's own cap with its message.
 * Reading stops here, whatever the file system says its size is.
 */
export const MAX_MODEL_FILE_BYTES = Math.max(...Object.values(MODEL_BYTE_CAPS));

export interface NodeMeshLoader {
  /** OBJ models only (three's GLTFLoader is asynchronous): for resolveBakeSceneSync. */
  loadSync(path: string): TriangleMesh;
  /** Any model (OBJ, glTF, GLB): for resolveBakeScene. */
  load(path: string): Promise<TriangleMesh>;
  /** Every model imported so far by the path the scene gives, with units and warnings (report.json shows them). */
  readonly imported: Map<string, ImportedMesh>;
}

/**
 * A file's bytes, or an InputError whose message is the reason alone ('no such file', 'file is too
 * large …', 'a character device, not a regular file'): regular files only, the size cap checked
 * while reading, inside `within` when given (readRegularFile).
 */
function readModelFile(file: string, within: readonly string[] | undefined): Uint8Array {
  return readRegularFile(file, { maxBytes: MAX_MODEL_FILE_BYTES, within });
}

function readModel(file: string, shown: string, within: readonly string[] | undefined): Uint8Array {
  try {
    return readModelFile(file, within);
  } catch (error) {
    throw new InputError(oneLine(`cannot read ${shown} (${(error as Error).message})`));
  }
}

function safeDecode(uri: string): string {
  try {
    return decodeURIComponent(uri);
  } catch {
    return uri;
  }
}

/**
 * The Node host's mesh loader for a scene file in `folder`: a mesh path is relative to it (absolute
 * paths kept), files the model refers to (MTL libraries, glTF buffers) relative to the model's own
 * folder; each path imported once, units detected automatically (docs/scene-format.md, "Objects").
 * Every file, the model's own references included, is read only inside `within` when given.
 */
export function createNodeMeshLoader(folder: string, options: { within?: readonly string[] } = {}): NodeMeshLoader {
  const { within } = options;
  const imported = new Map<string, ImportedMesh>();
  const prepare = (path: string): { files: MeshFile[]; readFile: (name: string) => Uint8Array; refused: () => void } => {
    const file = resolve(folder, path);
    const modelFolder = dirname(file);
    /** The first referenced file refused for what it is or where it lies (not merely missing). */
    let refusal: string | null = null;
    return {
      files: [{ name: basename(file), bytes: readModel(file, path, within) }],
      // A referenced file's reason alone: the importer says which file and what for.
      readFile: (name) => {
        try {
          return readModelFile(resolve(modelFolder, safeDecode(name)), within);
        } catch (error) {
          if (error instanceof InputError && error.message !== 'no such file') refusal ??= `cannot read ${name} (${error.message})`;
          throw error;
        }
      },
      // The importer turns an unreadable MTL library into a warning (grey materials), right for a
      // missing one; a device, pipe, folder, oversize file or one outside the allowed folders is
      // refused instead, naming it (issue 32: `mtllib /dev/zero`).
      refused: () => {
        // One line of at most 200 characters, as every importer message (a model may name a file with thousands).
        if (refusal) throw new InputError(oneLine(`${path}: ${refusal}`));
      },
    };
  };
  return {
    imported,
    loadSync(path) {
      if (!/\.obj$/i.test(path)) throw new InputError(`${path}: glTF models need the asynchronous scene loader (loadLightingSceneFileAsync); this caller reads OBJ only`);
      const { files, readFile, refused } = prepare(path);
      const result = importObjMesh(files, { readFile });
      refused();
      imported.set(path, result);
      return result.mesh;
    },
    async load(path) {
      const { files, readFile, refused } = prepare(path);
      let result: ImportedMesh;
      try {
        result = await importMesh(files, { readFile });
      } catch (error) {
        refused();
        throw error;
      }
      refused();
      imported.set(path, result);
      return result.mesh;
    },
  };
}
