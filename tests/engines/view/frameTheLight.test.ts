import { join } from 'node:path';
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import type { BakeLuminaire, BakeScene } from '../../../src/engines/bake/bakeScene';
import { cameraPreset, parseCameraSpec, type CameraPose } from '../../../src/engines/view/cameraPresets';
import { clampInsideRoom, EYE_MARGIN, eyeAcrossTheRoom, eyeFov, frameTheLight } from '../../../src/engines/view/frameTheLight';
import { orbitLimits } from '../../../src/engines/view/orbitLimits';
import { loadRenderInput } from '../../../src/hosts/node/renderInput';
import { isotropic, spot, uniformRoom } from '../bake/bakeTestKit';

/**
 * The eye camera frames the light (issue 26): on rooms of every shape, the view it picks holds the
 * main pool and at least one luminaire, checked independently by projecting them with a three.js
 * camera of the returned pose; the camera stands inside the room by the margin; same input, same pose.
 */
const ROOT = join(__dirname, '../../..');
const ASPECT = 1.6;

/** Normalised device coordinates of a world point through a pose (three.js, independent of frameTheLight's own projection). */
function ndc(pose: CameraPose, p: Vec3, aspect = ASPECT): THREE.Vector3 {
  const camera = new THREE.PerspectiveCamera(pose.fov, aspect, 0.05, 500);
  camera.position.set(...pose.position);
  camera.lookAt(new THREE.Vector3(...pose.target));
  camera.updateMatrixWorld();
  return new THREE.Vector3(...p).project(camera);
}
const inView = (pose: CameraPose, p: Vec3, aspect = ASPECT) => {
  const v = ndc(pose, p, aspect);
  return Math.abs(v.x) <= 1 && Math.abs(v.y) <= 1 && v.z > -1 && v.z < 1;
};

const down = (position: Vec3, photometry = spot(3000, 20, 10, 2.5)): BakeLuminaire => ({ photometry, position, yaw: 0, pitch: 0, roll: 0 });

const rooms: { name: string; scene: BakeScene }[] = [
  { name: 'corridor 10 × 2.2 m, three downlights along it', scene: { room: uniformRoom(10, 2.8, 2.2, 0.5), luminaires: [down([2, 2.7, 1.1]), down([5, 2.7, 1.1]), down([8, 2.7, 1.1])] } },
  { name: 'square 4 × 4 m, one downlight in the north-east corner', scene: { room: uniformRoom(4, 2.6, 4, 0.5), luminaires: [down([3.4, 2.5, 0.6])] } },
  { name: 'tall hall 8 × 6 × 8 m, two pendants off centre', scene: { room: uniformRoom(8, 6, 8, 0.4), luminaires: [down([2, 4, 5], isotropic(800)), down([2.5, 4, 6], isotropic(800))] } },
  { name: 'low small room 2.5 × 2.1 × 2 m, one downlight', scene: { room: uniformRoom(2.5, 2.1, 2, 0.6), luminaires: [down([1.8, 2.0, 0.5])] } },
  { name: 'wide shallow shop 9 × 3 m, a spot at the west end', scene: { room: uniformRoom(9, 3, 3, 0.5), luminaires: [down([1, 2.9, 1.5])] } },
];

function expectFramesTheLight(scene: BakeScene, aspect = ASPECT) {
  const f = frameTheLight(scene, aspect);
  const { width: W, height: H, depth: D } = scene.room;
  const margin = Math.min(EYE_MARGIN, W / 4, D / 4);
  const [x, y, z] = f.pose.position;
  expect(Math.min(x, W - x, z, D - z)).toBeGreaterThanOrEqual(margin - 1e-9);
  expect(Math.min(y, H - y)).toBeGreaterThanOrEqual(Math.min(EYE_MARGIN, H / 2) - 1e-9);
  // The target is in the room too (the orbit turns about it).
  f.pose.target.forEach((v, a) => {
    expect(v).toBeGreaterThanOrEqual(0);
    expect(v).toBeLessThanOrEqual([W, H, D][a]);
  });
  expect(f.pool).not.toBeNull();
  expect(inView(f.pose, f.pool!, aspect)).toBe(true);
  const lamps = scene.luminaires.filter((l) => inView(f.pose, l.position, aspect));
  expect(lamps.length).toBeGreaterThanOrEqual(1);
  // Those it counts lie in the central 75 % of the frame.
  for (const i of f.luminairesInView) {
    const v = ndc(f.pose, scene.luminaires[i].position, aspect);
    expect(Math.max(Math.abs(v.x), Math.abs(v.y))).toBeLessThanOrEqual(0.75 + 1e-9);
  }
  expect(f.luminairesInView.length).toBeGreaterThanOrEqual(1);
  return f;
}

describe('frameTheLight: the eye camera looks at the light', () => {
  for (const r of rooms) {
    it(`${r.name}: main pool and ≥ 1 luminaire in view, camera ≥ the margin inside, deterministic`, () => {
      const f = expectFramesTheLight(r.scene);
      expect(frameTheLight(r.scene, ASPECT)).toEqual(f);
    });
  }

  it('a room too low to hold pool and lamp in 60°: a wider lens (75° or 90°), never narrower', () => {
    expect(frameTheLight(rooms[3].scene, ASPECT).pose.fov).toBeGreaterThan(60);
    expect(frameTheLight(rooms[0].scene, ASPECT).pose.fov).toBe(60);
  });

  it('the main pool is the brightest floor patch: under the corner downlight, not in the middle of the room', () => {
    const f = frameTheLight(rooms[1].scene, ASPECT);
    expect(Math.hypot(f.pool![0] - 3.4, f.pool![2] - 0.6)).toBeLessThan(0.5);
    expect(f.pool![1]).toBe(0);
  });

  it('corner-l (the demo): the old eye view from the south wall held one luminaire at its edge and not the pool; the framed one holds them and the pool', () => {
    const input = loadRenderInput(join(ROOT, 'tests/fixtures/configurations/corner-l.luxbox.json'));
    const old: CameraPose = { position: [2.5, 1.6, 3.75], target: [2.5, 0.96, 1.2], fov: 75 };
    expect(input.bakeScene.luminaires.filter((l) => inView(old, l.position)).length).toBeLessThanOrEqual(1);
    expect(inView(old, frameTheLight(input.bakeScene, ASPECT).pool!)).toBe(false);
    const f = expectFramesTheLight(input.bakeScene);
    expect(f.luminairesInView.length).toBeGreaterThanOrEqual(3);
    // One definition: the CLI's --camera eye is this pose.
    expect(parseCameraSpec('eye', input.scene.room, { scene: input.bakeScene, aspect: ASPECT })).toEqual(f.pose);
  });

  it('portrait screen: the field widens to keep 60° across, and the light is still in view', () => {
    expect(eyeFov(1.6)).toBe(60);
    expect(frameTheLight(rooms[0].scene, 0.6).pose.fov).toBeGreaterThanOrEqual(eyeFov(0.6));
    expect(eyeFov(0.5)).toBeCloseTo((2 * Math.atan(Math.tan(Math.PI / 6) / 0.5) * 180) / Math.PI, 9);
    expectFramesTheLight(rooms[0].scene, 0.6);
  });

  it('no light: the plain view across the room from the south wall, the same without a scene', () => {
    const scene: BakeScene = { room: uniformRoom(5, 2.8, 4, 0.5), luminaires: [down([2, 2.7, 2], isotropic(0))] };
    expect(frameTheLight(scene, ASPECT).pose).toEqual(eyeAcrossTheRoom(scene.room, ASPECT));
    expect(cameraPreset('eye', scene.room)).toEqual(eyeAcrossTheRoom(scene.room));
    expect(frameTheLight(scene, ASPECT).luminairesInView).toEqual([]);
  });
});

describe('orbit limits', () => {
  const room = { width: 5, height: 2.8, depth: 4 };
  it('the eye camera is clamped EYE_MARGIN inside the walls, floor and ceiling', () => {
    const { inside } = orbitLimits('eye', room);
    expect(inside!([-3, 9, 12])).toEqual([EYE_MARGIN, 2.8 - EYE_MARGIN, 4 - EYE_MARGIN]);
    expect(inside!([2, 1.5, 1])).toEqual([2, 1.5, 1]);
    expect(clampInsideRoom([7, -1, 2], room, 0.5)).toEqual([4.5, 0.5, 2]);
  });
  it('outside views stay above the floor plane and within reach; only the eye is clamped into the room', () => {
    for (const p of ['top', 'corner'] as const) {
      const l = orbitLimits(p, room);
      expect(l.maxPolarAngle).toBeLessThan(Math.PI / 2);
      expect(l.inside).toBeUndefined();
      const pose = cameraPreset(p, room);
      const distance = Math.hypot(...pose.position.map((v, i) => v - pose.target[i]));
      expect(distance).toBeLessThan(l.maxDistance);
    }
  });
});
