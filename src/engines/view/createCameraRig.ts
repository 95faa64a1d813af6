import * as THREE from 'three';
import type { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import type { CameraPresetName } from './cameraPresets';
import { framePreset } from './framePreset';
import type { RoomView } from './roomView';

type Room = { width: number; height: number; depth: number };

/**
 * The viewer's camera: the chosen preset, the view's size, and the pose the
 * user left it in (orbit, pan, zoom), which survives a rebuilt room view
 * (display context restored) and a resize. A new room size re-frames the preset.
 */
export interface CameraRig {
  /** The room to frame; the preset is applied again only when its size changed. */
  setRoom(room: Room): void;
  setPreset(name: CameraPresetName): void;
  resize(width: number, height: number): void;
  readonly size: { width: number; height: number };
  /** A rebuilt room view: its camera takes the pose the user left. */
  attach(view: RoomView): void;
}

export function createCameraRig(controls: OrbitControls, view: RoomView): CameraRig {
  let room: Room | null = null;
  let roomKey = '';
  let preset: CameraPresetName = 'corner';
  let size = { width: 1, height: 1 };
  let pose = { position: view.camera.position.clone(), target: new THREE.Vector3() };

  const apply = (fromPreset: boolean) => {
    if (!room) return;
    const aspect = size.width / size.height;
    if (fromPreset) {
      const p = framePreset(preset, room, aspect);
      pose = { position: new THREE.Vector3(...p.position), target: new THREE.Vector3(...p.target) };
      view.setCamera(p, aspect);
    } else {
      view.camera.aspect = aspect;
      view.camera.position.copy(pose.position);
      view.camera.updateProjectionMatrix();
    }
    controls.target.copy(pose.target);
    controls.update();
  };
  controls.addEventListener('end', () => {
    pose = { position: view.camera.position.clone(), target: controls.target.clone() };
  });

  return {
    setRoom(next) {
      room = next;
      const key = JSON.stringify([next.width, next.height, next.depth]);
      if (key === roomKey) return;
      roomKey = key;
      apply(true);
    },
    setPreset(name) {
      preset = name;
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
