import { createGesture, dragAction, type Handler, pinchAction, wheelAction } from '@use-gesture/vanilla';
import type { PlannerController } from './PlannerController';
import { DRAG_THRESHOLD_PX } from './PlannerController';
import { addWheelPinchDelta, TRACKPAD_PINCH_SPAN_PX, wheelPinchSpan, wheelPixels } from './trackpadPinch';
import type { ScreenPoint } from './viewTransform';

/** What the gestures drive: the controller's input methods (tests pass a recording stand-in that checks their order). */
export type PlanGestureSink = Pick<PlannerController, 'pointerDown' | 'pointerMove' | 'pointerUp' | 'pointerCancel' | 'pinchStart' | 'pinchMove' | 'pinchEnd' | 'wheel'>;

/** Only the three recognisers the plan uses, so the bundle carries no scroll, move or hover engines. */
const planGesture = createGesture([dragAction, pinchAction, wheelAction]);

function isControl(target: EventTarget | null | undefined): boolean {
  return target instanceof Element && target.closest('button, input, select, label, [data-plan-control]') !== null;
}

/** What one pinch remembers between its events: whether the plan took it, where a trackpad pinch began and its wheel deltas so far. */
interface PinchMemo {
  mine: boolean;
  at: ScreenPoint;
  sum: number;
}

/**
 * The plan's three @use-gesture handlers and what they share: whether the press in progress has
 * become a pinch, and the trackpad pinch in progress.
 */
class PlanGestureHandlers {
  /** Set when two fingers make a pinch, cleared by the first finger of the next press (isPrimary). */
  pinchedThisPress = false;
  /** The trackpad pinch (ctrl+wheel, Safari's gesture events) in progress, if the plan took one. */
  private trackpadPinch: PinchMemo | null = null;

  constructor(
    private readonly controller: PlanGestureSink,
    private readonly local: (client: readonly number[]) => ScreenPoint,
  ) {}

  readonly onDrag: Handler<'drag'> = ({ first, last, tap, cancel, event, xy, initial, memo }) => {
    const { controller, local } = this;
    // Two fingers made a pinch of this press (the controller's pinchStart dropped the drag).
    if (this.pinchedThisPress) {
      cancel();
      return false;
    }
    // memo: whether this drag is the plan's (false: it started on a control).
    const mine = first || memo === undefined ? !isControl(event.target) : (memo as boolean);
    if (!mine) return false;
    // A press ends a trackpad pinch in progress.
    if (memo === undefined && this.trackpadPinch) {
      this.trackpadPinch.mine = false;
      this.trackpadPinch = null;
      controller.pinchEnd();
    }
    // A tap is a press that never became a drag; @use-gesture also calls a drag that travelled
    // exactly the threshold a tap when it ends (≤ against ≥): that one ends as a drag.
    if (tap && memo === undefined) {
      controller.pointerDown(local(initial));
      controller.pointerUp(local(initial));
      return true;
    }
    if (first) controller.pointerDown(local(initial));
    if (event.type === 'pointercancel' || event.type === 'lostpointercapture') controller.pointerCancel();
    // Released: where the release event is (@use-gesture's xy stays at the last move).
    else if (last) controller.pointerUp(local(event instanceof PointerEvent ? [event.clientX, event.clientY] : xy));
    else controller.pointerMove(local(xy));
    return true;
  };

  readonly onPinch: Handler<'pinch'> = ({ first, last, origin, da, event, type, dragging, memo }) => {
    const { controller, local } = this;
    const m = memo as PinchMemo | undefined;
    if (first || !m) {
      // A trackpad pinch while a drag is under way is not the plan's; nor is a pinch started on a control.
      const mine = !isControl(event?.target) && !(type === 'wheel' && dragging);
      const memoNow: PinchMemo = { mine, at: local(origin), sum: 0 };
      if (!mine) return memoNow;
      this.pinchedThisPress = type.startsWith('pointer');
      if (!this.pinchedThisPress) this.trackpadPinch = memoNow;
      controller.pinchStart(memoNow.at, type === 'wheel' ? TRACKPAD_PINCH_SPAN_PX : type.startsWith('gesture') ? TRACKPAD_PINCH_SPAN_PX * da[0] : da[0]);
      if (type === 'wheel') this.wheelPinchStep(memoNow, event as WheelEvent);
      return memoNow;
    }
    if (!m.mine) return m;
    if (last) {
      this.trackpadPinch = null;
      controller.pinchEnd();
    } else if (type === 'wheel') this.wheelPinchStep(m, event as WheelEvent);
    else if (type.startsWith('gesture')) controller.pinchMove(m.at, TRACKPAD_PINCH_SPAN_PX * da[0]);
    else controller.pinchMove(local(origin), da[0]);
    return m;
  };

  readonly onWheel: Handler<'wheel'> = ({ event, delta: [, dy], ctrlKey }) => {
    // ctrl+wheel is a trackpad pinch (onPinch); the closing call after the wheel stops has no delta.
    if (ctrlKey || dy === 0) return;
    event.preventDefault();
    this.controller.wheel(this.local([event.clientX, event.clientY]), dy);
  };

  private wheelPinchStep(m: PinchMemo, e: WheelEvent): void {
    m.sum = addWheelPinchDelta(m.sum, wheelPixels(e.deltaY, e.deltaMode));
    this.controller.pinchMove(m.at, wheelPinchSpan(m.sum));
  }
}

/**
 * Listens on the plan element through @use-gesture (drag, pinch, wheel) and hands the gestures to
 * the controller in plan pixels; marks the element `data-gestures="ready"` meanwhile. Returns the
 * function that removes the listeners. This module is a lazy chunk (usePlanGestures.ts loads it).
 *
 * - Drag with taps filtered: a press that travels at most DRAG_THRESHOLD_PX on each axis is a tap
 *   (pointerDown and pointerUp at the press point); one that moves that far is a drag
 *   (pointerDown at the press point, pointerMove for each move, pointerUp where it is released);
 *   @use-gesture drops the click that follows a drag. A press on a control, or with a button
 *   other than the primary one, is left alone. pointercancel and a lost capture drop the drag.
 * - Pinch: two fingers about their midpoint with their distance; a trackpad pinch (ctrl+wheel
 *   in Chromium and Firefox, Safari's gesture events) about where it began, with the scale of
 *   trackpadPinch.ts. A drag in progress is dropped; the finger left after a pinch neither drags
 *   nor taps until every finger has lifted.
 * - Wheel: zooms about the pointer, lines and pages turned into pixels by @use-gesture.
 */
export function listenToPlanGestures(el: HTMLElement, controller: PlanGestureSink): () => void {
  const handlers = new PlanGestureHandlers(controller, ([clientX, clientY]) => {
    const rect = el.getBoundingClientRect();
    return { sx: clientX - rect.left, sy: clientY - rect.top };
  });
  const onPressCapture = (e: PointerEvent) => {
    if (e.isPrimary) handlers.pinchedThisPress = false;
  };
  el.addEventListener('pointerdown', onPressCapture, { capture: true });
  el.dataset.gestures = 'ready';
  const gesture = planGesture(
    el,
    { onDrag: handlers.onDrag, onPinch: handlers.onPinch, onWheel: handlers.onWheel },
    {
      eventOptions: { passive: false },
      drag: { filterTaps: true, tapsThreshold: DRAG_THRESHOLD_PX },
      pinch: { rubberband: false },
    },
  );
  return () => {
    gesture.destroy();
    el.removeEventListener('pointerdown', onPressCapture, { capture: true });
    delete el.dataset.gestures;
    // A gesture in progress ends with the listeners, so the controller is not left mid-drag.
    controller.pointerCancel();
    controller.pinchEnd();
  };
}
