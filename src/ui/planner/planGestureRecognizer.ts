import type { PlannerController } from './PlannerController';
import { DRAG_THRESHOLD_PX } from './PlannerController';
import type { ScreenPoint } from './viewTransform';

/** What the recogniser drives: the controller's input methods (tests pass a recording fake). */
export type PlanGestureSink = Pick<PlannerController, 'pointerDown' | 'pointerMove' | 'pointerUp' | 'pointerCancel' | 'pinchStart' | 'pinchMove' | 'pinchEnd' | 'wheel'>;

/** One pointer event in plan pixels (relative to the plan's top-left corner). */
export interface PointerRecord {
  /** PointerEvent.pointerId. */
  readonly id: number;
  /** PointerEvent.pointerType: 'mouse', 'pen' or 'touch'. */
  readonly pointerType: string;
  readonly x: number;
  readonly y: number;
  /** Down only: PointerEvent.button (0 is the primary button, a finger or a pen's tip). */
  readonly button?: number;
  /** Down only: pressed on a control (button, field, label, on-plan control), which keeps the press. */
  readonly onControl?: boolean;
}

/** One wheel event in plan pixels. */
export interface WheelRecord {
  readonly x: number;
  readonly y: number;
  readonly deltaY: number;
  /** WheelEvent.deltaMode: 0 pixels, 1 lines, 2 pages. */
  readonly deltaMode: number;
  /** Set by Chromium and Firefox on the wheel events a trackpad pinch arrives as. */
  readonly ctrlKey: boolean;
}

/** One of Safari's gesturestart / gesturechange events (macOS trackpad pinch): `scale` since the gesture began. */
export interface ScaleRecord {
  readonly x: number;
  readonly y: number;
  readonly scale: number;
}

/**
 * Pixels per line and per page for wheels that count lines (deltaMode 1, Firefox with a mouse
 * wheel on several platforms) or pages (deltaMode 2): the values @use-gesture used, so the zoom
 * per notch did not change when it was replaced.
 */
export const WHEEL_LINE_PX = 40;
export const WHEEL_PAGE_PX = 800;

/**
 * A trackpad pinch has no fingers to measure: it is handed to the controller as a pinch whose
 * distance starts at this many pixels and follows the gesture's scale (the controller only uses
 * ratios of distances).
 */
export const TRACKPAD_PINCH_SPAN_PX = 100;

/**
 * ctrl+wheel deltaY per e-fold of scale. Chromium sends a trackpad pinch as ctrl+wheel events with
 * deltaY = −100·ln(scale) per event, designed so that deltas add (components/input/
 * touchpad_pinch_event_queue.cc: "to convert a wheel deltaY back to a scale use
 * Math.exp(-deltaY/100)"); Firefox sends deltaY = −100·M from macOS's magnification M
 * (PinchGestureInput::ComputeDeltaY, widget/InputData.cpp), the same to first order. So the
 * pinch's scale is exp(−ΣdeltaY / 100) over the gesture's events.
 */
export const CTRL_WHEEL_PX_PER_E = 100;

/**
 * One ctrl+wheel event changes the scale by at most e^(±0.5) (×1.65): a trackpad sends a few
 * pixels per event, but a mouse wheel turned with ctrl held sends 100 or more per notch, which
 * would otherwise zoom ×2.7 at a click.
 */
export const CTRL_WHEEL_MAX_DELTA_PX = 50;

/**
 * Milliseconds without a ctrl+wheel event after which the trackpad pinch they make up has ended
 * (wheel events carry no end; @use-gesture waited 140 ms). The hook keeps the timer and calls
 * wheelPinchEnd; the recogniser itself has no clock.
 */
export const WHEEL_PINCH_IDLE_MS = 140;

type PointerState =
  | { kind: 'idle' }
  /** One pointer pressed on the plan: a tap until it moves DRAG_THRESHOLD_PX, then a drag. */
  | { kind: 'press'; id: number; pointerType: string; start: ScreenPoint; last: ScreenPoint; dragging: boolean }
  /** Two fingers: a pinch about their midpoint. */
  | { kind: 'pinch'; a: Finger; b: Finger }
  /** The finger left when a pinch lost the other one: it never drags, but a new finger pinches with it. */
  | { kind: 'spent'; finger: Finger };

interface Finger {
  id: number;
  at: ScreenPoint;
}

const point = (r: { x: number; y: number }): ScreenPoint => ({ sx: r.x, sy: r.y });
const midpoint = (a: Finger, b: Finger): ScreenPoint => ({ sx: (a.at.sx + b.at.sx) / 2, sy: (a.at.sy + b.at.sy) / 2 });
const distance = (a: Finger, b: Finger): number => Math.hypot(a.at.sx - b.at.sx, a.at.sy - b.at.sy);
const finite = (...xs: number[]): boolean => xs.every(Number.isFinite);

/** A wheel's vertical delta in pixels, whatever unit the browser counted in. */
export function wheelPixels(deltaY: number, deltaMode: number): number {
  if (deltaMode === 1) return deltaY * WHEEL_LINE_PX;
  if (deltaMode === 2) return deltaY * WHEEL_PAGE_PX;
  return deltaY;
}

/**
 * The plan's gestures from pointer, wheel and Safari gesture records, without a DOM: taps, drags,
 * two-finger pinches, trackpad pinches (ctrl+wheel, Safari's gesture events) and wheel turns,
 * handed to the controller in plan pixels. usePlanGestures feeds it DOM events; tests feed it
 * scripted and random sequences.
 *
 * - A press (primary button, finger or pen tip; not on a control) that moves less than
 *   DRAG_THRESHOLD_PX on both axes before it is released is a tap: pointerDown and pointerUp at
 *   the press point. Once it moves that far it is a drag: pointerDown at the press point, then
 *   pointerMove for each move and pointerUp where it is released.
 * - A second finger while one is pressed (or left over from a pinch) drops the first one's drag
 *   (pointerCancel) and starts a pinch about the two fingers' midpoint with their distance;
 *   lifting either ends it. Further fingers are ignored.
 * - Cancelled pointers (pointercancel, lost capture) end what they were part of without moving
 *   anything: pointerCancel for a drag, pinchEnd for a pinch.
 */
export class PlanGestureRecognizer {
  private readonly sink: PlanGestureSink;
  private state: PointerState = { kind: 'idle' };
  /** A trackpad pinch in progress (ctrl+wheel or Safari gesture events): where, and the wheel deltas so far. */
  private trackpad: { source: 'wheel' | 'gesture'; at: ScreenPoint; sum: number } | null = null;

  constructor(sink: PlanGestureSink) {
    this.sink = sink;
  }

  /** Whether a pointer press, drag or pinch is in progress (the hook keeps the pointer captured meanwhile). */
  get busy(): boolean {
    return this.state.kind !== 'idle';
  }

  /** Whether a trackpad pinch made of ctrl+wheel events is in progress (the hook ends it after WHEEL_PINCH_IDLE_MS). */
  get wheelPinching(): boolean {
    return this.trackpad?.source === 'wheel';
  }

  /** A pointer went down. Returns whether the plan takes it (the hook then captures it), false when it is left alone. */
  down(r: PointerRecord): boolean {
    if ((r.button ?? 0) !== 0 || r.onControl || !finite(r.x, r.y)) return false;
    const s = this.state;
    const finger: Finger = { id: r.id, at: point(r) };
    if (s.kind === 'idle') {
      this.endTrackpad();
      this.state = { kind: 'press', id: r.id, pointerType: r.pointerType, start: point(r), last: point(r), dragging: false };
      return true;
    }
    if (r.pointerType !== 'touch') return false;
    if (s.kind === 'press' && s.pointerType === 'touch' && s.id !== r.id) {
      if (s.dragging) this.sink.pointerCancel();
      this.startPinch({ id: s.id, at: s.last }, finger);
      return true;
    }
    if (s.kind === 'spent' && s.finger.id !== r.id) {
      this.startPinch(s.finger, finger);
      return true;
    }
    return false;
  }

  private startPinch(a: Finger, b: Finger): void {
    this.state = { kind: 'pinch', a, b };
    this.sink.pinchStart(midpoint(a, b), distance(a, b));
  }

  move(r: PointerRecord): void {
    if (!finite(r.x, r.y)) return;
    const s = this.state;
    const at = point(r);
    if (s.kind === 'press' && s.id === r.id) {
      s.last = at;
      if (!s.dragging) {
        if (Math.abs(at.sx - s.start.sx) < DRAG_THRESHOLD_PX && Math.abs(at.sy - s.start.sy) < DRAG_THRESHOLD_PX) return;
        s.dragging = true;
        this.sink.pointerDown(s.start);
      }
      this.sink.pointerMove(at);
    } else if (s.kind === 'pinch' && (s.a.id === r.id || s.b.id === r.id)) {
      const moved = s.a.id === r.id ? s.a : s.b;
      if (moved.at.sx === at.sx && moved.at.sy === at.sy) return;
      moved.at = at;
      this.sink.pinchMove(midpoint(s.a, s.b), distance(s.a, s.b));
    } else if (s.kind === 'spent' && s.finger.id === r.id) {
      s.finger.at = at;
    }
  }

  /** A pointer was released. Returns whether that ended a drag (the hook then drops the click that follows). */
  up(r: PointerRecord): boolean {
    const s = this.state;
    if (s.kind === 'press' && s.id === r.id) {
      this.state = { kind: 'idle' };
      if (!s.dragging) {
        this.sink.pointerDown(s.start);
        this.sink.pointerUp(s.start);
        return false;
      }
      this.sink.pointerUp(finite(r.x, r.y) ? point(r) : s.start);
      return true;
    }
    this.release(r.id);
    return false;
  }

  /** A pointer was taken away (pointercancel, or the plan lost its capture): whatever it was part of ends without effect. */
  cancel(id: number): void {
    const s = this.state;
    if (s.kind === 'press' && s.id === id) {
      this.state = { kind: 'idle' };
      if (s.dragging) this.sink.pointerCancel();
      return;
    }
    this.release(id);
  }

  /** A finger of a pinch (or the one left over) went away. */
  private release(id: number): void {
    const s = this.state;
    if (s.kind === 'pinch' && (s.a.id === id || s.b.id === id)) {
      this.sink.pinchEnd();
      this.state = { kind: 'spent', finger: s.a.id === id ? s.b : s.a };
    } else if (s.kind === 'spent' && s.finger.id === id) {
      this.state = { kind: 'idle' };
    }
  }

  /**
   * A wheel turn: zooms about the pointer (lines and pages in pixels); with ctrl, a step of a
   * trackpad pinch about where it began (CTRL_WHEEL_PX_PER_E). A trackpad pinch is ignored while
   * a pointer gesture is in progress.
   */
  wheel(r: WheelRecord): void {
    const dy = wheelPixels(r.deltaY, r.deltaMode);
    if (!finite(r.x, r.y, dy)) return;
    if (!r.ctrlKey) {
      if (this.trackpad?.source === 'wheel') this.endTrackpad();
      this.sink.wheel(point(r), dy);
      return;
    }
    if (this.state.kind !== 'idle' || this.trackpad?.source === 'gesture') return;
    if (!this.trackpad) {
      this.trackpad = { source: 'wheel', at: point(r), sum: 0 };
      this.sink.pinchStart(this.trackpad.at, TRACKPAD_PINCH_SPAN_PX);
    }
    this.trackpad.sum += Math.max(-CTRL_WHEEL_MAX_DELTA_PX, Math.min(CTRL_WHEEL_MAX_DELTA_PX, dy));
    this.sink.pinchMove(this.trackpad.at, TRACKPAD_PINCH_SPAN_PX * Math.exp(-this.trackpad.sum / CTRL_WHEEL_PX_PER_E));
  }

  /** No ctrl+wheel event for WHEEL_PINCH_IDLE_MS: the trackpad pinch they made up is over. */
  wheelPinchEnd(): void {
    if (this.trackpad?.source === 'wheel') this.endTrackpad();
  }

  /** Safari's gesturestart (macOS trackpad pinch): ignored while a pointer gesture is in progress. */
  gestureStart(r: ScaleRecord): void {
    if (this.state.kind !== 'idle' || !finite(r.x, r.y, r.scale)) return;
    this.endTrackpad();
    this.trackpad = { source: 'gesture', at: point(r), sum: 0 };
    this.sink.pinchStart(this.trackpad.at, TRACKPAD_PINCH_SPAN_PX * (r.scale > 0 ? r.scale : 1));
  }

  /** Safari's gesturechange: `scale` is relative to the gesture's start. */
  gestureChange(r: ScaleRecord): void {
    if (this.trackpad?.source !== 'gesture' || !finite(r.scale) || r.scale <= 0) return;
    this.sink.pinchMove(this.trackpad.at, TRACKPAD_PINCH_SPAN_PX * r.scale);
  }

  gestureEnd(): void {
    if (this.trackpad?.source === 'gesture') this.endTrackpad();
  }

  /** Everything in progress ends without effect (the plan element went away): pointerCancel for a drag, pinchEnd for a pinch. */
  abort(): void {
    const s = this.state;
    this.state = { kind: 'idle' };
    if (s.kind === 'press' && s.dragging) this.sink.pointerCancel();
    else if (s.kind === 'pinch') this.sink.pinchEnd();
    this.endTrackpad();
  }

  private endTrackpad(): void {
    if (!this.trackpad) return;
    this.trackpad = null;
    this.sink.pinchEnd();
  }
}
