import * as THREE from 'three';
import type { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import type { Vec3 } from '../../../core/model/lightingScene/lightingScene';

/** The orbit camera's pose, kept while the spotlight view has the camera. */
export interface OrbitPose {
  position: THREE.Vector3;
  target: THREE.Vector3;
  fov: number;
  up: THREE.Vector3;
}

export function saveOrbitPose(cam: THREE.PerspectiveCamera, controls: OrbitControls): OrbitPose {
  return { position: cam.position.clone(), target: controls.target.clone(), fov: cam.fov, up: cam.up.clone() };
}

/** The orbit camera back where it was, its controls aimed at the same target. */
export function restoreOrbitPose(cam: THREE.PerspectiveCamera, controls: OrbitControls, saved: OrbitPose): void {
  cam.position.copy(saved.position);
  cam.up.copy(saved.up);
  cam.fov = saved.fov;
  cam.lookAt(saved.target);
  cam.updateProjectionMatrix();
  controls.target.copy(saved.target);
}

/** The camera at a pose (spotlightPose.ts): position, up, looking at the target, with its field of view. */
export function setCameraPose(cam: THREE.PerspectiveCamera, p: { fov: number; position: Vec3; up: Vec3; target: Vec3 }): void {
  cam.fov = p.fov;
  cam.position.set(...p.position);
  cam.up.set(...p.up);
  cam.lookAt(new THREE.Vector3(...p.target));
  cam.updateProjectionMatrix();
}
