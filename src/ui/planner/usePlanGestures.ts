import { type RefObject, useLayoutEffect, useRef } from 'react';
import type { PlannerController } from './PlannerController';
import { PlanGestureRecognizer, WHEEL_PINCH_IDLE_MS } from './planGestureRecognizer';

function isControl(target: EventTarget | null): boolean {
  return target instanceof Element && target.closest('button, input, select, label, [data-plan-control]') !== null;
}

/** Safari's GestureEvent (macOS trackpad pinch), which TypeScript's DOM types do not declare. */
interface SafariGestureEvent extends UIEvent {
  readonly scale: number;
  readonly clientX: number;
  readonly clientY: number;
}

/**
 * Listens on the plan element: pointer events, wheel and (Safari) gesture events go to a
 * PlanGestureRecognizer in plan pixels, which hands taps, drags, pinches and wheel turns to the
 * controller. Returns the function that removes the listeners.
 */
function listen(el: HTMLElement, controller: PlannerController): () => void {
  const recognizer = new PlanGestureRecognizer(controller);
  const local = (e: { clientX: number; clientY: number }) => {
    const rect = el.getBoundingClientRect();
    return { x: e.clientX - rect.left, y: e.clientY - rect.top };
  };
  const pointer = (e: PointerEvent) => ({ id: e.pointerId, pointerType: e.pointerType, ...local(e) });
  // A press that became a drag is followed by a click where it was released: the plan's own
  // gesture, not a press on what lies there. Cleared by the next press, so a click is never
  // dropped for a press the plan did not see.
  let dropClick = false;
  let wheelPinchTimer: number | undefined;

  const onPressCapture = () => {
    dropClick = false;
  };
  const onDown = (e: PointerEvent) => {
    if (!recognizer.down({ ...pointer(e), button: e.button, onControl: isControl(e.target) })) return;
    // The plan keeps the pointer while it is pressed, so drags continue outside it. The
    // pointer may already be gone again (a synthetic or very short press): nothing to keep then.
    try {
      el.setPointerCapture(e.pointerId);
    } catch {
      /* pointer no longer active */
    }
  };
  const onMove = (e: PointerEvent) => recognizer.move(pointer(e));
  const onUp = (e: PointerEvent) => {
    if (recognizer.up(pointer(e))) dropClick = true;
  };
  const onCancel = (e: PointerEvent) => recognizer.cancel(e.pointerId);
  // lostpointercapture bubbles: only the plan's own capture counts (after a release it finds nothing to end).
  const onLostCapture = (e: PointerEvent) => {
    if (e.target === el) recognizer.cancel(e.pointerId);
  };
  const onClickCapture = (e: MouseEvent) => {
    if (!dropClick || e.detail === 0) return;
    dropClick = false;
    e.preventDefault();
    e.stopPropagation();
  };
  const onWheel = (e: WheelEvent) => {
    // The plan zooms; neither the page nor (ctrl+wheel, trackpad pinch) the browser's page zoom may.
    e.preventDefault();
    recognizer.wheel({ ...local(e), deltaY: e.deltaY, deltaMode: e.deltaMode, ctrlKey: e.ctrlKey });
    window.clearTimeout(wheelPinchTimer);
    if (recognizer.wheelPinching) wheelPinchTimer = window.setTimeout(() => recognizer.wheelPinchEnd(), WHEEL_PINCH_IDLE_MS);
  };
  const onGesture = (e: Event) => {
    e.preventDefault();
    const g = e as SafariGestureEvent;
    if (e.type === 'gesturestart') recognizer.gestureStart({ ...local(g), scale: g.scale });
    else if (e.type === 'gesturechange') recognizer.gestureChange({ ...local(g), scale: g.scale });
    else recognizer.gestureEnd();
  };

  const listeners: [string, EventListener, AddEventListenerOptions][] = [
    ['pointerdown', onPressCapture as EventListener, { capture: true }],
    ['pointerdown', onDown as EventListener, {}],
    ['pointermove', onMove as EventListener, {}],
    ['pointerup', onUp as EventListener, {}],
    ['pointercancel', onCancel as EventListener, {}],
    ['lostpointercapture', onLostCapture as EventListener, {}],
    ['click', onClickCapture as EventListener, { capture: true }],
    ['wheel', onWheel as EventListener, { passive: false }],
  ];
  // Safari on macOS sends a trackpad pinch as gesture events, not ctrl+wheel. On touch screens
  // (iOS) it sends them for two fingers too, which the pointer events already make a pinch of.
  if ('GestureEvent' in window && !('ontouchstart' in window)) {
    for (const type of ['gesturestart', 'gesturechange', 'gestureend']) listeners.push([type, onGesture, { passive: false }]);
  }
  for (const [type, fn, options] of listeners) el.addEventListener(type, fn, options);
  return () => {
    for (const [type, fn, options] of listeners) el.removeEventListener(type, fn, options);
    window.clearTimeout(wheelPinchTimer);
    // A gesture in progress ends with the listeners, so the controller is not left mid-drag.
    recognizer.abort();
  };
}

/**
 * Mouse, touch and trackpad input on the plan, recognised by planGestureRecognizer and handed to
 * the controller in plan pixels: taps and drags (the controller tells floor from system and moves
 * or pans), wheel, and pinch (two fingers; ctrl+wheel from a trackpad in Chromium and Firefox,
 * Safari's gesture events). Gestures that start on a control (button, field) are left to that
 * control. The plan element keeps `touch-action: none` (app.css) so the browser neither scrolls
 * nor zooms the page under a finger.
 */
export function usePlanGestures(target: RefObject<HTMLElement | null>, controller: PlannerController): void {
  const bound = useRef<{ el: HTMLElement; controller: PlannerController; unlisten: () => void } | null>(null);
  // After every render: the plan element comes and goes with the 2D/3D switch, so the listeners
  // follow whichever element the ref holds now (and are not re-added while it stays the same).
  useLayoutEffect(() => {
    const el = target.current;
    const b = bound.current;
    if (b && b.el === el && b.controller === controller) return;
    b?.unlisten();
    bound.current = el ? { el, controller, unlisten: listen(el, controller) } : null;
  });
  useLayoutEffect(
    () => () => {
      bound.current?.unlisten();
      bound.current = null;
    },
    [],
  );
}
