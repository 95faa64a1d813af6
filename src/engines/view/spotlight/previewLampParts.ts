import type * as THREE from 'three';
import { aimedOrientation } from '../../../core/model/modules/aim';
import type { ModuleAim } from '../../../core/model/configuration/configuration';
import type { Photometry } from '../../../core/photometry/types';
import { luminaireRotation } from '../../bake/luminaireRotation';
import { candelaTexture } from '../spotPreview';

/** The preview lamp's candela texture, made again only when the photometry changes. */
export function createCandelaCache(linearFloat: boolean): { get(photometry: Photometry): THREE.DataTexture; dispose(): void } {
  let texture: { photometry: Photometry; texture: THREE.DataTexture } | null = null;
  return {
    get(photometry) {
      if (texture?.photometry !== photometry) {
        texture?.texture.dispose();
        texture = { photometry, texture: candelaTexture(photometry, linearFloat) };
      }
      return texture.texture;
    },
    dispose() {
      texture?.texture.dispose();
    },
  };
}

/** World → the luminaire's local frame for a module at this heading, roll and aim: the transpose of the (orthonormal) local → world rotation, row-major. */
export function worldToLuminaire(heading: number, roll: number, aim: ModuleAim): number[] {
  const o = aimedOrientation(heading, roll, aim);
  const m = luminaireRotation(o.yaw, o.pitch, o.roll);
  return [m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]];
}
