import { readFileSync, statSync } from 'node:fs';
import { basename, dirname, resolve } from 'node:path';
import { InputError } from '../../core/inputError';
import type { TriangleMesh } from '../../core/mesh/triangleMesh';
import type { ImportedMesh, MeshFile } from '../../engines/meshImport/importedMesh';
import { importMesh } from '../../engines/meshImport/importMesh';
import { importObjMesh } from '../../engines/meshImport/importObjMesh';

/** Largest model file read (bytes): a 200 000-triangle OBJ is about 15 MB; anything far larger is a mistaken path. */
export const MAX_MODEL_FILE_BYTES = 256e6;

export interface NodeMeshLoader {
  /** OBJ models only (three's GLTFLoader is asynchronous): for resolveBakeSceneSync. */
  loadSync(path: string): TriangleMesh;
  /** Any model (OBJ, glTF, GLB): for resolveBakeScene. */
  load(path: string): Promise<TriangleMesh>;
  /** Every model imported so far by the path the scene gives, with units and warnings (report.json shows them). */
  readonly imported: Map<string, ImportedMesh>;
}

/** A file's bytes, or an InputError whose message is the reason alone ('no such file', 'file is too large …'). */
function readModelFile(file: string): Uint8Array {
  try {
    const size = statSync(file).size;
    if (size > MAX_MODEL_FILE_BYTES) throw new InputError(`file is too large (${(size / 1e6).toFixed(0)} MB; at most ${MAX_MODEL_FILE_BYTES / 1e6} MB)`);
    return new Uint8Array(readFileSync(file));
  } catch (error) {
    if (error instanceof InputError) throw error;
    const code = (error as NodeJS.ErrnoException).code;
    throw new InputError(code === 'ENOENT' ? 'no such file' : code ?? 'read error');
  }
}

function readModel(file: string, shown: string): Uint8Array {
  try {
    return readModelFile(file);
  } catch (error) {
    throw new InputError(`cannot read ${shown} (${(error as Error).message})`);
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
 */
export function createNodeMeshLoader(folder: string): NodeMeshLoader {
  const imported = new Map<string, ImportedMesh>();
  const prepare = (path: string): { files: MeshFile[]; readFile: (name: string) => Uint8Array } => {
    const file = resolve(folder, path);
    const modelFolder = dirname(file);
    return {
      files: [{ name: basename(file), bytes: readModel(file, path) }],
      // A referenced file's reason alone: the importer says which file and what for.
      readFile: (name) => readModelFile(resolve(modelFolder, safeDecode(name))),
    };
  };
  return {
    imported,
    loadSync(path) {
      if (!/\.obj$/i.test(path)) throw new InputError(`${path}: glTF models need the asynchronous scene loader (loadLightingSceneFileAsync); this caller reads OBJ only`);
      const { files, readFile } = prepare(path);
      const result = importObjMesh(files, { readFile });
      imported.set(path, result);
      return result.mesh;
    },
    async load(path) {
      const { files, readFile } = prepare(path);
      const result = await importMesh(files, { readFile });
      imported.set(path, result);
      return result.mesh;
    },
  };
}
