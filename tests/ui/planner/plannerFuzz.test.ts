import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { addLibraryItem } from '../../../src/ui/planner/addFurniture';
import { PLANNER_COMMANDS } from '../../../src/ui/planner/plannerCommands';
import type { RoomObject } from '../../../src/core/model/configuration/configuration';
import { FURNITURE_LIBRARY } from '../../../src/core/model/objects/furniture/furnitureLibrary';
import { objectPlacement } from '../../../src/core/model/objects/objectGeometry';
import { TestPlanner } from './testPlanner';

/** One thing a user can do to the plan, with positions in plan pixels (1000 × 800). */
type Step =
  | { kind: 'drag'; on: 'system' | 'object' | 'anywhere'; from: [number, number]; by: [number, number]; steps: number }
  | { kind: 'add'; item: string; at: [number, number] | null }
  | { kind: 'tap'; at: [number, number] }
  | { kind: 'wheel'; at: [number, number]; delta: number }
  | { kind: 'pinch'; at: [number, number]; from: number; to: number }
  | { kind: 'key'; spec: string }
  | { kind: 'button'; id: string };

const point = fc.tuple(fc.integer({ min: -50, max: 1050 }), fc.integer({ min: -50, max: 850 }));
const keySpecs = [...new Set(PLANNER_COMMANDS.flatMap((c) => c.keys)), 'x', 'Mod+r', 'Alt+z'];
// 3D and options only change UI panels; leave the plan in 2D as the keyboard requires.
const buttonIds = PLANNER_COMMANDS.map((c) => c.id).filter((id) => id !== 'toggle-3d');

// Drags and keys are what change the configuration: they come up most.
const step: fc.Arbitrary<Step> = fc.oneof(
  {
    weight: 4,
    arbitrary: fc.record({
      kind: fc.constant('drag' as const),
      // A third of the drags start on a system (its first rail's middle), a third on an object, the rest anywhere.
      on: fc.constantFrom('system' as const, 'object' as const, 'anywhere' as const),
      from: point,
      by: fc.tuple(fc.integer({ min: -200, max: 200 }), fc.integer({ min: -200, max: 200 })),
      steps: fc.integer({ min: 1, max: 6 }),
    }),
  },
  fc.record({ kind: fc.constant('tap' as const), at: point }),
  // Furniture from the panel: tapped (the middle of the visible plan) or dropped at a point.
  fc.record({ kind: fc.constant('add' as const), item: fc.constantFrom(...FURNITURE_LIBRARY.map((i) => i.id)), at: fc.option(point, { nil: null }) }),
  fc.record({ kind: fc.constant('wheel' as const), at: point, delta: fc.integer({ min: -600, max: 600 }) }),
  fc.record({ kind: fc.constant('pinch' as const), at: point, from: fc.integer({ min: 20, max: 400 }), to: fc.integer({ min: 20, max: 400 }) }),
  { weight: 3, arbitrary: fc.record({ kind: fc.constant('key' as const), spec: fc.constantFrom(...keySpecs) }) },
  fc.record({ kind: fc.constant('button' as const), id: fc.constantFrom(...buttonIds) }),
);

/** A point on an object (its origin: a floor item's footprint centre, a wall item's back on its wall), on screen. */
function objectPoint(t: TestPlanner, o: RoomObject) {
  const w = objectPlacement(o, t.config.room).position;
  return t.screenOf({ x: w[0], z: w[2] });
}

function perform(t: TestPlanner, s: Step): void {
  const at = (p: [number, number]) => ({ sx: p[0], sy: p[1] });
  switch (s.kind) {
    case 'add':
      addLibraryItem(t.controller, s.item, s.at ? at(s.at) : undefined);
      return;
    case 'drag': {
      const o = t.config.objects[t.config.objects.length - 1];
      const from = s.on === 'system' && t.config.systems.length > 0 ? t.railCentre() : s.on === 'object' && o ? objectPoint(t, o) : at(s.from);
      t.drag(from, { sx: from.sx + s.by[0], sy: from.sy + s.by[1] }, s.steps);
      return;
    }
    case 'tap':
      t.tap(at(s.at));
      return;
    case 'wheel':
      t.controller.wheel(at(s.at), s.delta);
      return;
    case 'pinch':
      t.controller.pinchStart(at(s.at), s.from);
      t.controller.pinchMove(at(s.at), s.to);
      t.controller.pinchEnd();
      return;
    case 'key':
      t.press(s.spec);
      return;
    case 'button':
      t.controller.command(s.id);
  }
}

describe('random pointer and key sequences (seeded)', () => {
  it('never produce an invalid configuration (systems and objects alike), and every accepted step is undone exactly', () => {
    let changed = 0;
    let objectChanges = 0;
    fc.assert(
      fc.property(fc.array(step, { minLength: 1, maxLength: 40, size: 'max' }), (steps) => {
        const t = new TestPlanner();
        const seen = [t.config];
        for (const s of steps) {
          perform(t, s);
          expect(t.problems()).toEqual([]);
          expect(t.controller.drag).toBeNull();
          expect(Number.isFinite(t.view.scale) && Number.isFinite(t.view.offsetX) && Number.isFinite(t.view.offsetY)).toBe(true);
          const last = seen[seen.length - 1];
          if (t.config !== last) {
            if (t.config.objects !== last.objects) objectChanges++;
            seen.push(t.config);
          }
        }
        changed += seen.length - 1;
        // Undo walks back through valid configurations to the start.
        while (t.store.getState().undo()) expect(t.problems()).toEqual([]);
        expect(t.config).toEqual(seen[0]);
      }),
      { seed: 20261123, numRuns: 60 },
    );
    // The sequences did reach the model (else the check above proves little), objects included.
    expect(changed).toBeGreaterThan(100);
    expect(objectChanges).toBeGreaterThan(50);
  });
});
