import { shortName } from './readMtlMaterials';
import type { Json, GltfJson } from './gltfJson';
import { list, objectAt } from './gltfJson';

/** Extensions that only change shading or textures: dropped with the textures (luxbox reads a base colour factor). */
export const DROPPED_EXTENSIONS = /^(KHR_materials_|KHR_texture_|EXT_texture_|MSFT_texture_)/;

/** Remove images, textures and texture references; a base-colour texture leaves a warning (its factor is used). */
export function stripTextures(json: GltfJson, name: string, warnings: string[], fail: (p: string) => never): void {
  const materials = list(json, 'materials', fail);
  let textured = 0;
  materials.forEach((_, i) => {
    const m = objectAt(materials, i, 'materials', fail);
    const pbr = m.pbrMetallicRoughness;
    if (typeof pbr === 'object' && pbr !== null && !Array.isArray(pbr)) {
      const p = pbr as Json;
      if (p.baseColorTexture !== undefined) {
        textured++;
        if (textured <= 3) warnings.push(`${name}: material '${shortName(String(m.name ?? `materials[${i}]`))}' has a base-colour texture; luxbox uses its base colour factor`);
      }
      delete p.baseColorTexture;
      delete p.metallicRoughnessTexture;
    }
    delete m.normalTexture;
    delete m.occlusionTexture;
    delete m.emissiveTexture;
    delete m.extensions;
  });
  if (textured > 3) warnings.push(`${name}: ${textured - 3} more materials have base-colour textures (factors used)`);
  delete json.images;
  delete json.textures;
  delete json.samplers;
  delete json.animations;
  for (const key of ['extensionsUsed', 'extensionsRequired']) {
    const exts = list(json, key, fail);
    json[key] = exts.filter((e) => typeof e === 'string' && !DROPPED_EXTENSIONS.test(e));
  }
}
