/**
 * Dragging a fixing point along its chain in the plan (docs/planner.md, "Connector angles and
 * fixing points"): at system level, on a selected system, a press on a movable dot slides it
 * (pointer projected onto the rails, snapped to 1 cm by moveFixingPoint), live, committed as one
 * undoable action; a refused position keeps the last accepted one and shows the reason. On a
 * system that is not selected the same press drags the system, as before.
 * Positions by hand, metres along the chain; tolerance 1e-9 m.
 */
import { describe, expect, it } from 'vitest';
import type { Configuration } from '../../../src/core/model/configuration/configuration';
import { systemAtOneOne } from '../../core/model/helpers';
import { suspensionCoordinates } from '../../../src/core/model/rails/suspensionPoints';
import { detailLevel } from '../../../src/ui/planner/detailLevel';
import { TestPlanner, catalog } from './testPlanner';

/** System s1 at (1, 1) heading +x, one 2.5 m rail: suspensions at 0.5 and 2.0 m (inset min(0.5, 2.5/4), no point between: 1.5 ≤ 2). */
function oneRail(): Configuration {
  return systemAtOneOne([{ id: 'r2', length: 2.5, distribution: 'start', modules: [] }], [], 'f3', 4);
}

const points = (t: TestPlanner) => suspensionCoordinates(t.system(), catalog).map((p) => p.s);

describe('dragging a fixing point', () => {
  it('slides along the chain on a selected system, snapped, as one undoable moveFixingPoint', () => {
    const t = new TestPlanner(oneRail());
    expect(detailLevel(t.view.scale)).not.toBe('module');
    t.store.getState().select({ kind: 'system', id: 's1' });
    const from = t.screenOf({ x: 1.5, z: 1 });
    const k = t.view.scale;
    t.controller.pointerDown(from);
    // 0.197 m back along the rail and 0.1 m across: requested 0.303 → 0.3.
    t.controller.pointerMove({ sx: from.sx - 0.197 * k, sy: from.sy + 0.1 * k });
    const d = t.controller.drag;
    expect(d && 'fixingIndex' in d ? [d.fixingIndex, d.s, d.invalid] : null).toEqual([0, expect.closeTo(0.3, 9), false]);
    expect(t.system().fixings).toBeUndefined();
    t.controller.pointerUp({ sx: from.sx - 0.197 * k, sy: from.sy + 0.1 * k });
    expect(t.controller.drag).toBeNull();
    expect(t.system().fixings).toEqual([0.3, 2]);
    expect([t.system().x, t.system().z]).toEqual([1, 1]);
    t.store.getState().undo();
    expect(t.system().fixings).toBeUndefined();
    expect(points(t)).toEqual([0.5, 2]);
  });

  it('a refused position keeps the last accepted one and says why', () => {
    const t = new TestPlanner(oneRail());
    t.store.getState().select({ kind: 'system', id: 's1' });
    const from = t.screenOf({ x: 1.5, z: 1 });
    const k = t.view.scale;
    t.controller.pointerDown(from);
    t.controller.pointerMove({ sx: from.sx - 0.1 * k, sy: from.sy });
    // 0.6 m: the chain start would overhang it by more than 0.5 m.
    t.controller.pointerMove({ sx: from.sx + 0.1 * k, sy: from.sy });
    const d = t.controller.drag;
    expect(d && 'fixingIndex' in d ? [d.s, d.invalid] : null).toEqual([expect.closeTo(0.4, 9), true]);
    expect(t.status).toBe('cannot move the point to 0.6 m: the chain start would overhang its first suspension by 0.6 m (at most 0.5 m)');
    t.controller.pointerUp({ sx: from.sx + 0.1 * k, sy: from.sy });
    expect(t.system().fixings).toEqual([0.4, 2]);
  });

  it('on a system that is not selected, the press drags the system', () => {
    const t = new TestPlanner(oneRail());
    const from = t.screenOf({ x: 1.5, z: 1 });
    const k = t.view.scale;
    t.drag(from, { sx: from.sx + 0.5 * k, sy: from.sy + 0.5 * k });
    expect(t.system().fixings).toBeUndefined();
    expect(t.system().x).toBeCloseTo(1.5, 9);
    expect(t.system().z).toBeCloseTo(1.5, 9);
  });
});
