import type { BakeScene } from '../bake/bakeScene';
import { geometryKey, roomKey } from '../relight/luminaireGroups';
import { objectsKey } from '../relight/objectsKey';

/**
 * What makes a new picture rather than a relight of the same one: the room (size,
 * reflectances), the objects, and each module's photometry, position and aim, never its
 * dimming, colour or filter. The eye adaptation (eyeAdaptation.ts) holds while this stays the
 * same and adapts again when it changes.
 */
export function sceneGeometryKey(scene: BakeScene): string {
  return `${roomKey(scene.room)}|${objectsKey(scene.objects)}|${scene.luminaires.map(geometryKey).sort().join(';')}`;
}
