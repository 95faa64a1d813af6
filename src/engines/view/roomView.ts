import * as THREE from 'three';
import { createWindowPanes } from './createWindowPanes';
import type { BakeDaylight } from '../bake/daylight/bakeDaylight';
import type { Mat3 } from './colourMatrices';
import { SURFACE_NAMES, type Rgb, type SurfaceName, type Vec3 } from '../../core/model/lightingScene/lightingScene';
import type { LitMaps } from '../relight/relightMaps';
import type { CameraPose } from './cameraPresets';
import type { PreparedObjects } from '../bake/objects/preparedObjects';
import { createRoomHardware } from './createRoomHardware';
import type { Room as ShapedRoom } from '../../core/room/normaliseRoom';
import { applyRoomShape, firstSeenHit } from './shapedRoomView';
import { createRoomObjects, OBJECTS_MESH_NAME, type RoomObjects } from './createRoomObjects';
import { createRoomSurfaces, type SharedDisplayUniforms, type ViewMode } from './createRoomSurfaces';
import type { Fixtures } from './fixtures';
import { meanIlluminance } from './meanIlluminance';
import type { ObjectLight } from './objectLight';
import type { SpotPreviewUniforms } from './spotPreview';
import { createRoomViewRender, materialsKey } from './roomViewRender';

export type { ViewMode } from './createRoomSurfaces';

/** What a pick hit: an object (furniture, imported model) or a module, by id. */
export type PickTarget = { kind: 'object' | 'module'; id: string };

/**
 * The 3D room: six surfaces showing the relit light maps, the objects with
 * theirs, the hardware, a camera. Shared by the browser viewer and `luxbox render` (three.js on
 * headless-gl), so both draw the same pixels from the same maps.
 */
export interface RoomView {
  readonly scene: THREE.Scene;
  readonly camera: THREE.PerspectiveCamera;
  /** The display uniforms the surfaces, objects and luminaires share (exposure, adaptation, mode, lux levels). */
  readonly display: SharedDisplayUniforms;
  /** Upload relit maps (RGB lux) and the room's reflectances. */
  setMaps(lit: LitMaps, reflectance: Record<SurfaceName, Rgb>): void;
  /** Show the GPU relight's textures (createViewRelight.ts) on the surfaces and objects the last setMaps/setObjectLight laid out: a relight. */
  setLightTextures(surfaces: Record<SurfaceName, THREE.Texture>, objects: THREE.Texture | null): void;
  /** The objects' geometry (PreparedObjects of the scene's objects, the same the baker lights; null: none). */
  setObjects(prepared: PreparedObjects | null): void;
  /** A room of any shape (null: the box): its own surfaces are drawn from the atlas, the box's hidden (shapedRoomView.ts). */
  setRoomShape(shape: ShapedRoom | null): void;
  /** A shaped room's window panes and what they show: the scene's daylight, or null for the night sky (createWindowPanes.ts). */
  setWindows(shape: ShapedRoom | null, daylight: BakeDaylight | null, glazing: BakeDaylight['glazing']): void;
  /** The objects' relit light (null: not yet, they stay hidden). */
  setObjectLight(light: ObjectLight | null): void;
  /** Highlight an object by id (null: none). */
  setSelectedObject(id: string | null): void;
  /** Each module's weight now (dimming × colour) by id: its glow follows (docs/viewer.md, "Luminaires"). */
  setModuleWeights(weights: ReadonlyMap<string, Rgb>): void;
  /** Draw a module in the selection colour (null: none). */
  setSelectedModule(id: string | null): void;
  /** The nearest object or module under a point of the view (normalised device coordinates, −1…1, y up), or null. */
  pick(ndcX: number, ndcY: number): PickTarget | null;
  /** The world point of the room's surfaces or the objects under a point of the view (aim at, docs/aiming.md), or null. */
  pickPoint(ndcX: number, ndcY: number): Vec3 | null;
  /** The aiming preview's lamp uniforms, shared by the room's surfaces (spotPreview.ts). */
  readonly preview: SpotPreviewUniforms;
  setExposure(exposure: number): void;
  /** Chromatic adaptation before the tone curve (row-major 3×3 on linear sRGB, chromaticAdaptation.ts). */
  setAdaptation(matrix: Mat3): void;
  setMode(mode: ViewMode, levels?: readonly number[]): void;
  /** Draw the room finishes' patterns (default on; light mode only). */
  setFinishTextures(on: boolean): void;
  setFixtures(fixtures: Fixtures): void;
  setCamera(pose: CameraPose, aspect: number): void;
  /**
   * Veiling glare round bright sources (glare/createGlarePass.ts, docs/viewer.md "Glare"): in light
   * mode on a renderer with half-float targets; never in lux mode. Off until set.
   */
  setGlare(on: boolean): void;
  /** Whether the last render went through the glare pass. */
  glareShown(): boolean;
  render(renderer: THREE.WebGLRenderer): void;
  /** A key of the materials the next render draws: a new key needs a compile (roomViewRender.ts materialsKey). */
  materialsKey(): string;
  /** Compile the next render's materials without blocking (three's compileAsync; createCompileGate.ts). */
  compileAsync(renderer: THREE.WebGLRenderer): Promise<unknown>;
  dispose(): void;
}

/** Picks against the room: world matrices are brought up to date by a render, and a pick may come before the first one. */
function createRoomPicker(scene: THREE.Scene, camera: THREE.PerspectiveCamera, hardware: ReturnType<typeof createRoomHardware>, objects: RoomObjects): Pick<RoomView, 'pick' | 'pickPoint'> {
  const raycaster = new THREE.Raycaster();
  const aim = (ndcX: number, ndcY: number) => {
    scene.updateMatrixWorld();
    camera.updateMatrixWorld();
    raycaster.setFromCamera(new THREE.Vector2(ndcX, ndcY), camera);
  };
  const walls = () => scene.children.filter((c) => (SURFACE_NAMES as readonly string[]).includes(c.name));
  const shownObjects = () => objects.group.children.filter((c) => c.name === OBJECTS_MESH_NAME && c.visible);
  return {
    pick(ndcX, ndcY) {
      aim(ndcX, ndcY);
      // The room's surfaces are no targets, but they hide what lies behind them. They are front-side
      // materials, which the raycaster honours: the walls the corner view looks through (back faces) do not block.
      const hit = firstSeenHit(raycaster.intersectObjects([...walls(), ...hardware.moduleMeshes(), ...shownObjects()], false), objects, raycaster.ray);
      if (!hit) return null;
      if (hit.object.name === OBJECTS_MESH_NAME) {
        const id = hit.faceIndex != null ? objects.objectAt(hit.faceIndex) : null;
        return id ? { kind: 'object', id } : null;
      }
      return hit.object.name.startsWith('module:') ? { kind: 'module', id: hit.object.name.slice('module:'.length) } : null;
    },
    pickPoint(ndcX, ndcY) {
      aim(ndcX, ndcY);
      const hit = firstSeenHit(raycaster.intersectObjects([...walls(), ...shownObjects()], false), objects, raycaster.ray);
      return hit ? [hit.point.x, hit.point.y, hit.point.z] : null;
    },
  };
}

export function createRoomView(renderer: THREE.WebGLRenderer): RoomView {
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(60, 1, 0.05, 500);
  const surfaces = createRoomSurfaces(scene, renderer);
  const drawing = createRoomViewRender(scene, camera, surfaces.display);
  // The luminaires share the surfaces' display uniforms: one exposure, adaptation and mode for the room and its glow.
  const hardware = createRoomHardware(surfaces.display);
  scene.add(hardware.group);
  const objects = createRoomObjects(surfaces.display, renderer);
  scene.add(objects.group);
  const windows = createWindowPanes(surfaces.display);
  scene.add(windows.group);
  return {
    scene,
    camera,
    display: surfaces.display,
    setMaps(lit, reflectance) {
      surfaces.setMaps(lit, reflectance);
      hardware.setAmbient(meanIlluminance(lit));
    },
    setLightTextures(textures, objectsTexture) {
      surfaces.setLightTextures(textures);
      if (objectsTexture) objects.setLightTexture(objectsTexture);
    },
    setExposure: surfaces.setExposure,
    setAdaptation: surfaces.setAdaptation,
    setMode: surfaces.setMode,
    setFinishTextures(on) {
      surfaces.setFinishTextures(on);
      objects.setFinishTextures(on);
    },
    setFixtures: hardware.setFixtures,
    setModuleWeights: hardware.setModuleWeights,
    setObjects: objects.setGeometry,
    setRoomShape: (shape) => applyRoomShape(objects, shape),
    setWindows: windows.set,
    setObjectLight: objects.setLight,
    setSelectedObject: objects.setSelected,
    setSelectedModule: hardware.setSelectedModule,
    ...createRoomPicker(scene, camera, hardware, objects),
    preview: surfaces.preview,
    setCamera(pose, aspect) {
      camera.fov = pose.fov;
      camera.aspect = aspect;
      camera.position.set(...pose.position);
      camera.up.set(0, 1, 0);
      camera.lookAt(new THREE.Vector3(...pose.target));
      camera.updateProjectionMatrix();
    },
    setGlare: drawing.setGlare,
    glareShown: drawing.glareShown,
    render: drawing.render,
    materialsKey: () => materialsKey(scene),
    compileAsync: drawing.compileAsync,
    dispose() {
      windows.dispose();
      drawing.dispose();
      hardware.dispose();
      objects.dispose();
      surfaces.dispose();
    },
  };
}
