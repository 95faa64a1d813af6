/**
 * A room of any shape in the 3D view (issue 29): eye cameras stand inside the outline clear of every
 * wall (never inside a wall of an L), the orbit clamp keeps them there, and `luxbox render`'s path
 * (renderViews on headless-gl, the same RoomView as the browser) draws the room's own surfaces lit
 * by the atlas — the floor behind the L's inner corner dark, beside it bright — while the box's
 * surfaces stay hidden.
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import type { LightingScene, Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import { ceilingHeightAt } from '../../../src/core/room/ceilingHeightAt';
import type { RoomInput } from '../../../src/core/room/roomInput';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import createGL from 'gl';
import { prepareObjects } from '../../../src/engines/bake/objects/prepareObjects';
import { encloseShapedRoom } from '../../../src/engines/bake/shapedRoom/encloseShapedRoom';
import { createRelightEngine, VIEWER_BAKE_SETTINGS } from '../../../src/engines/relight/createRelightEngine';
import { floorStats, workPlaneStats } from '../../../src/engines/view/lightStats';
import { cameraPreset, type CameraPose } from '../../../src/engines/view/cameraPresets';
import { fixturesFromScene } from '../../../src/engines/view/fixtures';
import { EYE_MARGIN } from '../../../src/engines/view/frameTheLight';
import { orbitLimits } from '../../../src/engines/view/orbitLimits';
import { clearOfWalls } from '../../../src/engines/view/shapedRoomCamera';
import { createRenderSession } from '../../../src/hosts/node/renderImage';
import { isotropic } from '../../reference/photometryFixtures';
import { shapedBakeRoom } from '../bake/shapedRoomKit';

const L_OUTLINE: [number, number][] = [
  [0, 0],
  [6, 0],
  [6, 3],
  [3.5, 3],
  [3.5, 5],
  [0, 5],
];
const finishes = { floor: 0.4, ceiling: 0.8, walls: 0.6 };

function scene(input: RoomInput, lamps: Vec3[]): BakeScene {
  return { room: shapedBakeRoom(input), luminaires: lamps.map((position) => ({ photometry: isotropic(1500), position, yaw: 0, pitch: 0, roll: 0, dimming: 1, color: [1, 1, 1] })) };
}

describe('shaped rooms in the 3D view', () => {
  it('the eye camera stands inside the room, clear of every wall, for L rooms turned four ways and an attic', () => {
    const turns: [number, number][][] = [L_OUTLINE, L_OUTLINE.map(([x, z]) => [6 - x, z]), L_OUTLINE.map(([x, z]) => [x, 5 - z]), L_OUTLINE.map(([x, z]) => [z + 1, x - 2])];
    const rooms: RoomInput[] = [
      ...turns.map((outline) => ({ outline, height: 2.6, reflectance: finishes })),
      {
        outline: [
          [0, 0],
          [5, 0],
          [5, 4],
          [0, 4],
        ],
        height: 2.5,
        slopes: [{ wall: 0, kneeHeight: 0.8, pitch: 40 }],
        reflectance: finishes,
      },
    ];
    for (const input of rooms) {
      const xs = input.outline.map((c) => c[0]);
      const zs = input.outline.map((c) => c[1]);
      // A lamp in the room: the middle of the first wall, 1 m in.
      const s = scene(input, [[(xs[0] + xs[1]) / 2, 2, (zs[0] + zs[1]) / 2 + 1]]);
      const shape = s.room.shape!;
      for (const pose of [cameraPreset('eye', s.room, { scene: s, aspect: 1.6 }), cameraPreset('eye', s.room)]) {
        const [x, y, z] = pose.position;
        expect(clearOfWalls(shape, [x, z], EYE_MARGIN - 1e-6)).toBe(true);
        expect(y).toBeLessThan(ceilingHeightAt(shape, x, z) - 0.1);
        expect(y).toBeGreaterThan(0.1);
      }
      // The orbit may not take the eye into the notch of an L or into a wall.
      const inside = orbitLimits('eye', s.room).inside!;
      for (let k = 0; k < 200; k++) {
        const p: Vec3 = [Math.min(...xs) - 1 + ((k * 0.37) % (Math.max(...xs) - Math.min(...xs) + 2)), (k * 0.13) % 3, Math.min(...zs) - 1 + ((k * 0.61) % (Math.max(...zs) - Math.min(...zs) + 2))];
        const q = inside(p);
        expect(clearOfWalls(shape, [q[0], q[2]], EYE_MARGIN - 1e-6)).toBe(true);
        expect(q[1]).toBeLessThanOrEqual(ceilingHeightAt(shape, q[0], q[2]) + 1e-9);
      }
    }
  });

  it('renders the room mesh lit by the atlas: the shadow of the L’s inner corner on the floor, the box hidden', () => {
    const input: RoomInput = { outline: L_OUTLINE, height: 2.6, reflectance: finishes };
    const bakeScene = scene(input, [[5, 2, 1]]);
    const lightingScene: LightingScene = { version: 1, room: bakeScene.room, luminaires: [] };
    const WIDTH = 240;
    const HEIGHT = 200;
    // Straight down from above the ceiling (its back faces are not drawn): floor points in plan.
    const camera: CameraPose = { position: [3, 12, 2.5 + 1e-3], target: [3, 0, 2.5], fov: 40 };
    const session = createRenderSession(WIDTH, HEIGHT);
    let pixels: Uint8Array;
    let png: Buffer;
    try {
      [{ pixels, png }] = session.renderViews(
        { scene: lightingScene, bakeScene, fixtures: fixturesFromScene(lightingScene), kind: 'lighting-scene' },
        { width: WIDTH, height: HEIGHT, camera, exposureEv: 0, mode: 'light', glare: false, settings: { ...VIEWER_BAKE_SETTINGS, texelSize: 0.1, samples: 16, bounces: 2 } },
        [camera],
      );
    } finally {
      session.destroy();
    }
    mkdirSync('test-results/shaped-room', { recursive: true });
    writeFileSync('test-results/shaped-room/l-from-above.png', png);
    const cam = new THREE.PerspectiveCamera(camera.fov, WIDTH / HEIGHT, 0.05, 500);
    cam.position.set(...camera.position);
    cam.up.set(0, 1, 0);
    cam.lookAt(new THREE.Vector3(...camera.target));
    cam.updateMatrixWorld();
    const grey = (p: Vec3) => {
      const v = new THREE.Vector3(...p).project(cam);
      const [x, y] = [Math.round(((v.x + 1) / 2) * WIDTH), Math.round(((1 - v.y) / 2) * HEIGHT)];
      const o = 4 * (y * WIDTH + x);
      return [pixels[o], pixels[o + 1], pixels[o + 2]];
    };
    const Y = (c: number[]) => 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    // Behind the corner from the lamp (3, 4.6) and beside it in the lit arm (1, 4.6); the notch (5, 4.5) is outside the room: background.
    const shadow = Y(grey([3.2, 0, 4.7]));
    const lit = Y(grey([1, 0, 4.6]));
    const notch = grey([5, 0, 4.5]);
    console.info(`L from above: floor behind the corner ${shadow.toFixed(0)}, beside it ${lit.toFixed(0)}, notch [${notch.join(', ')}]`);
    expect(lit).toBeGreaterThan(1.5 * shadow + 10);
    // The view's background (0x1d2126): no box floor drawn in the notch.
    expect(notch).toEqual([0x1d, 0x21, 0x26]);
  }, 300_000);

  it('work-plane statistics: the notch left out, the plane behind the inner corner in shadow, the floor numbers from the atlas', () => {
    const input: RoomInput = { outline: L_OUTLINE, height: 2.6, reflectance: finishes };
    const s = scene(input, [[5, 2, 1]]);
    const gl = createGL(8, 8, { createWebGL2Context: true }) as unknown as WebGL2RenderingContext;
    const settings = { ...VIEWER_BAKE_SETTINGS, texelSize: 0.1, samples: 16, bounces: 2 };
    const engine = createRelightEngine(gl, settings);
    try {
      engine.setScene(s);
      engine.finish();
      const lit = engine.maps();
      const enclosed = encloseShapedRoom(s);
      const prepared = prepareObjects(enclosed.objects!, { texelSize: engine.settings.texelSize, maxAtlasSize: engine.settings.maxTextureSize });
      const plane = workPlaneStats(s, lit, 0.8, 0.25, settings, prepared);
      const at = (x: number, z: number) => plane.values[Math.floor(z / 0.25) * plane.nx + Math.floor(x / 0.25)];
      const coveredAt = (x: number, z: number) => plane.covered[Math.floor(z / 0.25) * plane.nx + Math.floor(x / 0.25)];
      // 24 × 20 cells, the notch's 10 × 8 left out.
      expect([plane.nx, plane.nz]).toEqual([24, 20]);
      expect(plane.points).toBe(24 * 20 - 10 * 8);
      expect(coveredAt(5, 4.5)).toBe(1);
      expect(coveredAt(1, 4.5)).toBe(0);
      // Behind the corner (no direct light: only what the room reflects) and beside it.
      console.info(`work plane: behind the corner ${at(3.2, 4.7).toFixed(1)} lx, beside it ${at(1, 4.6).toFixed(1)} lx, mean ${plane.avg.toFixed(1)} lx`);
      expect(at(1, 4.6)).toBeGreaterThan(2 * at(3.2, 4.7));
      expect(at(3.2, 4.7)).toBeGreaterThan(0);
      const floor = floorStats(lit, prepared);
      expect(floor.points).toBeGreaterThan(2000);
      expect(floor.avg).toBeGreaterThan(0);
    } finally {
      engine.dispose();
    }
  }, 300_000);
});
