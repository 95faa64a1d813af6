import { describe, expect, it } from 'vitest';
import { systemBounds } from '../../../src/core/model/rails/geometry';
import { MODULE_LEVEL_SCALE } from '../../../src/ui/planner/detailLevel';
import { ZOOM_STEP } from '../../../src/ui/planner/plannerCommands';
import { screenToWorld, wheelZoomFactor, zoomAt } from '../../../src/ui/planner/viewTransform';
import { TestPlanner, catalog } from './testPlanner';

/** Zooms the controller's view by `factor` about the middle of the plan. */
function zoomTo(t: TestPlanner, factor: number) {
  t.controller.setView(zoomAt(t.view, { sx: 500, sy: 400 }, factor), false);
}

describe('PlannerController: dragging systems', () => {
  it('a drag of 1 m on screen at zoom 2 moves the system 1 m in world units, as one undoable step', () => {
    const t = new TestPlanner();
    t.alignToCentimetres();
    zoomTo(t, 2);
    const before = t.system();
    const b = systemBounds(before, catalog);
    // Towards the side with room to spare, so the move is accepted.
    const dir = b.maxX + 1 <= t.config.room.width ? 1 : -1;
    const from = t.railCentre();
    t.controller.pointerDown(from);
    t.controller.pointerMove({ sx: from.sx + dir * t.view.scale * 0.5, sy: from.sy });
    // While held: the system is selected and drawn offset, accepted.
    expect(t.store.getState().selection).toEqual({ kind: 'system', id: before.id });
    expect(t.controller.drag).toEqual({ systemId: before.id, delta: { x: dir * 0.5, z: 0 }, invalid: false });
    t.controller.pointerUp({ sx: from.sx + dir * t.view.scale, sy: from.sy });
    expect(t.controller.drag).toBeNull();
    expect(t.system().x).toBeCloseTo(before.x + dir, 9);
    expect(t.system().z).toBe(before.z);
    expect(t.store.getState().history.past).toHaveLength(2);
  });

  it('positions snap to whole centimetres', () => {
    const t = new TestPlanner().alignToCentimetres();
    const from = t.railCentre();
    const s0 = t.system();
    const dir = systemBounds(s0, catalog).maxX + 1 <= t.config.room.width ? 1 : -1;
    t.drag(from, { sx: from.sx + dir * t.view.scale * 0.123456, sy: from.sy + t.view.scale * 0.0071 });
    expect(t.system().x).toBeCloseTo(s0.x + dir * 0.12, 9);
    expect(t.system().z).toBeCloseTo(s0.z + 0.01, 9);
  });

  it('a drag that would leave the room is refused: faded while held, the reason shown, the configuration unchanged and valid', () => {
    const t = new TestPlanner();
    const before = t.config;
    const b = systemBounds(t.system(), catalog);
    const from = t.railCentre();
    const out = { sx: from.sx - t.view.scale * (b.maxX + 1), sy: from.sy };
    t.controller.pointerDown(from);
    t.controller.pointerMove({ sx: from.sx - 20, sy: from.sy });
    t.controller.pointerMove(out);
    expect(t.controller.drag?.invalid).toBe(true);
    t.controller.pointerUp(out);
    expect(t.controller.drag).toBeNull();
    expect(t.config).toBe(before);
    expect(t.problems()).toEqual([]);
    expect(t.status).toMatch(/room|wall|outside/i);
    expect(t.store.getState().canUndo).toBe(false);
  });

  it('undo after a drag restores the exact configuration; redo repeats it', () => {
    const t = new TestPlanner();
    const before = t.config;
    const from = t.railCentre();
    t.drag(from, { sx: from.sx + 17, sy: from.sy + 11 });
    const after = t.config;
    expect(after).not.toEqual(before);
    expect(t.press('Mod+z')).toBe(true);
    expect(t.config).toEqual(before);
    expect(JSON.stringify(t.config)).toBe(JSON.stringify(before));
    t.press('Mod+Shift+z');
    expect(t.config).toEqual(after);
  });

  it('a pointer cancelled mid-drag (a second finger) moves nothing and clears the preview', () => {
    const t = new TestPlanner();
    const before = t.config;
    const from = t.railCentre();
    t.controller.pointerDown(from);
    t.controller.pointerMove({ sx: from.sx + 30, sy: from.sy });
    expect(t.controller.drag).not.toBeNull();
    t.controller.pinchStart(from, 100);
    expect(t.controller.drag).toBeNull();
    t.controller.pointerUp({ sx: from.sx + 60, sy: from.sy });
    expect(t.config).toBe(before);
  });
});

describe('PlannerController: taps select by zoom level', () => {
  it('a tap on a rail selects its system when zoomed out; zoomed in, the rail or the module; the floor deselects', () => {
    const t = new TestPlanner();
    const s = t.system();
    t.tap(t.railCentre());
    expect(t.store.getState().selection).toEqual({ kind: 'system', id: s.id });
    t.tap({ sx: 2, sy: 2 });
    expect(t.store.getState().selection).toBeNull();

    zoomTo(t, (MODULE_LEVEL_SCALE * 1.2) / t.view.scale);
    const m = s.rails[0].modules[0];
    t.tap(t.moduleCentre(0));
    expect(t.store.getState().selection).toEqual({ kind: 'module', id: m.id });
    // The rail's start, before its first module: the rail itself.
    const r = t.screenOf({ x: s.x, z: s.z });
    const along = t.railCentre();
    const len = Math.hypot(along.sx - r.sx, along.sy - r.sy);
    t.tap({ sx: r.sx + ((along.sx - r.sx) / len) * 4, sy: r.sy + ((along.sy - r.sy) / len) * 4 });
    expect(t.store.getState().selection).toEqual({ kind: 'rail', id: s.rails[0].id });
  });

  it('presses that move less than the threshold are taps, not drags', () => {
    const t = new TestPlanner();
    const before = t.config;
    const view = t.view;
    const from = t.railCentre();
    t.drag(from, { sx: from.sx + 2, sy: from.sy - 2 });
    expect(t.config).toBe(before);
    expect(t.store.getState().selection?.kind).toBe('system');
    t.drag({ sx: 5, sy: 5 }, { sx: 7, sy: 5 });
    expect(t.view).toEqual(view);
  });
});

describe('PlannerController: panning and zooming', () => {
  it('dragging the floor pans by the pointer movement after the press became a drag, and changes nothing else', () => {
    const t = new TestPlanner();
    const before = t.config;
    const v0 = t.view;
    const p = { sx: 10, sy: 10 };
    expect(t.controller.hitTest(p)).toEqual({});
    t.controller.pointerDown(p);
    t.controller.pointerMove({ sx: 20, sy: 10 }); // becomes a pan here
    t.controller.pointerMove({ sx: 60, sy: 40 });
    t.controller.pointerUp({ sx: 60, sy: 40 });
    expect(t.view).toEqual({ scale: v0.scale, offsetX: v0.offsetX + 40, offsetY: v0.offsetY + 30 });
    expect(t.config).toBe(before);
  });

  it('wheel zoom keeps the world point under the pointer fixed, and the same turn back returns', () => {
    const t = new TestPlanner();
    const at = { sx: 321, sy: 234 };
    const world = screenToWorld(t.view, at);
    const s0 = t.view.scale;
    t.controller.wheel(at, -240);
    expect(t.view.scale).toBeCloseTo(s0 * wheelZoomFactor(-240), 9);
    const still = screenToWorld(t.view, at);
    expect(still.x).toBeCloseTo(world.x, 9);
    expect(still.z).toBeCloseTo(world.z, 9);
    t.controller.wheel(at, 240);
    expect(t.view.scale).toBeCloseTo(s0, 9);
  });

  it('a pinch zooms by the ratio of finger distances and carries the world point under the fingers with them', () => {
    const t = new TestPlanner();
    const c0 = { sx: 400, sy: 300 };
    const world = screenToWorld(t.view, c0);
    const s0 = t.view.scale;
    t.controller.pinchStart(c0, 100);
    t.controller.pinchMove({ sx: 430, sy: 280 }, 300);
    t.controller.pinchEnd();
    expect(t.view.scale / s0).toBeCloseTo(3, 9);
    const under = screenToWorld(t.view, { sx: 430, sy: 280 });
    expect(under.x).toBeCloseTo(world.x, 9);
    expect(under.z).toBeCloseTo(world.z, 9);
  });

  it('zoom buttons and + / − zoom by the one zoom step, about the selected system when it is on screen', () => {
    const t = new TestPlanner();
    const s0 = t.view.scale;
    t.controller.command('zoom-in');
    expect(t.view.scale).toBeCloseTo(s0 * ZOOM_STEP, 9);
    t.press('-');
    expect(t.view.scale).toBeCloseTo(s0, 9);
    t.press('Shift++');
    t.press('=');
    expect(t.view.scale).toBeCloseTo(s0 * ZOOM_STEP * ZOOM_STEP, 9);
    t.controller.command('zoom-fit');
    expect(t.view.scale).toBeCloseTo(s0, 9);

    // With a system selected, its centre stays where it is on screen.
    t.tap(t.railCentre());
    const b = systemBounds(t.system(), catalog);
    const centre = { x: (b.minX + b.maxX) / 2, z: (b.minZ + b.maxZ) / 2 };
    const onScreen = t.screenOf(centre);
    t.press('+');
    expect(t.screenOf(centre).sx).toBeCloseTo(onScreen.sx, 6);
    expect(t.screenOf(centre).sy).toBeCloseTo(onScreen.sy, 6);
  });

  it('the room is fitted again when the viewport or the room changes, and not otherwise', () => {
    const t = new TestPlanner();
    t.controller.wheel({ sx: 100, sy: 100 }, -100);
    const zoomed = t.view;
    t.controller.setViewport({ width: 1000, height: 800 });
    expect(t.view).toBe(zoomed);
    t.controller.setViewport({ width: 375, height: 500 });
    expect(t.view).not.toBe(zoomed);
    const phone = t.view;
    t.store.getState().dispatch('setRoom', { width: 8, depth: 6, height: 3 });
    t.controller.setViewport({ width: 375, height: 500 });
    expect(t.view.scale).toBeLessThan(phone.scale);
  });
});

describe('PlannerController: fit insets (the room-shape mode)', () => {
  it('fits the room between the covered top and bottom of the plan, and back to the whole plan at 0, 0', () => {
    const t = new TestPlanner();
    const whole = t.view;
    const { depth } = t.config.room;
    t.controller.setFitInsets(120, 280);
    const top = t.view.offsetY;
    const bottom = t.view.offsetY + depth * t.view.scale;
    // Inside the 400 px left between them, with the fit's own margin (16–48 px) on the limiting side.
    expect(top).toBeGreaterThanOrEqual(120);
    expect(bottom).toBeLessThanOrEqual(800 - 280);
    expect(Math.min(top - 120, 800 - 280 - bottom)).toBeGreaterThanOrEqual(16);
    expect(t.view.scale).toBeLessThan(whole.scale);
    t.controller.setFitInsets(0, 0);
    expect(t.view).toEqual(whole);
  });
});
