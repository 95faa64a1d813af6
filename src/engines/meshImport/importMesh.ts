import { InputError } from '../../core/inputError';
import { boundedMessage } from './boundedMessage';
import type { ImportedMesh, MeshFile, MeshImportOptions } from './importedMesh';
import { importGltfMesh } from './importGltfMesh';
import { importObjMesh } from './importObjMesh';
import { scanMtllibNames } from './scanMtllibNames';
import { findFile } from './findFile';

/**
 * Import a model for the baker (docs/scene-format.md, "Importing meshes"), the same code in the
 * browser and in Node: either an .obj (with its .mtl files among `files` or read through
 * `options.readFile`) or one .gltf (external .bin buffers likewise) or .glb. Returns the mesh in
 * metres with the units applied and detected, the triangle count and warnings; every problem with
 * the files is an InputError naming the file.
 */
export async function importMesh(files: readonly MeshFile[], options: MeshImportOptions = {}): Promise<ImportedMesh> {
  try {
    return await importAny(files, options);
  } catch (error) {
    throw boundedMessage(error);
  }
}

async function importAny(files: readonly MeshFile[], options: MeshImportOptions): Promise<ImportedMesh> {
  if (files.some((f) => /\.(gltf|glb)$/i.test(f.name))) return importGltfMesh(files, options);
  const obj = files.find((f) => /\.obj$/i.test(f.name));
  if (!obj) {
    const names = files.map((f) => f.name).join(', ');
    throw new InputError(`${names || 'no file'}: not a model luxbox reads (pick an .obj with its .mtl, or one .gltf or .glb)`);
  }
  // The OBJ path is synchronous: fetch the material libraries it names first, if the reader is asynchronous.
  const all = [...files];
  const { readFile } = options;
  if (readFile) {
    for (const lib of scanMtllibNames(obj.bytes, obj.name)) {
      if (findFile(all, lib)) continue;
      try {
        all.push({ name: lib, bytes: await readFile(lib) });
      } catch {
        // Reported by importObjMesh as a missing library (a warning: the model still loads, grey).
      }
    }
  }
  return importObjMesh(all, { units: options.units });
}
