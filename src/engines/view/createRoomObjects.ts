import * as THREE from 'three';
import { objectSurfaceFragment, objectSurfaceVertex } from '../../../shaders/objectSurface.glsl';
import type { PreparedObjects } from '../bake/objects/preparedObjects';
import type { SharedDisplayUniforms } from './createRoomSurfaces';
import { dilateReflectance } from './dilateReflectance';
import { MAX_LEVELS, TURBO_B, TURBO_G, TURBO_R } from './falseColorScale';
import type { ObjectLight } from './objectLight';
import { objectRenderGeometry, type ObjectRenderGeometry } from './objectRenderGeometry';
import { objectFinishRgb } from '../../core/model/objects/furniture/objectFinishes';
import { uploadModulation, type FinishTextureOnGpu } from './createFinishTextures';
import { finishModulation } from './finishTexture';
import { OBJECT_FINISH_TEXTURE_OF, OBJECT_TEXTURE_SLOTS } from './finishTextureKinds';
import { ROOM_OBJECT_PREFIX } from '../bake/shapedRoom/roomSurfaceObjects';

/** A shaped room's surfaces come first among the objects (encloseShapedRoom): how many ids lead with the room's prefix. */
function roomSurfaceCount(ids: readonly string[]): number {
  const k = ids.findIndex((id) => !id.startsWith(ROOM_OBJECT_PREFIX));
  return k < 0 ? ids.length : k;
}

const fragmentShader = objectSurfaceFragment({ maxLevels: MAX_LEVELS, turbo: [TURBO_R, TURBO_G, TURBO_B] });

/** Name of the objects' three.js mesh (tests and picking find it by name). */
export const OBJECTS_MESH_NAME = 'objects';

/**
 * All objects of the room as one three.js mesh with their baked light (objectRenderGeometry:
 * world triangles with atlas uvs), a float texture of the atlas's relit illuminance and one of
 * its reflectance, the room surfaces' display uniforms, and the selection highlight: a tint in
 * the shader plus the selected object's feature edges drawn as lines.
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
  const linear = renderer.extensions.has('OES_texture_float_linear');
  const group = new THREE.Group();
  group.name = 'objects-group';
  const selected = { value: -1 };
  /** How many of the first objects are a shaped room's surfaces (front side only, never picked). */
  const frontOnlyBelow = { value: 0 };
  const material = new THREE.ShaderMaterial({
    glslVersion: THREE.GLSL3,
    vertexShader: objectSurfaceVertex,
    fragmentShader,
    uniforms: {
      uIlluminance: { value: null },
      uReflectance: { value: null },
      uSelected: selected,
      uFrontOnlyBelow: frontOnlyBelow,
      uSlot0: { value: null },
      uSlot1: { value: null },
      uSlotRho: { value: Array.from({ length: OBJECT_TEXTURE_SLOTS }, () => new THREE.Vector3(-1, -1, -1)) },
      uSlotGain: { value: Array.from({ length: OBJECT_TEXTURE_SLOTS }, () => new THREE.Vector3(1, 1, 1)) },
      uSlotPeriod: { value: new Array<number>(OBJECT_TEXTURE_SLOTS).fill(1) },
      uSlotOn: { value: new Array<number>(OBJECT_TEXTURE_SLOTS).fill(0) },
      ...display,
    },
    side: THREE.DoubleSide,
    // Pushed back a hair in depth so the selection's edge lines, which lie in the surfaces, win the depth test.
    polygonOffset: true,
    polygonOffsetFactor: 1,
    polygonOffsetUnits: 1,
  });
  const edgeMaterial = new THREE.LineBasicMaterial({ color: 0x2a8ffa, depthTest: true });
  let mesh: THREE.Mesh | null = null;
  let edges: THREE.LineSegments | null = null;
  let geometry: ObjectRenderGeometry | null = null;
  let prepared: PreparedObjects | null = null;
  let illuminance: THREE.DataTexture | null = null;
  let reflectance: THREE.DataTexture | null = null;
  let selectedId: string | null = null;
  // The textured object finishes' patterns, made on first use (a 512² pattern takes a moment on the CPU).
  const slotFinishes = Object.entries(OBJECT_FINISH_TEXTURE_OF).slice(0, OBJECT_TEXTURE_SLOTS);
  let slots: FinishTextureOnGpu[] | null = null;
  let texturesOn = true;
  const applySlots = () => {
    const u = material.uniforms;
    if (texturesOn && mesh && !slots) {
      const anisotropy = Math.min(8, renderer.capabilities.getMaxAnisotropy());
      slots = slotFinishes.map(([id, kind]) => uploadModulation(finishModulation(kind, objectFinishRgb(id), 1), anisotropy));
    }
    slotFinishes.forEach(([id], i) => {
      const t = texturesOn && slots ? slots[i] : null;
      u[`uSlot${i}`].value = t?.texture ?? null;
      (u.uSlotRho.value as THREE.Vector3[])[i].set(...objectFinishRgb(id));
      (u.uSlotGain.value as THREE.Vector3[])[i].set(...(t?.gain ?? [1, 1, 1]));
      (u.uSlotPeriod.value as number[])[i] = t?.period ?? 1;
      (u.uSlotOn.value as number[])[i] = t ? 1 : 0;
    });
  };

  const clearEdges = () => {
    if (!edges) return;
    group.remove(edges);
    edges.geometry.dispose();
    edges = null;
  };
  const clear = () => {
    clearEdges();
    if (mesh) {
      group.remove(mesh);
      mesh.geometry.dispose();
      mesh = null;
    }
    illuminance?.dispose();
    reflectance?.dispose();
    illuminance = reflectance = null;
    material.uniforms.uIlluminance.value = null;
    material.uniforms.uReflectance.value = null;
    geometry = null;
    prepared = null;
  };

  /** The selected object's feature edges (creases over 20°), drawn with the depth test (hidden edges stay hidden; the surfaces' polygon offset keeps the visible ones from z-fighting). */
  const showSelection = () => {
    clearEdges();
    const index = geometry && selectedId !== null ? geometry.ids.indexOf(selectedId) : -1;
    selected.value = index;
    if (!geometry || index < 0) return;
    const picked: number[] = [];
    for (let k = 0; k < geometry.triangleCount; k++) {
      if (geometry.objectOfTriangle[k] === index) for (let c = 0; c < 9; c++) picked.push(geometry.positions[9 * k + c]);
    }
    const solid = new THREE.BufferGeometry();
    solid.setAttribute('position', new THREE.Float32BufferAttribute(picked, 3));
    edges = new THREE.LineSegments(new THREE.EdgesGeometry(solid, 20), edgeMaterial);
    solid.dispose();
    edges.name = 'objects-selection';
    edges.visible = mesh?.visible ?? false;
    edges.renderOrder = 1;
    group.add(edges);
  };

  return {
    group,
    get geometry() {
      return geometry;
    },
    setGeometry(next) {
      if (next === prepared) return;
      clear();
      if (!next || next.triangleCount === 0) return;
      prepared = next;
      geometry = objectRenderGeometry(next);
      frontOnlyBelow.value = roomSurfaceCount(geometry.ids);
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(geometry.positions, 3));
      g.setAttribute('normal', new THREE.BufferAttribute(geometry.normals, 3));
      g.setAttribute('uv', new THREE.BufferAttribute(geometry.uvs, 2));
      const index = new Float32Array(geometry.triangleCount * 3);
      for (let k = 0; k < geometry.triangleCount; k++) index.fill(geometry.objectOfTriangle[k], 3 * k, 3 * k + 3);
      g.setAttribute('objectIndex', new THREE.BufferAttribute(index, 1));
      g.computeBoundingSphere();
      g.computeBoundingBox();
      mesh = new THREE.Mesh(g, material);
      mesh.name = OBJECTS_MESH_NAME;
      mesh.visible = false;
      group.add(mesh);
      const { width, height } = next.atlas;
      reflectance = new THREE.DataTexture(dilateReflectance(next.atlas), width, height, THREE.RGBAFormat, THREE.FloatType);
      reflectance.minFilter = reflectance.magFilter = THREE.NearestFilter;
      reflectance.generateMipmaps = false;
      reflectance.needsUpdate = true;
      material.uniforms.uReflectance.value = reflectance;
      applySlots();
      showSelection();
    },
    setLight(light) {
      if (!mesh || !prepared) return;
      const { width, height } = prepared.atlas;
      if (!light || light.atlas.width !== width || light.atlas.height !== height || light.atlas.texelSize !== prepared.atlas.texelSize) {
        // No light yet, or light of the objects before a move (another atlas): hidden until the new bake's first maps.
        mesh.visible = false;
        if (edges) edges.visible = false;
        return;
      }
      const n = width * height;
      if (!illuminance) {
        // RGBA float: three has no RGB float format; alpha unused.
        illuminance = new THREE.DataTexture(new Float32Array(n * 4), width, height, THREE.RGBAFormat, THREE.FloatType);
        illuminance.minFilter = illuminance.magFilter = linear ? THREE.LinearFilter : THREE.NearestFilter;
        illuminance.wrapS = illuminance.wrapT = THREE.ClampToEdgeWrapping;
        illuminance.generateMipmaps = false;
      }
      material.uniforms.uIlluminance.value = illuminance;
      const dst = illuminance.image.data as Float32Array;
      const src = light.total;
      for (let i = 0; i < n; i++) {
        dst[i * 4] = src[i * 3];
        dst[i * 4 + 1] = src[i * 3 + 1];
        dst[i * 4 + 2] = src[i * 3 + 2];
        dst[i * 4 + 3] = 1;
      }
      illuminance.needsUpdate = true;
      mesh.visible = true;
      if (edges) edges.visible = true;
    },
    setLightTexture(texture) {
      if (mesh?.visible) material.uniforms.uIlluminance.value = texture;
    },
    setFinishTextures(on) {
      texturesOn = on;
      applySlots();
    },
    setSelected(id) {
      if (id === selectedId) return;
      selectedId = id;
      showSelection();
    },
    objectAt(faceIndex) {
      if (!geometry || faceIndex < 0 || faceIndex >= geometry.triangleCount) return null;
      const object = geometry.objectOfTriangle[faceIndex];
      return object < frontOnlyBelow.value ? null : geometry.ids[object];
    },
    roomSurfaceAt(faceIndex) {
      if (!geometry || faceIndex < 0 || faceIndex >= geometry.triangleCount) return null;
      const object = geometry.objectOfTriangle[faceIndex];
      return object < frontOnlyBelow.value ? geometry.ids[object].slice(ROOM_OBJECT_PREFIX.length) : null;
    },
    dispose() {
      clear();
      for (const t of slots ?? []) t.texture.dispose();
      slots = null;
      material.dispose();
      edgeMaterial.dispose();
    },
  };
}
