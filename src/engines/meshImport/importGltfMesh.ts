import type { Material } from 'three';
import { GLTFLoader, type GLTF } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { InputError } from '../../core/inputError';
import { oneLine } from '../../core/untrustedJson';
import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { clampReflectance } from './clampReflectance';
import { collectTriangles, type ImportMaterial } from './collectTriangles';
import { finishImport, type ImportedMesh, type MeshFile, type MeshImportOptions } from './importedMesh';
import { DEFAULT_MATERIAL_NAME, DEFAULT_REFLECTANCE } from './defaultMaterial';
import { packGltf } from './packGltf';
import { shortName } from './readMtlMaterials';

/**
 * Import a glTF 2.0 model (.gltf with embedded or external buffers, or .glb) with three's
 * GLTFLoader: the file made self-contained first (packGltf: buffers resolved, textures removed),
 * then parsed; node transforms (the scene graph) applied. ρ per material is its
 * `pbrMetallicRoughness.baseColorFactor` (linear by the glTF 2.0 spec, §3.9.2), clamped below 1;
 * a primitive without a material is grey 0.5 (the spec's default material is white, which no
 * real surface is). glTF lengths are metres (§3.4), so 'auto' units are metres.
 */
export async function importGltfMesh(files: readonly MeshFile[], options: MeshImportOptions = {}): Promise<ImportedMesh> {
  const packed = await packGltf(files, options);
  const { name, json } = packed;
  const warnings = [...packed.warnings];
  let gltf: GLTF;
  try {
    gltf = await new Promise<GLTF>((resolve, reject) => new GLTFLoader().parse(packed.glb, '', resolve, reject));
  } catch (error) {
    // Structure the container checks do not cover (accessor types, sparse data …) fails inside the loader.
    throw new InputError(`${name}: cannot read the model (${oneLine(error instanceof Error ? error.message.replace(/^THREE\.GLTFLoader:\s*/, '') : String(error), 100)})`);
  }
  if (!gltf.scene) throw new InputError(`${name}: no scene`);
  const materials = Array.isArray(json.materials) ? json.materials : [];
  const byIndex = new Map<number, ImportMaterial>();
  let unassigned = false;
  const fileMesh = collectTriangles(
    gltf.scene,
    name,
    (material: Material | undefined) => {
      const index = material ? gltf.parser.associations.get(material)?.materials : undefined;
      if (index === undefined || !materials[index]) {
        unassigned = true;
        return { name: DEFAULT_MATERIAL_NAME, reflectance: DEFAULT_REFLECTANCE, twoSided: false };
      }
      let known = byIndex.get(index);
      if (!known) {
        const m = materials[index];
        const label = typeof m.name === 'string' && m.name !== '' ? m.name : `material ${index}`;
        const pbr = (m.pbrMetallicRoughness ?? {}) as { baseColorFactor?: unknown };
        const factor = pbr.baseColorFactor ?? [1, 1, 1, 1];
        let rgb: Rgb;
        if (Array.isArray(factor) && factor.length >= 3 && factor.slice(0, 3).every((x) => typeof x === 'number' && Number.isFinite(x))) {
          rgb = clampReflectance(factor.slice(0, 3) as Rgb, `${name}: material '${shortName(label)}': base colour`, warnings);
        } else {
          warnings.push(`${name}: material '${shortName(label)}': baseColorFactor is not [r, g, b, a]; grey 0.5 used`);
          rgb = DEFAULT_REFLECTANCE;
        }
        known = { name: label, reflectance: rgb, twoSided: m.doubleSided === true };
        byIndex.set(index, known);
      }
      return known;
    },
    warnings,
  );
  if (unassigned) warnings.push(`${name}: some primitives have no material; they are grey 0.5`);
  return finishImport(name, fileMesh, 'm', options, warnings);
}
