/**
 * Moving a module along its rail in the plan (docs/planner.md, "Moving a module"): at module
 * level a drag slides the module (pointer projected onto the rail, snapped by moveModule), live,
 * committed as one undoable action; a refused position keeps the module at the last accepted one
 * and shows the reason; arrow keys step it by the catalog's placement step (0.05 m).
 * Positions by hand, metres from the rail start; tolerance 1e-9 m.
 */
import { describe, expect, it } from 'vitest';
import { detailLevel } from '../../../src/ui/planner/detailLevel';
import { zoomAt } from '../../../src/ui/planner/viewTransform';
import { TestPlanner, twoRailSystem } from './testPlanner';

function zoomedIn(): TestPlanner {
  const t = new TestPlanner(twoRailSystem());
  t.controller.setView(zoomAt(t.view, t.screenOf({ x: 1.75, z: 1 }), 2.5), false);
  expect(detailLevel(t.view.scale)).toBe('module');
  return t;
}

const offsets = (t: TestPlanner) => t.config.systems[0].rails[0].modules.map((m) => [m.id, m.offset]);

describe('dragging a module along its rail', () => {
  it('follows the pointer along the rail only, snapped, and lands as one undoable moveModule', () => {
    const t = zoomedIn();
    const from = t.moduleCentre(1); // the linear, centre 0.45 m along
    const k = t.view.scale;
    t.controller.pointerDown(from);
    // 0.33 m along the rail and 0.2 m across it: requested start 0.15 + 0.33 = 0.48 → grid 0.5.
    t.controller.pointerMove({ sx: from.sx + 0.33 * k, sy: from.sy + 0.2 * k });
    expect(t.store.getState().selection).toEqual({ kind: 'module', id: 'm4' });
    const d = t.controller.drag;
    expect(d && 'moduleId' in d ? [d.moduleId, d.offset, d.invalid] : null).toEqual(['m4', expect.closeTo(0.5, 9), false]);
    // The preview system has the module there; the store does not yet.
    expect(d && 'moduleId' in d ? d.preview.rails[0].modules[1].offset : null).toBe(0.5);
    expect(offsets(t)).toEqual([
      ['m3', undefined],
      ['m4', undefined],
    ]);
    t.controller.pointerUp({ sx: from.sx + 0.33 * k, sy: from.sy + 0.2 * k });
    expect(t.controller.drag).toBeNull();
    expect(offsets(t)).toEqual([
      ['m3', 0],
      ['m4', 0.5],
    ]);
    expect(t.store.getState().history.past).toHaveLength(1);
    expect(t.problems()).toEqual([]);
    t.press('Mod+z');
    expect(offsets(t)).toEqual([
      ['m3', undefined],
      ['m4', undefined],
    ]);
  });

  it('a refused position shows the reason and keeps the module at the last accepted one', () => {
    const t = zoomedIn();
    const from = t.moduleCentre(1);
    const k = t.view.scale;
    t.controller.pointerDown(from);
    // 0.2 m right: start 0.35 (grid), accepted.
    t.controller.pointerMove({ sx: from.sx + 0.2 * k, sy: from.sy });
    // Back 0.3 m left of where it started: requested −0.15 + 0.15 … start 0.05 on the grid, over the spot.
    t.controller.pointerMove({ sx: from.sx - 0.1 * k, sy: from.sy });
    const d = t.controller.drag;
    expect(d && 'moduleId' in d ? [d.offset, d.invalid] : null).toEqual([expect.closeTo(0.35, 9), true]);
    expect(t.status).toBe('Linear diffuser at 0.05–0.65 m would overlap Spot m3');
    t.controller.pointerUp({ sx: from.sx - 0.1 * k, sy: from.sy });
    expect(offsets(t)).toEqual([
      ['m3', 0],
      ['m4', 0.35],
    ]);
    expect(t.store.getState().history.past).toHaveLength(1);
  });

  it('a drag that ends where it started changes nothing', () => {
    const t = zoomedIn();
    const from = t.moduleCentre(1);
    t.drag(from, { sx: from.sx, sy: from.sy + 0.3 * t.view.scale });
    expect(offsets(t)).toEqual([
      ['m3', undefined],
      ['m4', undefined],
    ]);
    expect(t.store.getState().history.past).toHaveLength(0);
  });

  it('zoomed out, a drag on a module still moves the whole system', () => {
    const t = new TestPlanner(twoRailSystem());
    expect(detailLevel(t.view.scale)).toBe('system');
    const from = t.moduleCentre(1);
    t.drag(from, { sx: from.sx + 0.5 * t.view.scale, sy: from.sy });
    expect(t.system().x).toBeCloseTo(1.5, 9);
    expect(offsets(t)).toEqual([
      ['m3', undefined],
      ['m4', undefined],
    ]);
  });
});

describe('arrow keys on a selected module', () => {
  it('step it along its rail by 0.05 m; arrows across the rail are refused with the reason', () => {
    const t = zoomedIn();
    t.tap(t.moduleCentre(1));
    expect(t.store.getState().selection).toEqual({ kind: 'module', id: 'm4' });
    expect(t.press('ArrowRight')).toBe(true);
    expect(offsets(t)).toEqual([
      ['m3', 0],
      ['m4', 0.2],
    ]);
    t.press('ArrowRight');
    expect(offsets(t)).toEqual([
      ['m3', 0],
      ['m4', 0.25],
    ]);
    t.press('ArrowLeft');
    expect(offsets(t)).toEqual([
      ['m3', 0],
      ['m4', 0.2],
    ]);
    t.press('ArrowUp');
    expect(t.status).toBe('a module slides along its rail: use the arrows along it');
    expect(offsets(t)).toEqual([
      ['m3', 0],
      ['m4', 0.2],
    ]);
    // Left twice more: 0.15 touches the spot, then 0.1 would overlap it.
    t.press('ArrowLeft');
    t.press('ArrowLeft');
    expect(offsets(t)).toEqual([
      ['m3', 0],
      ['m4', 0.15],
    ]);
    expect(t.status).toBe('Linear diffuser at 0.1–0.7 m would overlap Spot m3');
  });
});
