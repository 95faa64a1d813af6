import type * as THREE from 'three';
import type { PreparedObjects } from '../bake/objects/preparedObjects';
import { ROOM_OBJECT_PREFIX } from '../bake/shapedRoom/roomSurfaceObjects';
import type { SharedDisplayUniforms } from './createRoomSurfaces';
import type { ObjectLight } from './objectLight';
import type { ObjectRenderGeometry } from './objectRenderGeometry';
import { applySlots, setObjectsGeometry, setObjectsLight, showSelection } from './objects/roomObjectsParts';
import { clearObjects, initialObjectsState } from './objects/roomObjectsState';

export { OBJECTS_MESH_NAME } from './objects/roomObjectsParts';

/**
 * All objects of the room as one three.js mesh with their baked light (objectRenderGeometry:
 * world triangles with atlas uvs), a float texture of the atlas's relit illuminance and one of
 * its reflectance, the room surfaces' display uniforms, and the selection highlight: a tint in
 * the shader plus the selected object's feature edges drawn as lines.
 *
 * Its parts share one ObjectsState (objects/roomObjectsState.ts); objects/roomObjectsParts.ts
 * builds the mesh, shows the light, the selection and the finishes' textures.
 */
export interface RoomObjects {
  readonly group: THREE.Group;
  /** The objects' geometry (null: none). Hidden until their light arrives (setLight). */
  setGeometry(prepared: PreparedObjects | null): void;
  /** The objects' relit light on the atlas of the current geometry (null: none yet). */
  setLight(light: ObjectLight | null): void;
  /** Light the GPU relight wrote on the current atlas (createViewRelight.ts): shown where `setLight` showed light before (a relight). */
  setLightTexture(texture: THREE.Texture): void;
  /** Highlight one object by id (null: none). */
  setSelected(id: string | null): void;
  /** Draw the veneers' wood grain (default on; light mode only): OBJECT_FINISH_TEXTURE_OF. */
  setFinishTextures(on: boolean): void;
  /** The object id of a triangle of the drawn mesh (three's Raycaster faceIndex), or null (none, or a shaped room's surface). */
  objectAt(faceIndex: number): string | null;
  /** The shaped room's surface id ('floor', 'wall-2', …) of a triangle of the drawn mesh, or null (an object). */
  roomSurfaceAt(faceIndex: number): string | null;
  readonly geometry: ObjectRenderGeometry | null;
  dispose(): void;
}

export function createRoomObjects(display: SharedDisplayUniforms, renderer: THREE.WebGLRenderer): RoomObjects {
  const s = initialObjectsState(display, renderer);
  return {
    group: s.group,
    get geometry() {
      return s.geometry;
    },
    setGeometry: (next) => setObjectsGeometry(s, next),
    setLight: (light) => setObjectsLight(s, light),
    setLightTexture(texture) {
      if (s.mesh?.visible) s.material.uniforms.uIlluminance.value = texture;
    },
    setFinishTextures(on) {
      s.texturesOn = on;
      applySlots(s);
    },
    setSelected(id) {
      if (id === s.selectedId) return;
      s.selectedId = id;
      showSelection(s);
    },
    objectAt(faceIndex) {
      const g = s.geometry;
      if (!g || faceIndex < 0 || faceIndex >= g.triangleCount) return null;
      const object = g.objectOfTriangle[faceIndex];
      return object < s.frontOnlyBelow.value ? null : g.ids[object];
    },
    roomSurfaceAt(faceIndex) {
      const g = s.geometry;
      if (!g || faceIndex < 0 || faceIndex >= g.triangleCount) return null;
      const object = g.objectOfTriangle[faceIndex];
      return object < s.frontOnlyBelow.value ? g.ids[object].slice(ROOM_OBJECT_PREFIX.length) : null;
    },
    dispose() {
      clearObjects(s);
      for (const t of s.slots ?? []) t.texture.dispose();
      s.slots = null;
      s.material.dispose();
      s.edgeMaterial.dispose();
    },
  };
}
