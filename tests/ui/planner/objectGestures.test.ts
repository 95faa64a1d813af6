import { describe, expect, it } from 'vitest';
import { checkAction } from '../../../src/core/model/actions/actionDefinitions';
import { createConfiguration, type Configuration, type RoomObject } from '../../../src/core/model/configuration/configuration';
import { furnitureMesh } from '../../../src/core/model/objects/furniture/furnitureLibrary';
import { objectMesh, placedBounds } from '../../../src/core/model/objects/objectGeometry';
import { createConfiguratorStore } from '../../../src/core/store/createConfiguratorStore';
import { addLibraryItem } from '../../../src/ui/planner/addFurniture';
import { planHitTest } from '../../../src/ui/planner/planHitTest';
import { KEY_MOVE_STEP, OBJECT_ROTATE_STEP, plannerCommand } from '../../../src/ui/planner/plannerCommands';
import { screenToWorld, zoomAt } from '../../../src/ui/planner/viewTransform';
import { visibleCentre } from '../../../src/ui/planner/visibleCentre';
import { TestPlanner, catalog } from './testPlanner';

/** A 5 × 4 × 2.8 m room with the given library items added through the model (floor items at the given points). */
function furnished(items: { item: string; x?: number; z?: number }[], base: Configuration = createConfiguration()): Configuration {
  const store = createConfiguratorStore({ catalog, initial: base });
  for (const { item, x, z } of items) {
    const r = store.getState().dispatch('addObject', { source: { kind: 'library', item }, ...(x !== undefined && z !== undefined ? { placement: { on: 'floor', x, z } } : {}) });
    if (!r.ok) throw new Error(r.reason);
  }
  return store.getState().config;
}

function object(t: TestPlanner, index = 0): RoomObject {
  return t.config.objects[index];
}

/** Where a floor object's origin (its footprint centre, for library items) is on screen. */
function objectCentre(t: TestPlanner, index = 0) {
  const p = object(t, index).placement;
  if (p.on !== 'floor') throw new Error('floor objects only');
  return t.screenOf({ x: p.x, z: p.z });
}

describe('PlannerController: objects', () => {
  it('a tap on a table selects it; a tap on the floor deselects', () => {
    const t = new TestPlanner(furnished([{ item: 'dining-table', x: 2.5, z: 2 }]));
    t.tap(objectCentre(t));
    expect(t.store.getState().selection).toEqual({ kind: 'object', id: object(t).id });
    t.tap(t.screenOf({ x: 0.3, z: 0.3 }));
    expect(t.store.getState().selection).toBeNull();
  });

  it('a drag moves the object by the pointer movement in metres, as one undoable moveObject snapped to the centimetre', () => {
    const t = new TestPlanner(furnished([{ item: 'dining-table', x: 2.5, z: 2 }]));
    t.controller.setView(zoomAt(t.view, { sx: 500, sy: 400 }, 1.7), false);
    const from = objectCentre(t);
    t.controller.pointerDown(from);
    t.controller.pointerMove({ sx: from.sx + t.view.scale * 0.3, sy: from.sy });
    // While held: selected, drawn offset by the pointer's movement, accepted.
    expect(t.store.getState().selection).toEqual({ kind: 'object', id: object(t).id });
    expect(t.controller.drag).toEqual({ objectId: object(t).id, delta: { x: 0.3, z: 0 }, invalid: false });
    // 0.5037 m right and 0.2012 m down: lands on whole centimetres.
    t.controller.pointerUp({ sx: from.sx + t.view.scale * 0.5037, sy: from.sy + t.view.scale * 0.2012 });
    expect(t.controller.drag).toBeNull();
    expect(object(t).placement).toEqual({ on: 'floor', x: 3, z: 2.2 });
    expect(t.store.getState().history.past).toHaveLength(1);
    t.press('Mod+z');
    expect(object(t).placement).toEqual({ on: 'floor', x: 2.5, z: 2 });
  });

  it('a drag past a wall stops at the wall (issue #27): shown at the wall while held, dropped there as one undoable move', () => {
    const t = new TestPlanner(furnished([{ item: 'sofa', x: 2.5, z: 2 }]));
    const from = objectCentre(t);
    // 2 m to the right would put the 2.1 m sofa's right end at 4.5 + 1.05 m, past the 5 m east wall: it stops with its end on the wall.
    const to = { sx: from.sx + t.view.scale * 2, sy: from.sy };
    t.controller.pointerDown(from);
    t.controller.pointerMove(to);
    const held = t.controller.drag as { delta: { x: number; z: number }; invalid: boolean };
    expect(held.invalid).toBe(false);
    expect(held.delta.x).toBeCloseTo(1.45, 9);
    t.controller.pointerUp(to);
    expect(t.controller.drag).toBeNull();
    expect(object(t).placement).toEqual({ on: 'floor', x: 3.95, z: 2 });
    expect(placedBounds(object(t), objectMesh(t.config, object(t).id), t.config.room).max[0]).toBeCloseTo(5, 6);
    expect(t.store.getState().canUndo).toBe(true);
    expect(t.problems()).toEqual([]);
  });

  it('a drag toward a corner slides along both walls; a move that cannot fit anywhere is still refused with the model reason', () => {
    const t = new TestPlanner(furnished([{ item: 'armchair', x: 2.5, z: 2 }]));
    const from = objectCentre(t);
    const to = { sx: from.sx - t.view.scale * 5, sy: from.sy - t.view.scale * 5 };
    t.controller.pointerDown(from);
    t.controller.pointerUp(to);
    // Armchair 85 × 85 cm: its centre 0.425 m off the west and north walls.
    expect(object(t).placement).toEqual({ on: 'floor', x: 0.43, z: 0.43 });
    expect(t.problems()).toEqual([]);
    const check = checkAction(t.config, 'moveObject', { objectId: object(t).id, placement: { on: 'floor', x: -3, z: 2 } }, catalog);
    expect(check).not.toBe(true);
  });

  it('keys: R and [ turn it 15° left, Shift+R and ] right, arrows move it 0.1 m (Shift 0.01 m), Delete removes it; Undo brings it back', () => {
    const t = new TestPlanner(furnished([{ item: 'armchair', x: 2.5, z: 2 }]));
    t.store.getState().select({ kind: 'object', id: object(t).id });
    expect(t.press('r')).toBe(true);
    expect(object(t).yaw).toBe(OBJECT_ROTATE_STEP);
    t.press('[');
    expect(object(t).yaw).toBe(2 * OBJECT_ROTATE_STEP);
    t.press(']');
    t.press('Shift+r');
    t.press('Shift+r');
    expect(object(t).yaw).toBe(360 - OBJECT_ROTATE_STEP);
    t.press('ArrowRight');
    t.press('ArrowUp');
    t.press('Shift+ArrowUp');
    expect(object(t).placement).toEqual({ on: 'floor', x: 2.5 + KEY_MOVE_STEP, z: 2 - KEY_MOVE_STEP - KEY_MOVE_STEP / 10 });
    const id = object(t).id;
    t.press('Delete');
    expect(t.config.objects).toHaveLength(0);
    expect(t.store.getState().selection).toBeNull();
    t.press('Mod+z');
    expect(t.config.objects.map((o) => o.id)).toEqual([id]);
    expect(t.problems()).toEqual([]);
  });

  it('turning or moving against a wall is refused with the model reason, by key and by button alike', () => {
    // The sofa's back against the north wall: turning it swings its corners through the wall.
    const t = new TestPlanner(furnished([{ item: 'sofa', x: 2.5, z: 0.45 }]));
    const id = object(t).id;
    t.store.getState().select({ kind: 'object', id });
    const turn = checkAction(t.config, 'rotateObject', { objectId: id, by: OBJECT_ROTATE_STEP }, catalog);
    expect(turn).not.toBe(true);
    const reason = turn === true ? '' : turn.reason;
    expect(plannerCommand('rotate').disabledReason(t.controller)).toBe(reason);
    const before = t.config;
    t.press('r');
    expect(t.status).toBe(reason);
    t.press('ArrowUp');
    expect(t.config).toBe(before);
    expect(t.status).toMatch(/wall|room|outside/i);
  });

  it('a picture is added to the nearest wall and slides along it: drags and arrows across the wall do not take it off', () => {
    const t = new TestPlanner(createConfiguration());
    // Dropped near the east wall (x = 5 m), 1.2 m from the north end.
    expect(addLibraryItem(t.controller, 'picture', t.screenOf({ x: 4.7, z: 1.2 }))).toBeNull();
    const pic = object(t);
    expect(t.store.getState().selection).toEqual({ kind: 'object', id: pic.id });
    expect(pic.placement).toEqual({ on: 'wall', wall: 'east', u: 1.2, y: 1.55 });
    // Drag it 1 m left and 0.5 m down: only the 0.5 m along the east wall (z) is followed.
    const at = t.screenOf({ x: 5 - 0.01, z: 1.2 });
    t.controller.pointerDown(at);
    t.controller.pointerMove({ sx: at.sx - t.view.scale, sy: at.sy + t.view.scale * 0.5 });
    expect(t.controller.drag).toEqual({ objectId: pic.id, delta: { x: -0, z: 0.5 }, invalid: false });
    t.controller.pointerUp({ sx: at.sx - t.view.scale, sy: at.sy + t.view.scale * 0.5 });
    expect(object(t).placement).toEqual({ on: 'wall', wall: 'east', u: 1.7, y: 1.55 });
    const before = t.config;
    t.press('ArrowLeft');
    expect(t.config).toBe(before);
    expect(t.status).toMatch(/along its wall/);
    t.press('ArrowDown');
    expect(object(t).placement).toEqual({ on: 'wall', wall: 'east', u: 1.8, y: 1.55 });
  });

  it('a library item tapped in the panel lands at the middle of the visible plan (inside the room) and is selected', () => {
    const t = new TestPlanner(createConfiguration());
    const c = visibleCentre(t.config.room, t.view, t.controller.viewport);
    expect(addLibraryItem(t.controller, 'coffee-table')).toBeNull();
    expect(object(t).placement).toEqual({ on: 'floor', x: c.x, z: c.z });
    // Panned so the middle of the plan is outside the room: the point is pulled back inside, the model fits the item.
    t.controller.setView({ ...t.view, offsetX: t.view.offsetX + 5000 }, false);
    expect(addLibraryItem(t.controller, 'chair')).toBeNull();
    const chair = object(t, 1);
    const b = placedBounds(chair, furnitureMesh('chair'), t.config.room);
    expect(b.min[0]).toBeGreaterThanOrEqual(-1e-6);
    expect(t.store.getState().selection).toEqual({ kind: 'object', id: chair.id });
    expect(addLibraryItem(t.controller, 'spaceship')).toMatch(/spaceship/);
  });

  it('systems lie above objects: a rail over a table takes the tap; the table is hit where no system is', () => {
    const demo = new TestPlanner();
    const r = demo.controller.hitTest(demo.railCentre());
    expect(r.systemId).toBeDefined();
    // A table centred under the middle of the demo's first rail.
    const centre = screenToWorld(demo.view, demo.railCentre());
    const t = new TestPlanner(furnished([{ item: 'dining-table', x: Math.round(centre.x * 100) / 100, z: Math.round(centre.z * 100) / 100 }], demo.config));
    expect(t.controller.hitTest(t.railCentre()).systemId).toBe(r.systemId);
    t.tap(t.railCentre());
    expect(t.store.getState().selection).toEqual({ kind: 'system', id: r.systemId });
    // Somewhere on the table's top away from every rail's hit strip: the table.
    const p = object(t).placement;
    if (p.on !== 'floor') throw new Error('floor table expected');
    const free = [-0.85, 0.85].flatMap((dx) => [-0.4, 0.4].map((dz) => t.screenOf({ x: p.x + dx, z: p.z + dz }))).find((at) => !t.controller.hitTest(at).systemId);
    expect(free).toBeDefined();
    expect(planHitTest(t.config, catalog, t.view, free!)).toEqual({ objectId: object(t).id });
  });
});
