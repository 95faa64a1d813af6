/**
 * Three's programs compiled before a frame draws them, without blocking (createCompileGate.ts,
 * roomViewRender.ts): a new materials key holds the frame and starts one compileAsync; the frame is
 * drawn only once it has resolved; a render after it compiles nothing more (the key sees what the
 * render draws); new materials or a material's needsUpdate start another. On a real three.js
 * renderer over headless-gl, and with a controlled compile for the order of events.
 */
import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import { attemptAction } from '../../../src/core/model/actions/actionDefinitions';
import { createConfiguration } from '../../../src/core/model/configuration/configuration';
import { furnitureMesh } from '../../../src/core/model/objects/furniture/furnitureLibrary';
import { prepareObjects } from '../../../src/engines/bake/objects/prepareObjects';
import { surfaceLayouts } from '../../../src/engines/bake/surfaceLayout';
import { emptyLitMaps } from '../../../src/engines/relight/relightMaps';
import { createCompileGate } from '../../../src/engines/view/createCompileGate';
import { createFrameScheduler } from '../../../src/engines/view/createFrameScheduler';
import { fixturesFromConfiguration } from '../../../src/engines/view/fixtures';
import { createRoomView } from '../../../src/engines/view/roomView';
import { headlessRenderer } from './headlessRenderer';

const W = 64;
const H = 48;
const renderer = headlessRenderer(W, H);
const room = { width: 5, height: 2.8, depth: 4, reflectance: { floor: 0.3, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } };
const grey = (x: number): [number, number, number] => [x, x, x];

/** A compile the test resolves by hand, counting its calls. */
function manualCompile() {
  const resolvers: (() => void)[] = [];
  return {
    calls: () => resolvers.length,
    compile: () => new Promise<void>((resolve) => resolvers.push(resolve)),
    resolve: (k: number) => resolvers[k](),
  };
}
const settled = () => new Promise<void>((resolve) => setTimeout(resolve, 0));

describe('createCompileGate with the frame scheduler', () => {
  it('the first frame is drawn only after the compile resolved; asking again meanwhile starts no second compile', async () => {
    const c = manualCompile();
    const queue: (() => void)[] = [];
    const drawn: number[] = [];
    const gate = createCompileGate({ key: () => 'a', compile: c.compile, onReady: () => frames.request() });
    const frames = createFrameScheduler({
      draw: () => {
        drawn.push(gate.counters.finished);
        gate.drawn();
      },
      canDraw: () => gate.ready(),
      onFrame: () => {},
      schedule: (f) => queue.push(f),
    });
    const flush = () => queue.splice(0).forEach((f) => f());
    frames.request();
    flush();
    frames.request();
    flush();
    expect(drawn).toEqual([]);
    expect(c.calls()).toBe(1);
    expect(gate.counters).toMatchObject({ started: 1, finished: 0, heldFrames: 2, finishedAtFirstFrame: null });
    c.resolve(0);
    await settled();
    // onReady asked for the frame: it draws now, after the compile.
    flush();
    expect(drawn).toEqual([1]);
    expect(gate.counters).toMatchObject({ started: 1, finished: 1, heldFrames: 2, finishedAtFirstFrame: 1 });
    frames.request();
    flush();
    expect(drawn).toEqual([1, 1]);
    expect(c.calls()).toBe(1);
  });

  it('a compile overtaken by a newer key does not open the gate; the newer one does; nothing after dispose', async () => {
    const c = manualCompile();
    let key = 'a';
    let ready = 0;
    const gate = createCompileGate({ key: () => key, compile: c.compile, onReady: () => ready++ });
    expect(gate.ready()).toBe(false);
    key = 'b';
    expect(gate.ready()).toBe(false);
    expect(c.calls()).toBe(2);
    c.resolve(0);
    await settled();
    expect(ready).toBe(0);
    expect(gate.ready()).toBe(false);
    expect(c.calls()).toBe(2);
    c.resolve(1);
    await settled();
    expect(ready).toBe(1);
    expect(gate.ready()).toBe(true);
    key = 'c';
    expect(gate.ready()).toBe(false);
    gate.dispose();
    c.resolve(2);
    await settled();
    expect(ready).toBe(1);
  });
});

describe('RoomView.materialsKey and compileAsync on three.js (headless-gl)', () => {
  const view = createRoomView(renderer);
  view.setMaps(emptyLitMaps(surfaceLayouts(room, 0.1, 256)), { floor: grey(0.3), ceiling: grey(0.8), north: grey(0.5), south: grey(0.5), west: grey(0.5), east: grey(0.5) });
  view.setCamera({ position: [2.5, 1.6, 3.9], target: [2.5, 1.2, 2], fov: 70 }, W / H);
  const programs = () => renderer.info.programs?.length ?? 0;

  it('after the compile a render links no program; new materials change the key, and their compile again leaves the render nothing to link', async () => {
    let readyCalls = 0;
    const gate = createCompileGate({ key: view.materialsKey, compile: () => view.compileAsync(renderer), onReady: () => readyCalls++ });
    const before = programs();
    expect(gate.ready()).toBe(false);
    await new Promise<void>((resolve) => {
      const poll = () => (readyCalls > 0 ? resolve() : setTimeout(poll, 5));
      poll();
    });
    expect(gate.ready()).toBe(true);
    const compiled = programs();
    expect(compiled).toBeGreaterThan(before);
    view.render(renderer);
    expect(programs()).toBe(compiled);

    // A luminaire and a table: new materials, a new key.
    let config = createConfiguration({ width: 5, depth: 4, height: 2.8 });
    const placed = attemptAction(config, 'placePreset', { presetId: 'single' }, defaultCatalog);
    if (!placed.ok) throw new Error(placed.reason);
    config = placed.next;
    view.setFixtures(fixturesFromConfiguration(config, defaultCatalog));
    view.setObjects(prepareObjects([{ id: 'table', mesh: furnitureMesh('dining-table'), position: [2.5, 0, 2], yaw: 0, scale: 1 }], { texelSize: 0.1 }));
    expect(gate.ready()).toBe(false);
    expect(gate.counters.started).toBe(2);
    await new Promise<void>((resolve) => {
      const poll = () => (readyCalls > 1 ? resolve() : setTimeout(poll, 5));
      poll();
    });
    expect(gate.ready()).toBe(true);
    const withHardware = programs();
    view.render(renderer);
    expect(programs()).toBe(withHardware);
  });

  it('a material marked needsUpdate changes the key (three will link it anew)', () => {
    const key = view.materialsKey();
    let mesh: { material?: { needsUpdate: boolean } } | null = null;
    view.scene.traverse((o) => {
      if (!mesh && (o as { material?: unknown }).material) mesh = o as never;
    });
    mesh!.material!.needsUpdate = true;
    expect(view.materialsKey()).not.toBe(key);
  });
});
