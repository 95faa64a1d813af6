import type { BakeObject } from '../bake/bakeScene';
import type { BakeSettings } from '../bake/bakeSettings';
import { prepareObjects } from '../bake/objects/prepareObjects';
import type { PreparedObjects } from '../bake/objects/preparedObjects';
import { objectsKey } from '../relight/objectsKey';

/**
 * The view's copy of the objects' geometry: prepareObjects on the same objects with the same
 * texel size and atlas limit as the baker (prepareBakeInputs), so the atlas layout is the one the maps
 * come on (prepareObjects is deterministic: same input, byte-identical atlas). Computed again
 * exactly when the relight engine rebakes for the objects (the same objectsKey: an object's
 * mesh, placement or reflectance changed), never for a dimming change.
 */
export function createObjectsMemo(): (objects: readonly BakeObject[] | undefined, settings: Pick<BakeSettings, 'texelSize' | 'maxTextureSize'>) => PreparedObjects | null {
  let lastKey = '';
  let last: PreparedObjects | null = null;
  return (objects, settings) => {
    if (!objects || objects.length === 0) {
      lastKey = '';
      last = null;
      return null;
    }
    const key = `${settings.texelSize}/${settings.maxTextureSize}/${objectsKey(objects)}`;
    if (key !== lastKey) {
      last = prepareObjects([...objects], { texelSize: settings.texelSize, maxAtlasSize: settings.maxTextureSize });
      lastKey = key;
    }
    return last;
  };
}
