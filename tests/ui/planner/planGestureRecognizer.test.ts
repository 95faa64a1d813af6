import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { CTRL_WHEEL_MAX_DELTA_PX, type PlanGestureSink, PlanGestureRecognizer, type PointerRecord, TRACKPAD_PINCH_SPAN_PX, WHEEL_LINE_PX, WHEEL_PAGE_PX } from '../../../src/ui/planner/planGestureRecognizer';
import { DRAG_THRESHOLD_PX } from '../../../src/ui/planner/PlannerController';
import type { ScreenPoint } from '../../../src/ui/planner/viewTransform';
import { screenToWorld, worldToScreen } from '../../../src/ui/planner/viewTransform';
import { TestPlanner } from './testPlanner';

type Call = [name: string, ...args: unknown[]];

/**
 * A controller that records what it is told and checks the order a real one relies on: moves and
 * releases only inside a drag, pinch moves only inside a pinch, no drag starting inside a pinch,
 * no pinch starting over a drag that was not cancelled first.
 */
class RecordingController implements PlanGestureSink {
  readonly calls: Call[] = [];
  readonly violations: string[] = [];
  dragging = false;
  pinching = false;

  private check(ok: boolean, what: string): void {
    if (!ok) this.violations.push(`${what} after ${JSON.stringify(this.calls.slice(-4))}`);
  }
  pointerDown(at: ScreenPoint): void {
    this.check(!this.dragging && !this.pinching, 'pointerDown during a gesture');
    this.calls.push(['pointerDown', at]);
    this.dragging = true;
  }
  pointerMove(at: ScreenPoint): void {
    this.check(this.dragging, 'pointerMove outside a drag');
    this.calls.push(['pointerMove', at]);
  }
  pointerUp(at: ScreenPoint): void {
    this.check(this.dragging, 'pointerUp outside a drag');
    this.calls.push(['pointerUp', at]);
    this.dragging = false;
  }
  pointerCancel(): void {
    this.check(this.dragging, 'pointerCancel outside a drag');
    this.calls.push(['pointerCancel']);
    this.dragging = false;
  }
  pinchStart(centre: ScreenPoint, distance: number): void {
    this.check(!this.dragging && !this.pinching, 'pinchStart during a gesture');
    this.calls.push(['pinchStart', centre, distance]);
    this.pinching = true;
  }
  pinchMove(centre: ScreenPoint, distance: number): void {
    this.check(this.pinching, 'pinchMove without pinchStart');
    this.calls.push(['pinchMove', centre, distance]);
  }
  pinchEnd(): void {
    this.check(this.pinching, 'pinchEnd outside a pinch');
    this.calls.push(['pinchEnd']);
    this.pinching = false;
  }
  wheel(at: ScreenPoint, deltaYPixels: number): void {
    this.calls.push(['wheel', at, deltaYPixels]);
  }
}

const setup = () => {
  const c = new RecordingController();
  return { c, g: new PlanGestureRecognizer(c) };
};
const mouse = (x: number, y: number, extra: Partial<PointerRecord> = {}): PointerRecord => ({ id: 1, pointerType: 'mouse', x, y, button: 0, ...extra });
const finger = (id: number, x: number, y: number): PointerRecord => ({ id, pointerType: 'touch', x, y, button: 0 });
const at = (sx: number, sy: number): ScreenPoint => ({ sx, sy });

describe('taps and drags', () => {
  it('a press that moves less than the threshold on both axes is a tap at the press point', () => {
    const { c, g } = setup();
    expect(g.down(mouse(10, 10))).toBe(true);
    g.move(mouse(10 + DRAG_THRESHOLD_PX - 0.01, 10 - (DRAG_THRESHOLD_PX - 0.01)));
    g.move(mouse(12, 11.5));
    expect(c.calls).toEqual([]);
    expect(g.up(mouse(12, 11))).toBe(false);
    expect(c.calls).toEqual([
      ['pointerDown', at(10, 10)],
      ['pointerUp', at(10, 10)],
    ]);
    expect(c.violations).toEqual([]);
  });

  it('a press that moves the threshold reports its press point, then every move, then the release', () => {
    const { c, g } = setup();
    g.down(mouse(10, 10));
    g.move(mouse(11, 12));
    expect(c.calls).toEqual([]);
    g.move(mouse(10, 10 + DRAG_THRESHOLD_PX));
    g.move(mouse(11, 11)); // back inside the threshold: still a drag
    g.move(mouse(40, 30));
    expect(g.up(mouse(45, 30))).toBe(true);
    expect(c.calls).toEqual([
      ['pointerDown', at(10, 10)],
      ['pointerMove', at(10, 13)],
      ['pointerMove', at(11, 11)],
      ['pointerMove', at(40, 30)],
      ['pointerUp', at(45, 30)],
    ]);
    expect(c.violations).toEqual([]);
  });

  it('a press on a control, or with a button other than the primary, is left alone', () => {
    const { c, g } = setup();
    expect(g.down(mouse(10, 10, { onControl: true }))).toBe(false);
    g.move(mouse(60, 60));
    g.up(mouse(60, 60));
    expect(g.down(mouse(10, 10, { button: 2 }))).toBe(false);
    g.move(mouse(60, 60));
    g.up(mouse(60, 60));
    expect(g.down(mouse(10, 10, { button: 1 }))).toBe(false);
    g.up(mouse(10, 10));
    expect(c.calls).toEqual([]);
    // ... and a finger on a control does not make a pinch of the next one either.
    expect(g.down({ ...finger(5, 0, 0), onControl: true })).toBe(false);
    g.down(finger(6, 100, 0));
    g.up(finger(6, 100, 0));
    expect(c.calls).toEqual([
      ['pointerDown', at(100, 0)],
      ['pointerUp', at(100, 0)],
    ]);
  });

  it('pointercancel ends a drag without a release, and a press below the threshold without anything', () => {
    const { c, g } = setup();
    g.down(mouse(0, 0));
    g.move(mouse(1, 1));
    g.cancel(1);
    expect(c.calls).toEqual([]);
    g.down(mouse(0, 0));
    g.move(mouse(20, 0));
    g.cancel(1);
    g.up(mouse(30, 0)); // too late: the press is over
    expect(c.calls).toEqual([['pointerDown', at(0, 0)], ['pointerMove', at(20, 0)], ['pointerCancel']]);
    expect(g.busy).toBe(false);
    expect(c.violations).toEqual([]);
  });
});

describe('pinches', () => {
  it('two fingers pinch about their midpoint with their distance; lifting one ends it', () => {
    const { c, g } = setup();
    g.down(finger(1, 100, 100));
    expect(g.down(finger(2, 200, 100))).toBe(true);
    g.move(finger(2, 300, 100));
    g.move(finger(1, 100, 40));
    g.up(finger(1, 100, 40));
    g.move(finger(2, 310, 100)); // the finger left over neither pinches nor drags
    expect(c.calls).toEqual([['pinchStart', at(150, 100), 100], ['pinchMove', at(200, 100), 200], ['pinchMove', at(200, 70), Math.hypot(200, 60)], ['pinchEnd']]);
    // A new finger pinches with the one left over, from where that one is now.
    g.down(finger(3, 310, 200));
    expect(c.calls.at(-1)).toEqual(['pinchStart', at(310, 150), 100]);
    g.cancel(3);
    g.up(finger(2, 310, 100));
    expect(c.calls.at(-1)).toEqual(['pinchEnd']);
    expect(g.busy).toBe(false);
    expect(c.violations).toEqual([]);
  });

  it('a second finger during a drag cancels the drag and pinches from the first finger’s last position', () => {
    const { c, g } = setup();
    g.down(finger(1, 0, 0));
    g.move(finger(1, 30, 40));
    g.down(finger(2, 30, 140));
    g.down(finger(3, 500, 500)); // a third finger is ignored
    g.move(finger(3, 600, 600));
    g.up(finger(3, 600, 600));
    expect(c.calls).toEqual([['pointerDown', at(0, 0)], ['pointerMove', at(30, 40)], ['pointerCancel'], ['pinchStart', at(30, 90), 100]]);
    g.cancel(2);
    expect(c.calls.at(-1)).toEqual(['pinchEnd']);
    expect(c.violations).toEqual([]);
  });

  it('a second finger before the first passed the threshold pinches without a drag to cancel', () => {
    const { c, g } = setup();
    g.down(finger(1, 0, 0));
    g.move(finger(1, 1, 1));
    g.down(finger(2, 1, 101));
    expect(c.calls).toEqual([['pinchStart', at(1, 51), 100]]);
  });

  it('a mouse press ignores touches, and a second mouse-like pointer does not pinch', () => {
    const { c, g } = setup();
    g.down(mouse(0, 0));
    expect(g.down(finger(2, 50, 50))).toBe(false);
    expect(g.down({ id: 3, pointerType: 'pen', x: 9, y: 9, button: 0 })).toBe(false);
    g.up(mouse(0, 0));
    expect(c.calls).toEqual([
      ['pointerDown', at(0, 0)],
      ['pointerUp', at(0, 0)],
    ]);
  });
});

describe('wheel and trackpad pinch', () => {
  it('a wheel zooms about the pointer in pixels; lines and pages are converted', () => {
    const { c, g } = setup();
    g.wheel({ x: 5, y: 6, deltaY: -53, deltaMode: 0, ctrlKey: false });
    g.wheel({ x: 5, y: 6, deltaY: 3, deltaMode: 1, ctrlKey: false });
    g.wheel({ x: 5, y: 6, deltaY: -1, deltaMode: 2, ctrlKey: false });
    expect(c.calls).toEqual([
      ['wheel', at(5, 6), -53],
      ['wheel', at(5, 6), 3 * WHEEL_LINE_PX],
      ['wheel', at(5, 6), -WHEEL_PAGE_PX],
    ]);
    expect([WHEEL_LINE_PX, WHEEL_PAGE_PX]).toEqual([40, 800]);
  });

  it('ctrl+wheel is a pinch about where it began whose scale is exp(−ΣdeltaY/100) (Chromium’s encoding)', () => {
    const { c, g } = setup();
    // Chromium sends each pinch frame of scale s as deltaY = −100·ln(s).
    const frames = [1.1, 1.25, 0.9];
    frames.forEach((s, i) => g.wheel({ x: 50 + i, y: 60, deltaY: -100 * Math.log(s), deltaMode: 0, ctrlKey: true }));
    expect(g.wheelPinching).toBe(true);
    g.wheelPinchEnd();
    expect(c.calls.map((x) => x[0])).toEqual(['pinchStart', 'pinchMove', 'pinchMove', 'pinchMove', 'pinchEnd']);
    expect(c.calls[0]).toEqual(['pinchStart', at(50, 60), TRACKPAD_PINCH_SPAN_PX]);
    let product = 1;
    frames.forEach((s, i) => {
      product *= s;
      const [, centre, d] = c.calls[1 + i] as [string, ScreenPoint, number];
      expect(centre).toEqual(at(50, 60));
      expect(d / TRACKPAD_PINCH_SPAN_PX).toBeCloseTo(product, 12);
    });
    expect(c.violations).toEqual([]);
  });

  it('one ctrl+wheel event zooms by at most e^±0.5 (a mouse wheel with ctrl held), and a plain wheel ends the pinch', () => {
    const { c, g } = setup();
    g.wheel({ x: 0, y: 0, deltaY: 3, deltaMode: 1, ctrlKey: true });
    expect(c.calls[1]).toEqual(['pinchMove', at(0, 0), TRACKPAD_PINCH_SPAN_PX * Math.exp(-CTRL_WHEEL_MAX_DELTA_PX / 100)]);
    g.wheel({ x: 0, y: 0, deltaY: 10, deltaMode: 0, ctrlKey: false });
    expect(c.calls.slice(2)).toEqual([['pinchEnd'], ['wheel', at(0, 0), 10]]);
    expect(g.wheelPinching).toBe(false);
  });

  it('ctrl+wheel is ignored during a drag, and a press ends a trackpad pinch first', () => {
    const { c, g } = setup();
    g.down(mouse(0, 0));
    g.move(mouse(10, 0));
    g.wheel({ x: 0, y: 0, deltaY: -5, deltaMode: 0, ctrlKey: true });
    g.up(mouse(10, 0));
    g.wheel({ x: 0, y: 0, deltaY: -5, deltaMode: 0, ctrlKey: true });
    g.down(mouse(0, 0));
    expect(c.calls.map((x) => x[0])).toEqual(['pointerDown', 'pointerMove', 'pointerUp', 'pinchStart', 'pinchMove', 'pinchEnd']);
    expect(c.violations).toEqual([]);
  });

  it('Safari’s gesture events pinch by their scale about where they began', () => {
    const { c, g } = setup();
    g.gestureStart({ x: 20, y: 30, scale: 1 });
    g.gestureChange({ x: 25, y: 30, scale: 2 });
    g.gestureChange({ x: 25, y: 30, scale: 0.5 });
    g.wheel({ x: 0, y: 0, deltaY: -5, deltaMode: 0, ctrlKey: true }); // not both at once
    g.gestureEnd();
    expect(c.calls).toEqual([['pinchStart', at(20, 30), TRACKPAD_PINCH_SPAN_PX], ['pinchMove', at(20, 30), 2 * TRACKPAD_PINCH_SPAN_PX], ['pinchMove', at(20, 30), 0.5 * TRACKPAD_PINCH_SPAN_PX], ['pinchEnd']]);
  });

  it('abort ends a drag or a pinch in progress without effect', () => {
    const { c, g } = setup();
    g.down(mouse(0, 0));
    g.move(mouse(9, 0));
    g.abort();
    g.down(finger(1, 0, 0));
    g.down(finger(2, 10, 0));
    g.abort();
    expect(c.calls.map((x) => x[0])).toEqual(['pointerDown', 'pointerMove', 'pointerCancel', 'pinchStart', 'pinchEnd']);
    expect(g.busy).toBe(false);
  });
});

describe('with the real controller', () => {
  it('a drag moves a system by the pointer’s whole movement: the press point is the one reported', () => {
    const tp = new TestPlanner().alignToCentimetres();
    const g = new PlanGestureRecognizer(tp.controller);
    const before = tp.system();
    const from = tp.railCentre(0);
    g.down(mouse(from.sx, from.sy));
    for (let i = 1; i <= 6; i++) g.move(mouse(from.sx + 10 * i, from.sy));
    g.up(mouse(from.sx + 60, from.sy));
    const moved = tp.system();
    expect(moved.x - before.x).toBeCloseTo(Math.round((60 / tp.view.scale) * 100) / 100, 9);
    expect(moved.z).toBeCloseTo(before.z, 9);
  });

  it('a trackpad pinch of ×1.5 in Chromium’s ctrl+wheel deltas zooms ×1.5 and keeps the point under the cursor', () => {
    const tp = new TestPlanner();
    const g = new PlanGestureRecognizer(tp.controller);
    const view0 = tp.view;
    const cursor = at(400, 300);
    const world = screenToWorld(view0, cursor);
    for (let i = 0; i < 10; i++) g.wheel({ x: cursor.sx, y: cursor.sy, deltaY: (-100 * Math.log(1.5)) / 10, deltaMode: 0, ctrlKey: true });
    g.wheelPinchEnd();
    expect(tp.view.scale / view0.scale).toBeCloseTo(1.5, 9);
    const back = worldToScreen(tp.view, world);
    expect(back.sx).toBeCloseTo(cursor.sx, 6);
    expect(back.sy).toBeCloseTo(cursor.sy, 6);
  });
});

type Op = { kind: 'down' | 'move' | 'up'; id: number; x: number; y: number; button: number; onControl: boolean } | { kind: 'cancel'; id: number } | { kind: 'wheel'; deltaY: number; ctrlKey: boolean } | { kind: 'wheelIdle' };

describe('random sequences (seeded)', () => {
  const coord = fc.integer({ min: -20, max: 220 });
  const pointerOp = fc.record({
    kind: fc.constantFrom('down' as const, 'move' as const, 'move' as const, 'move' as const, 'up' as const),
    id: fc.integer({ min: 1, max: 3 }),
    x: coord,
    y: coord,
    button: fc.constantFrom(0, 0, 0, 0, 2),
    onControl: fc.constantFrom(false, false, false, true),
  });
  const op: fc.Arbitrary<Op> = fc.oneof(
    { weight: 10, arbitrary: pointerOp },
    { weight: 2, arbitrary: fc.record({ kind: fc.constant('cancel' as const), id: fc.integer({ min: 1, max: 3 }) }) },
    { weight: 1, arbitrary: fc.record({ kind: fc.constant('wheel' as const), deltaY: fc.integer({ min: -120, max: 120 }), ctrlKey: fc.boolean() }) },
    { weight: 1, arbitrary: fc.constant({ kind: 'wheelIdle' as const }) },
  );
  // Each of the three pointers is a finger, a mouse or a pen for the whole sequence.
  const types = fc.tuple(...[0, 1, 2].map(() => fc.constantFrom('touch', 'touch', 'mouse', 'pen')));

  it('after every pointer is up or cancelled, the controller is in no drag or pinch, and never saw a move outside one', () => {
    fc.assert(
      fc.property(types, fc.array(op, { maxLength: 60 }), fc.array(fc.boolean(), { minLength: 3, maxLength: 3 }), (kinds, ops, cancelAtEnd) => {
        const { c, g } = setup();
        const down = new Set<number>();
        const record = (o: { id: number; x: number; y: number; button?: number; onControl?: boolean }): PointerRecord => ({
          id: o.id,
          pointerType: kinds[o.id - 1],
          x: o.x,
          y: o.y,
          button: o.button,
          onControl: o.onControl,
        });
        for (const o of ops) {
          if (o.kind === 'down') {
            // As browsers do: a pointer already down does not go down again.
            if (down.has(o.id)) continue;
            down.add(o.id);
            g.down(record(o));
          } else if (o.kind === 'move')
            g.move(record(o)); // also for pointers that are not down (a hovering mouse)
          else if (o.kind === 'up') {
            down.delete(o.id);
            g.up(record(o));
          } else if (o.kind === 'cancel') {
            down.delete(o.id);
            g.cancel(o.id);
          } else if (o.kind === 'wheel') g.wheel({ x: 50, y: 50, deltaY: o.deltaY, deltaMode: 0, ctrlKey: o.ctrlKey });
          else g.wheelPinchEnd();
        }
        for (const id of down) {
          if (cancelAtEnd[id - 1]) g.cancel(id);
          else g.up({ id, pointerType: kinds[id - 1], x: 0, y: 0 });
        }
        g.wheelPinchEnd();
        expect(c.violations).toEqual([]);
        expect(c.dragging).toBe(false);
        expect(c.pinching).toBe(false);
        expect(g.busy).toBe(false);
      }),
      { seed: 20261123, numRuns: 400 },
    );
  });
});
