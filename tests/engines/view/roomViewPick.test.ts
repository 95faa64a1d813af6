/**
 * Picking in the 3D view (RoomView.pick, three's Raycaster on the objects' mesh and the module
 * boxes, the room's surfaces as occluders) and the selection highlight, on a headless-gl
 * three.js renderer: a tap on the table's top picks the table, on a module picks the module, on
 * the bare floor picks nothing; objects whose light has not arrived are not pickable.
 */
import createGL from 'gl';
import * as THREE from 'three';
import { afterAll, describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import { furnitureMesh } from '../../../src/core/model/objects/furniture/furnitureLibrary';
import { attemptAction } from '../../../src/core/model/actions/actionDefinitions';
import { createConfiguration } from '../../../src/core/model/configuration/configuration';
import type { BakeObject } from '../../../src/engines/bake/bakeScene';
import { prepareObjects } from '../../../src/engines/bake/objects/prepareObjects';
import { surfaceLayouts } from '../../../src/engines/bake/surfaceLayout';
import { emptyLitMaps } from '../../../src/engines/relight/relightMaps';
import { cameraPreset, type CameraPose } from '../../../src/engines/view/cameraPresets';
import { fixturesFromConfiguration } from '../../../src/engines/view/fixtures';
import { createRoomView } from '../../../src/engines/view/roomView';

const W = 200;
const H = 150;
const gl = createGL(W, H, { createWebGL2Context: true }) as unknown as WebGL2RenderingContext & { getExtension(n: 'STACKGL_destroy_context'): { destroy(): void } | null };
const canvas = { width: W, height: H, style: {}, addEventListener() {}, removeEventListener() {} } as unknown as HTMLCanvasElement;
Object.defineProperty(gl, 'canvas', { value: canvas, configurable: true });
const renderer = new THREE.WebGLRenderer({ canvas, context: gl, antialias: false });
afterAll(() => {
  renderer.dispose();
  gl.getExtension('STACKGL_destroy_context')?.destroy();
});

const room = { width: 5, height: 2.8, depth: 4, reflectance: { floor: 0.3, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } };
let config = createConfiguration({ width: 5, depth: 4, height: 2.8 });
const placed = attemptAction(config, 'placePreset', { presetId: 'single' }, defaultCatalog);
if (!placed.ok) throw new Error(placed.reason);
config = placed.next;
const fixtures = fixturesFromConfiguration(config, defaultCatalog);
const objects: BakeObject[] = [{ id: 'table', mesh: furnitureMesh('dining-table'), position: [2.5, 0, 2], yaw: 0, scale: 1 }];
const prepared = prepareObjects(objects, { texelSize: 0.1 });

function ndcOf(pose: CameraPose, point: [number, number, number]): [number, number] {
  const cam = new THREE.PerspectiveCamera(pose.fov, W / H, 0.05, 500);
  cam.position.set(...pose.position);
  cam.lookAt(new THREE.Vector3(...pose.target));
  cam.updateMatrixWorld();
  const p = new THREE.Vector3(...point).project(cam);
  return [p.x, p.y];
}

describe('RoomView.pick', () => {
  const view = createRoomView(renderer);
  view.setMaps(emptyLitMaps(surfaceLayouts(room, 0.1, 256)), { floor: [0.3, 0.3, 0.3], ceiling: [0.8, 0.8, 0.8], north: [0.5, 0.5, 0.5], south: [0.5, 0.5, 0.5], west: [0.5, 0.5, 0.5], east: [0.5, 0.5, 0.5] });
  view.setFixtures(fixtures);
  view.setObjects(prepared);
  const eye: CameraPose = { position: [2.5, 1.6, 3.9], target: [2.5, 1.2, 2], fov: 70 };
  const tableTop: [number, number, number] = [2.9, 0.751, 2.3];

  it('objects without light yet are not pickable', () => {
    view.setCamera(eye, W / H);
    expect(view.pick(...ndcOf(eye, tableTop))).toBeNull();
  });

  it('the table top, a module and the bare floor, from eye height and from the corner (through the culled walls)', () => {
    view.setObjectLight({ atlas: prepared.atlas, total: new Float32Array(prepared.atlas.width * prepared.atlas.height * 3) });
    view.setCamera(eye, W / H);
    expect(view.pick(...ndcOf(eye, tableTop))).toEqual({ kind: 'object', id: 'table' });
    const m = fixtures.modules[1];
    expect(view.pick(...ndcOf(eye, [m.centre[0], m.centre[1] + 0.015, m.centre[2]]))).toEqual({ kind: 'module', id: m.id });
    expect(view.pick(...ndcOf(eye, [0.6, 0, 1.0]))).toBeNull();
    const corner = cameraPreset('corner', room);
    view.setCamera(corner, W / H);
    expect(view.pick(...ndcOf(corner, tableTop))).toEqual({ kind: 'object', id: 'table' });
  });

  it("the selection: the selected object's edges (none for an unknown id), the selected module in the accent colour", () => {
    view.setSelectedObject('table');
    const edges = view.scene.getObjectByName('objects-selection') as THREE.LineSegments | undefined;
    expect(edges).toBeDefined();
    // A box-built table: every edge line lies on the table's placed bounds.
    const pos = edges!.geometry.getAttribute('position');
    const b = prepared.objects[0].bounds;
    for (let i = 0; i < pos.count; i++) {
      expect(pos.getX(i)).toBeGreaterThanOrEqual(b.min[0] - 1e-5);
      expect(pos.getX(i)).toBeLessThanOrEqual(b.max[0] + 1e-5);
      expect(pos.getY(i)).toBeLessThanOrEqual(b.max[1] + 1e-5);
    }
    expect(pos.count).toBeGreaterThan(24);
    view.setSelectedObject('nothing-like-this');
    expect(view.scene.getObjectByName('objects-selection')).toBeUndefined();
    // A selected module is drawn in the accent colour; the others keep theirs, also after new fixtures.
    const colour = (id: string) => ((view.scene.getObjectByName(`module:${id}`) as THREE.Mesh).material as THREE.ShaderMaterial).uniforms.uColor.value.toArray();
    const [first, second] = fixtures.modules;
    const plain = colour(first.id);
    view.setSelectedModule(first.id);
    view.setFixtures(fixtures);
    expect(colour(first.id)).toEqual([0.16, 0.56, 0.98].map((x) => expect.closeTo(x, 6)));
    expect(colour(second.id)).toEqual(plain);
    view.setSelectedModule(null);
    expect(colour(first.id)).toEqual(plain);
    view.render(renderer);
    view.dispose();
  });
});
