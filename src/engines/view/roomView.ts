import * as THREE from 'three';
import type { Rgb, SurfaceName } from '../../core/model/lightingScene';
import type { LitMaps } from '../relight/relightMaps';
import type { CameraPose } from './cameraPresets';
import { createRoomHardware } from './createRoomHardware';
import { createRoomSurfaces, type ViewMode } from './createRoomSurfaces';
import type { Fixtures } from './fixtures';

export type { ViewMode } from './createRoomSurfaces';

/**
 * The 3D room: six surfaces showing the relit light maps, the hardware, a
 * camera. Shared by the browser viewer and `luxbox render` (three.js on
 * headless-gl), so both draw the same pixels from the same maps.
 */
export interface RoomView {
  readonly scene: THREE.Scene;
  readonly camera: THREE.PerspectiveCamera;
  /** Upload relit maps (RGB lux) and the room's reflectances. */
  setMaps(lit: LitMaps, reflectance: Record<SurfaceName, Rgb>): void;
  setExposure(exposure: number): void;
  setMode(mode: ViewMode, levels?: readonly number[]): void;
  setFixtures(fixtures: Fixtures): void;
  setCamera(pose: CameraPose, aspect: number): void;
  render(renderer: THREE.WebGLRenderer): void;
  dispose(): void;
}

export function createRoomView(renderer: THREE.WebGLRenderer): RoomView {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x1d2126);
  const camera = new THREE.PerspectiveCamera(60, 1, 0.05, 500);
  const hardware = createRoomHardware();
  scene.add(hardware.group);
  const surfaces = createRoomSurfaces(scene, renderer);
  return {
    scene,
    camera,
    setMaps: surfaces.setMaps,
    setExposure: surfaces.setExposure,
    setMode: surfaces.setMode,
    setFixtures: hardware.setFixtures,
    setCamera(pose, aspect) {
      camera.fov = pose.fov;
      camera.aspect = aspect;
      camera.position.set(...pose.position);
      camera.up.set(0, 1, 0);
      camera.lookAt(new THREE.Vector3(...pose.target));
      camera.updateProjectionMatrix();
    },
    render(renderer) {
      renderer.render(scene, camera);
    },
    dispose() {
      hardware.dispose();
      surfaces.dispose();
    },
  };
}
