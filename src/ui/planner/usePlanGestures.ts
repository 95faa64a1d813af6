import { useGesture } from '@use-gesture/react';
import type { RefObject } from 'react';
import { type PlanPoint, type PlanView, panBy, screenToWorld, wheelZoomFactor, zoomAt } from './viewTransform';
import type { PlanViewControls } from './usePlanView';

export interface PlanGestureHandlers {
  /** A system is being dragged: the world-space offset from where the drag started. */
  onSystemDrag: (systemId: string, delta: PlanPoint) => void;
  /** The drag ended: commit the offset as one undoable action. */
  onSystemDrop: (systemId: string, delta: PlanPoint) => void;
  /** A tap (no drag): what was under the pointer (all undefined on empty plan). */
  onTap: (hit: PlanHit) => void;
}

export interface PlanHit {
  systemId?: string;
  railId?: string;
  moduleId?: string;
}

type DragMemo = { mode: 'pan'; last: [number, number] } | { mode: 'system'; id: string; startView: PlanView; hit: PlanHit } | { mode: 'none' };

/** What an event started on: plan elements carry data-system-id / data-rail-id / data-module-id. */
function hitAt(target: EventTarget | null): PlanHit {
  if (!(target instanceof Element)) return {};
  const attr = (name: string) => target.closest(`[${name}]`)?.getAttribute(name) ?? undefined;
  return { systemId: attr('data-system-id'), railId: attr('data-rail-id'), moduleId: attr('data-module-id') };
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
            const hit = hitAt(event.target);
            memo = hit.systemId ? { mode: 'system', id: hit.systemId, startView: plan.targetRef.current, hit } : { mode: 'pan', last: xy };
          }
        }
        if (tap) {
          if (memo.mode !== 'none') handlers.onTap(memo.mode === 'system' ? memo.hit : {});
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
