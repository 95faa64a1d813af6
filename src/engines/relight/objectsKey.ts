import type { BakeObject } from '../bake/bakeScene';

/**
 * A key that changes whenever a scene's objects change in a way that changes the light: id,
 * placement, reflectance override, and the mesh itself (a 32-bit FNV-1a hash of its positions'
 * float bits, its indices and its materials' reflectances; Fowler–Noll–Vo). Empty for no objects,
 * so a scene without objects keys exactly as before objects existed.
 */
export function objectsKey(objects: readonly BakeObject[] | undefined): string {
  if (!objects || objects.length === 0) return '';
  return JSON.stringify(objects.map((o) => [o.id, o.position, o.yaw, o.scale, o.reflectance ?? null, meshHash(o)]));
}

function meshHash(o: BakeObject): number {
  let h = 0x811c9dc5;
  const mix = (words: ArrayLike<number>) => {
    for (let i = 0; i < words.length; i++) h = Math.imul(h ^ words[i], 0x01000193) >>> 0;
  };
  const { mesh } = o;
  mix(new Uint32Array(mesh.positions.buffer, mesh.positions.byteOffset, mesh.positions.length));
  mix(mesh.indices);
  mix(mesh.materialOfTriangle);
  mix(new Uint32Array(new Float32Array(mesh.materials.flatMap((m) => m.reflectance)).buffer));
  return h;
}
