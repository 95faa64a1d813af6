import { useGesture } from '@use-gesture/react';
import type { RefObject } from 'react';
import type { PlannerController } from './PlannerController';
import type { ScreenPoint } from './viewTransform';

function isControl(target: EventTarget | null): boolean {
  return target instanceof Element && target.closest('button, input, select, label, [data-plan-control]') !== null;
}

/**
 * Mouse, touch and trackpad input on the plan, recognised by @use-gesture and handed to the
 * controller in plan pixels: drags (the controller tells floor from system and moves or
 * pans), wheel, and pinch (ctrl+wheel from a trackpad arrives as a pinch). Gestures that start
 * on a control (button, field) are left to that control.
 */
export function usePlanGestures(target: RefObject<HTMLElement | null>, controller: PlannerController): void {
  const local = ([clientX, clientY]: readonly [number, number]): ScreenPoint => {
    const rect = target.current?.getBoundingClientRect();
    return { sx: clientX - (rect?.left ?? 0), sy: clientY - (rect?.top ?? 0) };
  };

  useGesture(
    {
      onDrag: ({ first, last, tap, pinching, cancel, event, xy, initial, memo }) => {
        if (pinching) {
          cancel();
          controller.pointerCancel();
          return undefined;
        }
        // memo: whether this drag is the plan's (false: it started on a control).
        const mine = first || memo === undefined ? !isControl(event.target) : (memo as boolean);
        if (!mine) return mine;
        // @use-gesture reports a drag only once it passes its tap threshold, and a tap once, at
        // the end: replay both as the press and the pointer positions the controller expects.
        if (tap) {
          controller.pointerDown(local(initial));
          controller.pointerUp(local(initial));
          return mine;
        }
        if (first) controller.pointerDown(local(initial));
        if (last) controller.pointerUp(local(xy));
        else controller.pointerMove(local(xy));
        return mine;
      },
      onPinch: ({ first, last, memo, da, origin, event }) => {
        if (first && isControl(event.target)) return undefined;
        if (first || !memo) controller.pinchStart(local(origin), da[0]);
        controller.pinchMove(local(origin), da[0]);
        if (last) controller.pinchEnd();
        return true;
      },
      onWheel: ({ event, delta: [, dy], ctrlKey }) => {
        if (ctrlKey) return; // trackpad pinch arrives as ctrl+wheel and is handled by onPinch
        event.preventDefault();
        const we = event as WheelEvent;
        // delta, not the event's deltaY: @use-gesture has turned lines and pages into pixels, and
        // its closing call (after the wheel stops) repeats the last event with a zero delta.
        controller.wheel(local([we.clientX, we.clientY]), dy);
      },
    },
    {
      target,
      eventOptions: { passive: false },
      drag: { filterTaps: true, pointer: { touch: true } },
      pinch: { rubberband: false },
    },
  );
}
