import { OBJLoader } from 'three/examples/jsm/loaders/OBJLoader.js';
import type { Group, Material } from 'three';
import { InputError } from '../../core/inputError';
import { oneLine } from '../../core/untrustedJson';
import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { boundedMessage } from './boundedMessage';
import { checkByteCap, MODEL_BYTE_CAPS } from './byteCaps';
import { collectTriangles } from './collectTriangles';
import { decodeText } from './decodeText';
import { DEFAULT_MATERIAL_NAME, DEFAULT_REFLECTANCE } from './defaultMaterial';
import { findFile } from './findFile';
import { finishImport, type ImportedMesh, type MeshFile, type MeshImportOptions } from './importedMesh';
import { readMtlMaterials, shortName } from './readMtlMaterials';
import { scanObjText } from './scanObjText';

/**
 * Import a Wavefront OBJ model (with its MTL libraries) synchronously: the .obj among `files`
 * (MTL files among them or read through `options.readFile`, which must then return bytes, not a
 * promise). The file is checked line by line first (scanObjText), then read by three's OBJLoader
 * (objects, groups, materials, fan triangulation of polygons). Materials are named by `usemtl`;
 * ρ is the MTL's Kd used directly (the contract: docs/scene-format.md, "Importing meshes").
 */
export function importObjMesh(files: readonly MeshFile[], options: MeshImportOptions = {}): ImportedMesh {
  try {
    return importObj(files, options);
  } catch (error) {
    throw boundedMessage(error);
  }
}

function importObj(files: readonly MeshFile[], options: MeshImportOptions): ImportedMesh {
  const obj = files.find((f) => /\.obj$/i.test(f.name));
  if (!obj) throw new InputError(`no .obj file among ${files.map((f) => f.name).join(', ') || 'the files given'}`);
  const name = obj.name;
  const warnings: string[] = [];
  const scanned = scanObjText(obj.bytes, name);
  if (scanned.ignored.size > 0) {
    const list = [...scanned.ignored].map(([k, n]) => `${JSON.stringify(k)} ×${n}`).join(', ');
    warnings.push(`${name}: statements luxbox does not use were ignored: ${list}`.slice(0, 200));
  }

  const kd = new Map<string, Rgb>();
  let librariesFound = 0;
  for (const lib of scanned.mtllibs) {
    let bytes = findFile(files, lib)?.bytes;
    if (!bytes && options.readFile) {
      try {
        const read = options.readFile(lib);
        if (read instanceof Uint8Array) bytes = read;
      } catch {
        bytes = undefined;
      }
    }
    if (!bytes) {
      warnings.push(`${name}: material library ${shortName(lib)} not found; its materials are grey 0.5`);
      continue;
    }
    checkByteCap(shortName(lib), bytes.length, MODEL_BYTE_CAPS.mtl, 'a material library');
    librariesFound++;
    for (const [material, rgb] of readMtlMaterials(decodeText(bytes), lib, warnings)) if (!kd.has(material)) kd.set(material, rgb);
  }

  let group: Group;
  try {
    group = new OBJLoader().parse(scanned.text);
  } catch (error) {
    // scanObjText leaves OBJLoader only well-formed statements; this is the safety net for its own limits.
    throw new InputError(`${name}: cannot read the model (${oneLine(error instanceof Error ? error.message : String(error), 100)})`);
  }
  const undefinedMaterials = new Set<string>();
  const fileMesh = collectTriangles(
    group,
    name,
    (material: Material | undefined) => {
      const materialName = material?.name || DEFAULT_MATERIAL_NAME;
      const rgb = kd.get(materialName);
      if (!rgb && material?.name) undefinedMaterials.add(materialName);
      return { name: materialName, reflectance: rgb ?? DEFAULT_REFLECTANCE, twoSided: true };
    },
    warnings,
  );
  // A missing library was reported above; otherwise name each material no library defines.
  if (scanned.mtllibs.length === 0 && undefinedMaterials.size > 0) {
    warnings.push(`${name}: no material library (mtllib); every material is grey 0.5`);
  } else if (librariesFound > 0) {
    for (const m of undefinedMaterials) warnings.push(`${name}: material '${shortName(m)}' is not defined in ${scanned.mtllibs.join(', ')}; grey 0.5 used`);
  }
  return finishImport(name, fileMesh, null, options, warnings);
}
