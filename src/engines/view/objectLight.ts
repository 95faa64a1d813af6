import type { LitMaps, ObjectDirectTotal } from '../relight/relightMaps';

/** The objects' relit light: RGB lux per atlas texel (3 floats, row 0 first) on the atlas they were baked on. */
export type ObjectLight = Pick<ObjectDirectTotal, 'atlas' | 'total'>;

/** The objects' part of relit maps (the relight engine adds it for a scene with objects), or null. */
export function objectLightOf(lit: LitMaps): ObjectLight | null {
  const objects = lit.maps.objects;
  return objects && objects.total.length > 0 ? objects : null;
}
