import * as THREE from 'three';
import type { Rgb } from '../../../core/model/lightingScene/lightingScene';
import { luminaireFragment, luminaireVertex } from '../../../../shaders/luminaireShading.glsl';
import type { SharedDisplayUniforms } from '../createRoomSurfaces';
import { luminanceToward, type EmitterPhotometry } from '../luminaires/viewLuminance';

/**
 * Finishes (docs/viewer.md, "Luminaires"): housings, rails and connectors a dark matte grey
 * (ρ 0.06, black-grey powder coat; assumed), steel wire ρ 0.4 (assumed). The flat sRGB colours are
 * what lux mode and the selection draw.
 */
export const HOUSING = { reflectance: 0.06, flat: [0.16, 0.16, 0.17] as Rgb };
export const CABLE = { reflectance: 0.4, flat: [0.3, 0.3, 0.3] as Rgb };
/** The UI's accent blue (the plan's selection colour), for the selected module. */
const SELECTED: Rgb = [0.16, 0.56, 0.98];

/**
 * A glowing face: its material, the module's photometry and which hemisphere it emits (side, area),
 * its centre in its mesh's frame, the module's weight now and its luminance toward the last eye it
 * was drawn for (cd/m², full power; luminaires/viewLuminance.ts).
 */
export interface Emitter {
  material: THREE.ShaderMaterial;
  photometry: EmitterPhotometry | null;
  side: -1 | 1;
  area: number;
  centre: THREE.Vector3;
  weight: Rgb;
  luminance: number;
}

/** One module's meshes: its housing meshes (repainted on selection), all of them (for picks) and its emitters. */
export interface ModuleEntry {
  meshes: THREE.Mesh[];
  all: THREE.Mesh[];
  emitters: Emitter[];
}

export interface MaterialOptions {
  flat: Rgb;
  reflectance?: number;
  emitter?: boolean;
  selected?: boolean;
}

/** What the hardware's parts share: the group, its materials and uniforms, the modules drawn and the selection. */
export interface HardwareState {
  group: THREE.Group;
  display: SharedDisplayUniforms;
  shading: { linear?: boolean };
  ambient: { value: THREE.Vector3 };
  housing: THREE.ShaderMaterial;
  cable: THREE.ShaderMaterial;
  selectedMaterial: THREE.ShaderMaterial;
  selected: string | null;
  /** Per module: its housing meshes, its emitter materials with their luminance at full weight per side. */
  modules: Map<string, ModuleEntry>;
  emitterMaterials: THREE.ShaderMaterial[];
}

/** A part's material: the display's shared uniforms, the room's ambient light and this finish. */
export function hardwareMaterial(s: Pick<HardwareState, 'display' | 'shading' | 'ambient'>, opts: MaterialOptions): THREE.ShaderMaterial {
  return new THREE.ShaderMaterial({
    glslVersion: THREE.GLSL3,
    vertexShader: luminaireVertex,
    fragmentShader: luminaireFragment(s.shading),
    // Open parts (a wire, the rail's channel) show their inner side; the shader flips its normal.
    side: THREE.DoubleSide,
    uniforms: {
      uExposure: s.display.uExposure,
      uAdapt: s.display.uAdapt,
      uMode: s.display.uMode,
      uAmbient: s.ambient,
      uEmitter: { value: opts.emitter ? 1 : 0 },
      uFlat: { value: opts.selected ? 1 : 0 },
      uColor: { value: new THREE.Vector3(...opts.flat) },
      uReflectance: { value: new THREE.Vector3().setScalar(opts.reflectance ?? 0) },
      uLuminance: { value: new THREE.Vector3(0, 0, 0) },
    },
  });
}

export function initialHardwareState(display: SharedDisplayUniforms, shading: { linear?: boolean }): HardwareState {
  const base = { display, shading, ambient: { value: new THREE.Vector3(0, 0, 0) } };
  return {
    ...base,
    group: new THREE.Group(),
    housing: hardwareMaterial(base, { flat: HOUSING.flat, reflectance: HOUSING.reflectance }),
    cable: hardwareMaterial(base, { flat: CABLE.flat, reflectance: CABLE.reflectance }),
    selectedMaterial: hardwareMaterial(base, { flat: SELECTED, selected: true }),
    selected: null,
    modules: new Map(),
    emitterMaterials: [],
  };
}

/** The selected module's housing in the selection colour, every other in its own material. */
export function paintSelection(s: HardwareState): void {
  for (const [id, m] of s.modules) for (const mesh of m.meshes) mesh.material = id === s.selected ? s.selectedMaterial : (mesh.userData.material as THREE.ShaderMaterial);
}

function showGlow(e: Emitter): void {
  (e.material.uniforms.uLuminance.value as THREE.Vector3).set(e.weight[0] * e.luminance, e.weight[1] * e.luminance, e.weight[2] * e.luminance);
}

/** The emitters' module weight (dimming × colour, linear RGB); not finite or negative: dark. */
export function setEmitterWeight(emitters: Emitter[], w: Rgb): void {
  for (const e of emitters) {
    e.weight = w.map((c) => (Number.isFinite(c) && c > 0 ? c : 0)) as Rgb;
    showGlow(e);
  }
}

const eye = new THREE.Vector3();
const faceCentre = new THREE.Vector3();

/**
 * The face's luminance toward the camera drawing it, set just before its draw (the mesh's
 * onBeforeRender, so every view, the glare pass's HDR target and the A/B compare's second view
 * included, shows the face as seen from its own camera): one bilinear look-up in the photometry
 * per face and frame.
 */
export function glowToward(e: Emitter, mesh: THREE.Object3D, camera: THREE.Camera): void {
  eye.setFromMatrixPosition(camera.matrixWorld);
  faceCentre.copy(e.centre).applyMatrix4(mesh.matrixWorld);
  e.luminance = e.photometry ? luminanceToward(e.photometry, e.side, e.area, [eye.x - faceCentre.x, eye.y - faceCentre.y, eye.z - faceCentre.z]) : 0;
  showGlow(e);
}

/** Everything drawn removed: geometries and emitter materials freed (the shared materials stay). */
export function clearHardware(s: HardwareState): void {
  s.group.traverse((o) => (o as THREE.Mesh).geometry?.dispose());
  s.group.clear();
  for (const m of s.emitterMaterials.splice(0)) m.dispose();
  s.modules = new Map();
}
