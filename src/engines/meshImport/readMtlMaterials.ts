import { MTLLoader } from 'three/examples/jsm/loaders/MTLLoader.js';
import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { clampReflectance } from './clampReflectance';

/**
 * The diffuse colour (`Kd`) of every material of an MTL file, read with three's MTLLoader
 * (its `materialsInfo`: the raw values, before any three.js material or colour conversion).
 * The lighting-scene contract takes Kd as the reflectance ρ directly (docs/scene-format.md,
 * "Importing meshes"), clamped to [0, MAX_REFLECTANCE]; a material without a usable Kd is grey
 * 0.5. Problems are warnings, never errors: a bad colour must not stop a model from loading.
 */
export function readMtlMaterials(text: string, file: string, warnings: string[]): Map<string, Rgb> {
  const creator = new MTLLoader().parse(text, '');
  const out = new Map<string, Rgb>();
  for (const [name, info] of Object.entries(creator.materialsInfo as Record<string, { kd?: unknown }>)) {
    const kd = info.kd;
    if (!Array.isArray(kd) || kd.length < 3 || !kd.slice(0, 3).every((x) => typeof x === 'number' && Number.isFinite(x))) {
      if (kd !== undefined) warnings.push(`${file}: material '${shortName(name)}': Kd is not three numbers; grey 0.5 used`);
      else warnings.push(`${file}: material '${shortName(name)}' has no Kd; grey 0.5 used`);
      out.set(name, [0.5, 0.5, 0.5]);
      continue;
    }
    out.set(name, clampReflectance(kd.slice(0, 3) as Rgb, `${file}: material '${shortName(name)}': Kd`, warnings));
  }
  return out;
}

export function shortName(name: string): string {
  const flat = name.replace(/[\r\n\t\u2028\u2029]+/g, ' ');
  return flat.length > 40 ? `${flat.slice(0, 39)}…` : flat;
}
