import type { AimLimits } from '../../../core/model/modules/aim';
import type { ModuleAim } from '../../../core/model/configuration/configuration';
import { draggedAim } from '../spotlightPose';

export interface HeadDragHooks {
  /** The aim shown now and the limits it keeps to, or null when no module is in the view (no drag starts). */
  current(): { aim: ModuleAim; limits: AimLimits } | null;
  /** The camera's vertical field of view, degrees. */
  fov(): number;
  /** The drag moved the head to a new aim. */
  moved(next: ModuleAim): void;
  /** The drag ended (released or cancelled); `start` is the aim it began at. */
  released(start: ModuleAim): void;
}

export interface HeadDrag {
  dragging(): boolean;
  /** Forget the drag under way (the view was left). */
  cancel(): void;
  dispose(): void;
}

/** Dragging the head (mouse or one finger) in the spotlight view: pan and tilt from the drag's start (draggedAim, spotlightPose.ts). */
export function watchHeadDrag(canvas: HTMLCanvasElement, hooks: HeadDragHooks): HeadDrag {
  let drag: { id: number; x: number; y: number; start: ModuleAim } | null = null;
  const ndcHeight = () => Math.max(1, canvas.getBoundingClientRect().height);
  const onDown = (e: PointerEvent) => {
    const now = hooks.current();
    if (!now || drag || (e.pointerType === 'mouse' && e.button !== 0)) return;
    drag = { id: e.pointerId, x: e.clientX, y: e.clientY, start: now.aim };
    canvas.setPointerCapture?.(e.pointerId);
  };
  const onMove = (e: PointerEvent) => {
    const now = hooks.current();
    if (!drag || e.pointerId !== drag.id || !now) return;
    const next = draggedAim(drag.start, e.clientX - drag.x, e.clientY - drag.y, hooks.fov(), ndcHeight(), now.limits);
    if (next.rotation === now.aim.rotation && next.tilt === now.aim.tilt) return;
    hooks.moved(next);
  };
  const onUp = (e: PointerEvent) => {
    if (!drag || e.pointerId !== drag.id || !hooks.current()) return;
    // The release's own position counts: the last move before it may have been coalesced away.
    if (e.type !== 'pointercancel') onMove(e);
    const start = drag.start;
    drag = null;
    hooks.released(start);
  };
  canvas.addEventListener('pointerdown', onDown);
  canvas.addEventListener('pointermove', onMove);
  canvas.addEventListener('pointerup', onUp);
  canvas.addEventListener('pointercancel', onUp);
  return {
    dragging: () => drag !== null,
    cancel() {
      drag = null;
    },
    dispose() {
      canvas.removeEventListener('pointerdown', onDown);
      canvas.removeEventListener('pointermove', onMove);
      canvas.removeEventListener('pointerup', onUp);
      canvas.removeEventListener('pointercancel', onUp);
    },
  };
}
