import { useGesture } from '@use-gesture/react';
import type { RefObject } from 'react';
import { type PlanPoint, type PlanView, panBy, screenToWorld, wheelZoomFactor, zoomAt } from './viewTransform';
import type { PlanViewControls } from './usePlanView';

export interface PlanGestureHandlers {
  /** A system is being dragged: the world-space offset from where the drag started. */
  onSystemDrag: (systemId: string, delta: PlanPoint) => void;
  /** The drag ended: commit the offset as one undoable action. */
  onSystemDrop: (systemId: string, delta: PlanPoint) => void;
  /** A tap (no drag) on a system, or on empty plan (null). */
  onTap: (systemId: string | null) => void;
}

type DragMemo = { mode: 'pan'; last: [number, number] } | { mode: 'system'; id: string; startView: PlanView } | { mode: 'none' };

/** Which system, if any, an event started on (elements carry data-system-id). */
function systemIdAt(target: EventTarget | null): string | null {
  const el = target instanceof Element ? target.closest('[data-system-id]') : null;
  return el?.getAttribute('data-system-id') ?? null;
}

function isControl(target: EventTarget | null): boolean {
  return target instanceof Element && target.closest('button, input, select, label, [data-plan-control]') !== null;
}

/**
 * Mouse, touch and trackpad navigation of the plan with @use-gesture: drag the background to
 * pan, drag a system to move it, wheel / pinch / ctrl+wheel to zoom about the pointer, and two
 * fingers to pan while pinching (the pinch origin carries the anchored world point). Gestures
 * that start on a control (button, field) are left to that control.
 */
export function usePlanGestures(target: RefObject<HTMLElement | null>, plan: PlanViewControls, handlers: PlanGestureHandlers): void {
  const local = (clientX: number, clientY: number): { sx: number; sy: number } => {
    const rect = target.current?.getBoundingClientRect();
    return { sx: clientX - (rect?.left ?? 0), sy: clientY - (rect?.top ?? 0) };
  };

  useGesture(
    {
      onDrag: (state) => {
        const { first, last, tap, pinching, cancel, event, xy, movement } = state;
        if (pinching) {
          cancel();
          return undefined;
        }
        let memo = state.memo as DragMemo | undefined;
        if (first || !memo) {
          if (isControl(event.target)) memo = { mode: 'none' };
          else {
            const id = systemIdAt(event.target);
            memo = id ? { mode: 'system', id, startView: plan.targetRef.current } : { mode: 'pan', last: xy };
          }
        }
        if (tap) {
          if (memo.mode !== 'none') handlers.onTap(memo.mode === 'system' ? memo.id : null);
          return memo;
        }
        if (memo.mode === 'pan') {
          plan.jumpTo(panBy(plan.targetRef.current, xy[0] - memo.last[0], xy[1] - memo.last[1]));
          return { mode: 'pan', last: xy } satisfies DragMemo;
        }
        if (memo.mode === 'system') {
          const delta = { x: movement[0] / memo.startView.scale, z: movement[1] / memo.startView.scale };
          if (last) handlers.onSystemDrop(memo.id, delta);
          else handlers.onSystemDrag(memo.id, delta);
        }
        return memo;
      },
      onPinch: (state) => {
        const { first, memo, da, origin, event } = state;
        if (first && isControl(event.target)) return undefined;
        const anchorScreen = local(origin[0], origin[1]);
        // The zoom factor is the ratio of finger distances since the pinch began (da[0] is the
        // current distance), so it does not depend on offsets accumulated by earlier pinches.
        const start = (first || !memo
          ? { view: plan.targetRef.current, world: screenToWorld(plan.targetRef.current, anchorScreen), d0: Math.max(1, da[0]) }
          : memo) as { view: PlanView; world: PlanPoint; d0: number };
        const scaled = zoomAt(start.view, anchorScreen, Math.max(1, da[0]) / start.d0);
        // Put the world point that started under the fingers back under them: two-finger pan.
        const drift = { dx: anchorScreen.sx - (start.world.x * scaled.scale + scaled.offsetX), dy: anchorScreen.sy - (start.world.z * scaled.scale + scaled.offsetY) };
        plan.jumpTo(panBy(scaled, drift.dx, drift.dy));
        return start;
      },
      onWheel: ({ event, delta: [, dy], ctrlKey }) => {
        if (ctrlKey) return; // trackpad pinch arrives as ctrl+wheel and is handled by onPinch
        event.preventDefault();
        const we = event as WheelEvent;
        // deltaMode 1 = lines, 2 = pages (Firefox); normalise to pixels.
        const px = we.deltaMode === 1 ? dy * 16 : we.deltaMode === 2 ? dy * 400 : dy;
        plan.zoomBy(wheelZoomFactor(px), local(we.clientX, we.clientY));
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
