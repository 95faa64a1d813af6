import * as THREE from 'three';
import { defaultSurfaceFinishes } from '../../core/catalog/surfaceFinishes';
import { matchFinish, type SurfaceFinish } from '../../core/model/catalogSchema/surfaceFinish';
import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { encodeModulation, finishModulation, mipChain, type FinishModulation } from './finishTexture';
import { FINISH_TEXTURE_OF } from './finishTextureKinds';

/** One finish's pattern on the GPU: the texture, the gain that makes its 8-bit mean exactly 1, and its period in metres. */
export interface FinishTextureOnGpu {
  texture: THREE.DataTexture;
  gain: Rgb;
  period: number;
}

export interface FinishTextures {
  /** The pattern of the finish whose reflectance this is (the planner's own match, matchFinish); null for a custom reflectance or a finish without a texture. */
  forReflectance(reflectance: Rgb): FinishTextureOnGpu | null;
  dispose(): void;
}

/**
 * A finish's pattern (finishTexture.ts) as a GPU texture: 8-bit with the gain that keeps its mean at
 * exactly 1, repeating, mipmapped with our own mean-keeping chain (mipChain), trilinear and
 * anisotropic so fine patterns (carpet, grain) do not shimmer.
 */
export function uploadModulation(mod: FinishModulation, anisotropy: number): FinishTextureOnGpu {
  const { data, gain } = encodeModulation(mod);
  const texture = new THREE.DataTexture(data, mod.size, mod.size, THREE.RGBAFormat, THREE.UnsignedByteType);
  texture.wrapS = texture.wrapT = THREE.RepeatWrapping;
  texture.magFilter = THREE.LinearFilter;
  texture.minFilter = THREE.LinearMipmapLinearFilter;
  // Our own mip chain (mipChain: the mean kept at every level), not the driver's.
  texture.mipmaps = mipChain(data, mod.size) as unknown as typeof texture.mipmaps;
  texture.generateMipmaps = false;
  texture.anisotropy = anisotropy;
  // Linear data (a modulation), not sRGB colour.
  texture.colorSpace = THREE.NoColorSpace;
  texture.needsUpdate = true;
  return { texture, gain, period: mod.period };
}

/**
 * The room finishes' patterns (finishTexture.ts), made once per finish on first use. The room stores
 * reflectances, not finish ids, so a surface's finish is found as the finish picker finds it: by its
 * reflectance. Mipmapped, trilinear and anisotropic so fine patterns (carpet, grain) do not shimmer.
 */
export function createFinishTextures(renderer: THREE.WebGLRenderer, finishes: readonly SurfaceFinish[] = defaultSurfaceFinishes): FinishTextures {
  const made = new Map<string, FinishTextureOnGpu>();
  const anisotropy = Math.min(8, renderer.capabilities.getMaxAnisotropy());
  return {
    forReflectance(reflectance) {
      const finish = matchFinish(finishes, reflectance);
      const kind = finish ? FINISH_TEXTURE_OF[finish.id] : undefined;
      if (!finish || !kind) return null;
      let t = made.get(finish.id);
      if (!t) {
        t = uploadModulation(finishModulation(kind, reflectance, 1), anisotropy);
        made.set(finish.id, t);
      }
      return t;
    },
    dispose() {
      for (const t of made.values()) t.texture.dispose();
      made.clear();
    },
  };
}
