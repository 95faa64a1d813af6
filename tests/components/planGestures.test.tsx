import { act, cleanup, render } from '@testing-library/react';
import fc from 'fast-check';
import { useRef } from 'react';
import { afterEach, beforeAll, beforeEach, describe, expect, it, vi } from 'vitest';
import { DRAG_THRESHOLD_PX, type PlannerController } from '../../src/ui/planner/PlannerController';
import { CTRL_WHEEL_MAX_DELTA_PX, TRACKPAD_PINCH_SPAN_PX, WHEEL_LINE_PX, WHEEL_PAGE_PX } from '../../src/ui/planner/trackpadPinch';
import { loadPlanGestures, type PlanGestureSink, usePlanGestures } from '../../src/ui/planner/usePlanGestures';
import { type ScreenPoint, screenToWorld, worldToScreen } from '../../src/ui/planner/viewTransform';
import { TestPlanner } from '../ui/planner/testPlanner';

/**
 * The plan's gestures as @use-gesture recognises them (usePlanGestures.ts, planGestureListener.ts), fed DOM pointer and
 * wheel events in happy-dom on each runtime (React, preact/compat). The plan element sits at the
 * page's origin, so client and plan pixels are the same. These are the scenarios the hand-written
 * recogniser was tested with before the library came back (docs/planner.md, "Gestures").
 */

type Call = [name: string, ...args: unknown[]];

/**
 * Records what the controller is told and checks the order a real one relies on: moves and
 * releases only inside a drag, pinch moves only inside a pinch, no drag starting inside a pinch.
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
    // The real controller's pointerCancel is safe at any time (the hook calls it when it unbinds).
    if (this.dragging) this.calls.push(['pointerCancel']);
    this.dragging = false;
  }
  pinchStart(centre: ScreenPoint, distance: number): void {
    // As the real controller: a pinch drops the drag in progress.
    this.pointerCancel();
    this.check(!this.pinching, 'pinchStart during a pinch');
    this.calls.push(['pinchStart', centre, distance]);
    this.pinching = true;
  }
  pinchMove(centre: ScreenPoint, distance: number): void {
    this.check(this.pinching, 'pinchMove without pinchStart');
    this.calls.push(['pinchMove', centre, distance]);
  }
  pinchEnd(): void {
    if (this.pinching) this.calls.push(['pinchEnd']);
    this.pinching = false;
  }
  wheel(at: ScreenPoint, deltaYPixels: number): void {
    this.calls.push(['wheel', at, deltaYPixels]);
  }
}

function GesturePlan({ sink }: { sink: PlanGestureSink }) {
  const ref = useRef<HTMLDivElement>(null);
  usePlanGestures(ref, sink);
  return (
    <div ref={ref} data-testid="plan">
      <button type="button">control</button>
      <svg>
        <rect data-testid="floor" width="100" height="100" />
      </svg>
    </div>
  );
}

let plan: HTMLElement;
let control: HTMLElement;

function mount(sink: PlanGestureSink) {
  const { getByTestId, getByRole } = render(<GesturePlan sink={sink} />);
  plan = getByTestId('plan');
  expect(plan.dataset.gestures).toBe('ready');
  control = getByRole('button');
}

const at = (sx: number, sy: number): ScreenPoint => ({ sx, sy });
/** Pointers down now: the first of a press sequence is the primary one, as browsers mark it. */
const pressed = new Set<number>();
let primary: number | null = null;
function pointer(type: string, id: number, pointerType: string, x: number, y: number, buttons: number, target: Element = plan): boolean {
  if (type === 'pointerdown') {
    if (pressed.size === 0) primary = id;
    pressed.add(id);
  }
  const e = new PointerEvent(type, { pointerId: id, pointerType, isPrimary: id === primary, clientX: x, clientY: y, buttons, button: type === 'pointermove' ? -1 : buttons === 2 ? 2 : 0, bubbles: true, cancelable: true });
  if (type === 'pointerup' || type === 'pointercancel') pressed.delete(id);
  return target.dispatchEvent(e);
}
const mouse = {
  down: (x: number, y: number, target?: Element) => pointer('pointerdown', 1, 'mouse', x, y, 1, target),
  move: (x: number, y: number) => pointer('pointermove', 1, 'mouse', x, y, 1),
  up: (x: number, y: number) => pointer('pointerup', 1, 'mouse', x, y, 0),
};
const finger = {
  down: (id: number, x: number, y: number) => pointer('pointerdown', id, 'touch', x, y, 1),
  move: (id: number, x: number, y: number) => pointer('pointermove', id, 'touch', x, y, 1),
  up: (id: number, x: number, y: number) => pointer('pointerup', id, 'touch', x, y, 0),
};
/** happy-dom's WheelEvent takes only the deltas from its init (no clientX/Y, no modifier keys): the rest is set on the event as a browser's would have it. */
const wheel = (x: number, y: number, deltaY: number, deltaMode = 0, ctrlKey = false) => {
  const e = new WheelEvent('wheel', { deltaY, deltaMode, bubbles: true, cancelable: true });
  for (const [key, value] of Object.entries({ clientX: x, clientY: y, ctrlKey, metaKey: false, shiftKey: false, altKey: false })) Object.defineProperty(e, key, { value });
  return plan.dispatchEvent(e);
};

// The listeners are a lazy chunk: once it is loaded, a plan element listens as soon as it mounts.
beforeAll(async () => {
  await loadPlanGestures();
});
beforeEach(() => {
  vi.useFakeTimers();
});
afterEach(() => {
  cleanup();
  pressed.clear();
  vi.useRealTimers();
});

describe('taps and drags', () => {
  it('a press that moves less than the threshold on both axes is a tap at the press point', () => {
    const c = new RecordingController();
    mount(c);
    mouse.down(10, 10);
    mouse.move(10 + DRAG_THRESHOLD_PX - 1, 10);
    mouse.move(12, 11);
    expect(c.calls).toEqual([]);
    mouse.up(12, 11);
    expect(c.calls).toEqual([
      ['pointerDown', at(10, 10)],
      ['pointerUp', at(10, 10)],
    ]);
    expect(c.violations).toEqual([]);
  });

  it('a press that moves the threshold reports its press point, then every move, then the release; the click after it is dropped', () => {
    const c = new RecordingController();
    mount(c);
    mouse.down(10, 10);
    mouse.move(11, 12);
    expect(c.calls).toEqual([]);
    mouse.move(10, 10 + DRAG_THRESHOLD_PX);
    mouse.move(11, 11); // back inside the threshold: still a drag
    mouse.move(40, 30);
    mouse.up(45, 30);
    expect(c.calls).toEqual([
      ['pointerDown', at(10, 10)],
      ['pointerMove', at(10, 13)],
      ['pointerMove', at(11, 11)],
      ['pointerMove', at(40, 30)],
      ['pointerUp', at(45, 30)],
    ]);
    const click = new MouseEvent('click', { detail: 1, bubbles: true, cancelable: true });
    plan.dispatchEvent(click);
    expect(click.defaultPrevented).toBe(true);
    expect(c.violations).toEqual([]);
  });

  it('a press on a control, or with a button other than the primary, is left alone', () => {
    const c = new RecordingController();
    mount(c);
    mouse.down(10, 10, control);
    pointer('pointermove', 1, 'mouse', 60, 60, 1, control);
    pointer('pointerup', 1, 'mouse', 60, 60, 0, control);
    pointer('pointerdown', 1, 'mouse', 10, 10, 2);
    pointer('pointermove', 1, 'mouse', 60, 60, 2);
    pointer('pointerup', 1, 'mouse', 60, 60, 0);
    expect(c.calls).toEqual([]);
  });

  it('pointercancel ends a drag without a release', () => {
    const c = new RecordingController();
    mount(c);
    mouse.down(0, 0);
    mouse.move(20, 0);
    pointer('pointercancel', 1, 'mouse', 20, 0, 0);
    mouse.up(30, 0); // too late: the press is over
    act(() => void vi.runAllTimers());
    expect(c.calls).toEqual([['pointerDown', at(0, 0)], ['pointerMove', at(20, 0)], ['pointerCancel']]);
    expect(c.violations).toEqual([]);
  });
});

describe('pinches', () => {
  it('two fingers pinch about their midpoint with their distance; lifting one ends it, and the one left neither drags nor taps', () => {
    const c = new RecordingController();
    mount(c);
    finger.down(1, 100, 100);
    finger.down(2, 200, 100);
    finger.move(2, 300, 100);
    finger.move(1, 100, 40);
    finger.up(1, 100, 40);
    finger.move(2, 310, 100);
    finger.move(2, 340, 130);
    finger.up(2, 340, 130);
    act(() => void vi.runAllTimers());
    expect(c.calls[0]).toEqual(['pinchStart', at(150, 100), 100]);
    expect(c.calls.filter((x) => x[0] === 'pinchMove').at(-1)).toEqual(['pinchMove', at(200, 70), Math.hypot(200, 60)]);
    expect(c.calls.at(-1)).toEqual(['pinchEnd']);
    expect(c.calls.some((x) => x[0].startsWith('pointer'))).toBe(false);
    expect(c.violations).toEqual([]);
  });

  it('a second finger during a drag drops the drag and pinches from the first finger’s last position', () => {
    const c = new RecordingController();
    mount(c);
    finger.down(1, 0, 0);
    finger.move(1, 30, 40);
    finger.down(2, 30, 140);
    finger.up(2, 30, 140);
    finger.up(1, 30, 40);
    act(() => void vi.runAllTimers());
    expect(c.calls.slice(0, 4)).toEqual([['pointerDown', at(0, 0)], ['pointerMove', at(30, 40)], ['pointerCancel'], ['pinchStart', at(30, 90), 100]]);
    expect(c.calls.at(-1)).toEqual(['pinchEnd']);
    expect(c.calls.filter((x) => x[0] === 'pointerUp')).toEqual([]);
    expect(c.violations).toEqual([]);
  });
});

describe('wheel and trackpad pinch', () => {
  it('a wheel zooms about the pointer in pixels; lines and pages are converted', () => {
    const c = new RecordingController();
    mount(c);
    wheel(5, 6, -53);
    act(() => void vi.runAllTimers());
    wheel(5, 6, 3, 1);
    act(() => void vi.runAllTimers());
    wheel(5, 6, -1, 2);
    act(() => void vi.runAllTimers());
    expect(c.calls).toEqual([
      ['wheel', at(5, 6), -53],
      ['wheel', at(5, 6), 3 * WHEEL_LINE_PX],
      ['wheel', at(5, 6), -WHEEL_PAGE_PX],
    ]);
    expect([WHEEL_LINE_PX, WHEEL_PAGE_PX]).toEqual([40, 800]);
  });

  it('ctrl+wheel is a pinch about where it began whose scale is exp(−ΣdeltaY/100) (Chromium’s encoding), ended when the wheel rests', () => {
    const c = new RecordingController();
    mount(c);
    // Chromium sends each pinch frame of scale s as deltaY = −100·ln(s).
    const frames = [1.1, 1.25, 0.9];
    frames.forEach((s, i) => wheel(50 + i, 60, -100 * Math.log(s), 0, true));
    expect(c.calls.map((x) => x[0])).toEqual(['pinchStart', 'pinchMove', 'pinchMove', 'pinchMove']);
    act(() => void vi.runAllTimers());
    expect(c.calls.at(-1)).toEqual(['pinchEnd']);
    expect(c.calls[0]).toEqual(['pinchStart', at(50, 60), TRACKPAD_PINCH_SPAN_PX]);
    let product = 1;
    frames.forEach((s, i) => {
      product *= s;
      const [, centre, d] = c.calls[1 + i] as [string, ScreenPoint, number];
      expect(centre).toEqual(at(50, 60));
      expect(d / TRACKPAD_PINCH_SPAN_PX).toBeCloseTo(product, 12);
    });
    expect(c.calls.some((x) => x[0] === 'wheel')).toBe(false);
    expect(c.violations).toEqual([]);
  });

  it('one ctrl+wheel event zooms by at most e^±0.5 (a mouse wheel with ctrl held)', () => {
    const c = new RecordingController();
    mount(c);
    wheel(0, 0, 3, 1, true);
    expect(c.calls[1]).toEqual(['pinchMove', at(0, 0), TRACKPAD_PINCH_SPAN_PX * Math.exp(-CTRL_WHEEL_MAX_DELTA_PX / 100)]);
  });

  it('unmounting in the middle of a drag or a pinch ends it without effect', () => {
    const c = new RecordingController();
    mount(c);
    mouse.down(0, 0);
    mouse.move(9, 0);
    cleanup();
    expect(c.calls.map((x) => x[0])).toEqual(['pointerDown', 'pointerMove', 'pointerCancel']);
    expect(c.dragging).toBe(false);
  });
});

describe('with the real controller', () => {
  it('a drag moves a system by the pointer’s whole movement: the press point is the one reported', () => {
    const tp = new TestPlanner().alignToCentimetres();
    mount(tp.controller as PlannerController);
    const before = tp.system();
    const from = tp.railCentre(0);
    mouse.down(from.sx, from.sy);
    for (let i = 1; i <= 6; i++) mouse.move(from.sx + 10 * i, from.sy);
    mouse.up(from.sx + 60, from.sy);
    const moved = tp.system();
    expect(moved.x - before.x).toBeCloseTo(Math.round((60 / tp.view.scale) * 100) / 100, 9);
    expect(moved.z).toBeCloseTo(before.z, 9);
  });

  it('a trackpad pinch of ×1.5 in Chromium’s ctrl+wheel deltas zooms ×1.5 and keeps the point under the cursor', () => {
    const tp = new TestPlanner();
    mount(tp.controller);
    const view0 = tp.view;
    const cursor = at(400, 300);
    const world = screenToWorld(view0, cursor);
    for (let i = 0; i < 10; i++) wheel(cursor.sx, cursor.sy, (-100 * Math.log(1.5)) / 10, 0, true);
    act(() => void vi.runAllTimers());
    expect(tp.view.scale / view0.scale).toBeCloseTo(1.5, 9);
    const back = worldToScreen(tp.view, world);
    expect(back.sx).toBeCloseTo(cursor.sx, 6);
    expect(back.sy).toBeCloseTo(cursor.sy, 6);
  });
});

type Op = { kind: 'down' | 'move' | 'up' | 'cancel'; id: number; x: number; y: number } | { kind: 'wheel'; deltaY: number; ctrlKey: boolean } | { kind: 'idle' };

describe('random sequences (seeded)', () => {
  const coord = fc.integer({ min: -20, max: 220 });
  const op: fc.Arbitrary<Op> = fc.oneof(
    { weight: 10, arbitrary: fc.record({ kind: fc.constantFrom('down' as const, 'move' as const, 'move' as const, 'move' as const, 'up' as const), id: fc.integer({ min: 1, max: 3 }), x: coord, y: coord }) },
    { weight: 2, arbitrary: fc.record({ kind: fc.constant('cancel' as const), id: fc.integer({ min: 1, max: 3 }), x: coord, y: coord }) },
    { weight: 1, arbitrary: fc.record({ kind: fc.constant('wheel' as const), deltaY: fc.integer({ min: -120, max: 120 }), ctrlKey: fc.boolean() }) },
    { weight: 1, arbitrary: fc.constant({ kind: 'idle' as const }) },
  );

  it('fingers and wheels in any order: after every finger is up and the timers have run, the controller is in no drag or pinch and never saw a move outside one', () => {
    fc.assert(
      fc.property(fc.array(op, { maxLength: 40 }), (ops) => {
        const c = new RecordingController();
        mount(c);
        try {
          runOps(c, ops);
        } finally {
          cleanup();
          pressed.clear();
        }
      }),
      { seed: 20261127, numRuns: 150 },
    );
  });
});

function runOps(c: RecordingController, ops: Op[]): void {
  const down = new Set<number>();
  for (const o of ops) {
    if (o.kind === 'wheel') wheel(50, 50, o.deltaY, 0, o.ctrlKey);
    else if (o.kind === 'idle') act(() => void vi.runAllTimers());
    else if (o.kind === 'down') {
      // As browsers do: a pointer already down does not go down again, nor does one that is up move.
      if (down.has(o.id)) continue;
      down.add(o.id);
      finger.down(o.id, o.x, o.y);
    } else if (down.has(o.id)) {
      if (o.kind === 'move') finger.move(o.id, o.x, o.y);
      else {
        down.delete(o.id);
        pointer(o.kind === 'up' ? 'pointerup' : 'pointercancel', o.id, 'touch', o.x, o.y, 0);
      }
    }
  }
  for (const id of down) finger.up(id, 0, 0);
  act(() => void vi.runAllTimers());
  expect(c.violations).toEqual([]);
  expect(c.dragging).toBe(false);
  expect(c.pinching).toBe(false);
}
