import * as THREE from 'three';
import type { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import type { BakeScene } from '../bake/bakeScene';
import type { CameraPresetName } from './cameraPresets';
import { framePreset } from './framePreset';
import { orbitLimits } from './orbitLimits';
import type { RoomView } from './roomView';

/**
 * The viewer's camera: the chosen preset, the view's size, and the pose the
 * user left it in (orbit, pan, zoom), which survives a rebuilt room view
 * (display context restored) and a resize. A new room size re-frames the preset;
 * the eye preset also re-frames when the luminaires moved, until the user moves the camera.
 * The orbit stays within the preset's limits (orbitLimits.ts: the eye camera inside the room).
 */
export interface CameraRig {
  /** The scene to frame; the preset is applied again only when what it frames changed. */
  setScene(scene: BakeScene): void;
  setPreset(name: CameraPresetName): void;
  resize(width: number, height: number): void;
  readonly size: { width: number; height: number };
  /** A rebuilt room view: its camera takes the pose the user left. */
  attach(view: RoomView): void;
}

/** What a preset frames: the room's size and, for the eye preset (it looks at the light), where the luminaires are. */
function framingKey(scene: BakeScene, preset: CameraPresetName): { room: string; light: string } {
  const { width, height, depth } = scene.room;
  return { room: JSON.stringify([width, height, depth]), light: preset === 'eye' ? JSON.stringify(scene.luminaires.map((l) => [l.position, l.yaw, l.pitch, (l.dimming ?? 1) > 0])) : '' };
}

export function createCameraRig(controls: OrbitControls, view: RoomView): CameraRig {
  let scene: BakeScene | null = null;
  let key = { room: '', light: '' };
  let preset: CameraPresetName = 'corner';
  let size = { width: 1, height: 1 };
  let pose = { position: view.camera.position.clone(), target: new THREE.Vector3() };
  /** The user moved the camera since the preset framed it: a new light no longer re-frames it. */
  let moved = false;

  const limit = () => {
    if (!scene) return;
    const limits = orbitLimits(preset, scene.room);
    controls.minPolarAngle = limits.minPolarAngle;
    controls.maxPolarAngle = limits.maxPolarAngle;
    controls.maxDistance = limits.maxDistance;
    controls.minDistance = limits.minDistance;
  };
  const apply = (fromPreset: boolean) => {
    if (!scene) return;
    const aspect = size.width / size.height;
    limit();
    if (fromPreset) {
      const p = framePreset(preset, scene.room, aspect, scene);
      pose = { position: new THREE.Vector3(...p.position), target: new THREE.Vector3(...p.target) };
      view.setCamera(p, aspect);
      // A portrait screen steps the outside views back (framePreset): the limit never pulls them in.
      controls.maxDistance = Math.max(controls.maxDistance, 1.5 * pose.position.distanceTo(pose.target));
      moved = false;
    } else {
      view.camera.aspect = aspect;
      view.camera.position.copy(pose.position);
      view.camera.updateProjectionMatrix();
    }
    controls.target.copy(pose.target);
    controls.update();
  };
  controls.addEventListener('change', () => {
    if (!scene) return;
    // The eye camera stays inside the room, its target too (a pan cannot carry it through a wall).
    const limits = orbitLimits(preset, scene.room);
    if (!limits.inside) return;
    const c = view.camera.position;
    const inside = limits.inside([c.x, c.y, c.z]);
    const t = limits.inside([controls.target.x, controls.target.y, controls.target.z]);
    if (inside.some((v, i) => v !== [c.x, c.y, c.z][i])) c.set(...inside);
    if (t.some((v, i) => v !== [controls.target.x, controls.target.y, controls.target.z][i])) controls.target.set(...(t as Vec3));
  });
  controls.addEventListener('end', () => {
    pose = { position: view.camera.position.clone(), target: controls.target.clone() };
    moved = true;
  });

  return {
    setScene(next) {
      scene = next;
      const k = framingKey(next, preset);
      const reframe = k.room !== key.room || (k.light !== key.light && !moved);
      key = k;
      if (reframe) apply(true);
    },
    setPreset(name) {
      preset = name;
      if (scene) key = framingKey(scene, preset);
      apply(true);
    },
    resize(width, height) {
      size = { width: Math.max(1, width), height: Math.max(1, height) };
      view.camera.aspect = size.width / size.height;
      view.camera.updateProjectionMatrix();
    },
    get size() {
      return size;
    },
    attach(next) {
      view = next;
      controls.object = next.camera;
      apply(false);
    },
  };
}
