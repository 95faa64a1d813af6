import * as THREE from 'three';
import { objectSurfaceFragment, objectSurfaceVertex } from '../../../../shaders/objectSurface.glsl';
import type { PreparedObjects } from '../../bake/objects/preparedObjects';
import type { FinishTextureOnGpu } from '../createFinishTextures';
import type { SharedDisplayUniforms } from '../createRoomSurfaces';
import { MAX_LEVELS, TURBO_B, TURBO_G, TURBO_R } from '../falseColorScale';
import { OBJECT_FINISH_TEXTURE_OF, OBJECT_TEXTURE_SLOTS, type FinishTexture } from '../finishTextureKinds';
import type { ObjectRenderGeometry } from '../objectRenderGeometry';

const fragmentShader = objectSurfaceFragment({ maxLevels: MAX_LEVELS, turbo: [TURBO_R, TURBO_G, TURBO_B] });

/** What the room objects' parts share: the group, the materials and uniforms, what is drawn now and the selection. */
export interface ObjectsState {
  renderer: THREE.WebGLRenderer;
  /** Float textures filter linearly here (OES_texture_float_linear), else nearest. */
  linear: boolean;
  group: THREE.Group;
  /** The selected object's index in the geometry's ids (-1: none): a uniform of the material. */
  selected: { value: number };
  /** How many of the first objects are a shaped room's surfaces (front side only, never picked). */
  frontOnlyBelow: { value: number };
  material: THREE.ShaderMaterial;
  edgeMaterial: THREE.LineBasicMaterial;
  mesh: THREE.Mesh | null;
  edges: THREE.LineSegments | null;
  geometry: ObjectRenderGeometry | null;
  prepared: PreparedObjects | null;
  illuminance: THREE.DataTexture | null;
  reflectance: THREE.DataTexture | null;
  selectedId: string | null;
  /** The finishes drawn with a texture, one per slot of the shader. */
  slotFinishes: [string, FinishTexture][];
  /** The textured object finishes' patterns, made on first use (a 512² pattern takes a moment on the CPU). */
  slots: FinishTextureOnGpu[] | null;
  texturesOn: boolean;
}

function objectsMaterial(display: SharedDisplayUniforms, selected: { value: number }, frontOnlyBelow: { value: number }): THREE.ShaderMaterial {
  return new THREE.ShaderMaterial({
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
}

export function initialObjectsState(display: SharedDisplayUniforms, renderer: THREE.WebGLRenderer): ObjectsState {
  const linear = renderer.extensions.has('OES_texture_float_linear');
  const group = new THREE.Group();
  group.name = 'objects-group';
  const selected = { value: -1 };
  const frontOnlyBelow = { value: 0 };
  return {
    renderer,
    linear,
    group,
    selected,
    frontOnlyBelow,
    material: objectsMaterial(display, selected, frontOnlyBelow),
    edgeMaterial: new THREE.LineBasicMaterial({ color: 0x2a8ffa, depthTest: true }),
    mesh: null,
    edges: null,
    geometry: null,
    prepared: null,
    illuminance: null,
    reflectance: null,
    selectedId: null,
    slotFinishes: Object.entries(OBJECT_FINISH_TEXTURE_OF).slice(0, OBJECT_TEXTURE_SLOTS),
    slots: null,
    texturesOn: true,
  };
}

export function clearEdges(s: ObjectsState): void {
  if (!s.edges) return;
  s.group.remove(s.edges);
  s.edges.geometry.dispose();
  s.edges = null;
}

/** Nothing drawn: the mesh, the edges and both textures freed. */
export function clearObjects(s: ObjectsState): void {
  clearEdges(s);
  if (s.mesh) {
    s.group.remove(s.mesh);
    s.mesh.geometry.dispose();
    s.mesh = null;
  }
  s.illuminance?.dispose();
  s.reflectance?.dispose();
  s.illuminance = s.reflectance = null;
  s.material.uniforms.uIlluminance.value = null;
  s.material.uniforms.uReflectance.value = null;
  s.geometry = null;
  s.prepared = null;
}
