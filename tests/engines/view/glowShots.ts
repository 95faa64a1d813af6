/**
 * How the glow tests (l3dGlow, luminaireModels) look at a luminaire's emitting face: the room
 * hardware alone on a float target before the tone curve, and the centre pixel of the whole room
 * view as the shopper sees it.
 */
import * as THREE from 'three';
import type { Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import { createRoomHardware } from '../../../src/engines/view/createRoomHardware';
import type { SharedDisplayUniforms } from '../../../src/engines/view/createRoomSurfaces';
import type { FixtureModule, Fixtures } from '../../../src/engines/view/fixtures';
import { createRoomView } from '../../../src/engines/view/roomView';

/**
 * The hardware of one luminaire hanging level at 2 m (centre [0, 2, 0], 0.15 m long, no rails),
 * switched on or off: `which` names it, its kind, its light and, for a GLDF luminaire, its body.
 */
export function oneLuminaire(which: Pick<FixtureModule, 'id' | 'kind' | 'light' | 'body'>): (on: boolean) => Fixtures {
  const module = (on: boolean): FixtureModule => ({ centre: [0, 2, 0], heading: 0, length: 0.15, on, orientation: { yaw: 0, pitch: 0, roll: 0 }, mount: 0, ...which });
  return (on) => ({ rails: [], railWidth: 0, connectors: [], cables: [], modules: [module(on)] });
}

export interface GlowPose {
  position: Vec3;
  target: Vec3;
  fov: number;
}

/**
 * The room hardware (createRoomHardware, linear output, identity adaptation, exposure `exposure`)
 * with `fixtures`, seen from `pose` (near plane `near`, camera up `up`) on a `width` × `height` float target:
 * `render()` draws it again and returns the RGBA pixels.
 */
export function linearHardwareShot(renderer: THREE.WebGLRenderer, fixtures: Fixtures, pose: GlowPose, near: number, width: number, height: number, exposure: number, up: Vec3 = [0, 1, 0]) {
  const display: SharedDisplayUniforms = { uExposure: { value: exposure }, uAdapt: { value: new THREE.Matrix3() }, uMode: { value: 0 }, uLevels: { value: [] }, uLevelCount: { value: 0 } };
  const hardware = createRoomHardware(display, { linear: true });
  hardware.setFixtures(fixtures);
  const scene = new THREE.Scene();
  scene.add(hardware.group);
  const camera = new THREE.PerspectiveCamera(pose.fov, 1, near, 10);
  camera.position.set(...pose.position);
  camera.up.set(...up);
  camera.lookAt(new THREE.Vector3(...pose.target));
  const target = new THREE.WebGLRenderTarget(width, height, { type: THREE.FloatType });
  const px = new Float32Array(width * height * 4);
  return {
    hardware,
    render(): Float32Array {
      renderer.setRenderTarget(target);
      renderer.render(scene, camera);
      renderer.readRenderTargetPixels(target, 0, 0, width, height, px);
      renderer.setRenderTarget(null);
      return px;
    },
    dispose() {
      target.dispose();
      hardware.dispose();
    },
  };
}

/** The centre pixel (8-bit RGB, after the display transform) of a room view that `setup` prepares, seen from `pose`. */
export function centreViewPixel(renderer: THREE.WebGLRenderer, pose: GlowPose, width: number, height: number, setup: (view: ReturnType<typeof createRoomView>) => void): number[] {
  const gl = renderer.getContext();
  const view = createRoomView(renderer);
  setup(view);
  view.setCamera(pose, width / height);
  view.render(renderer);
  const px = new Uint8Array(4);
  gl.readPixels(width / 2, height / 2, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
  view.dispose();
  return [px[0], px[1], px[2]];
}
