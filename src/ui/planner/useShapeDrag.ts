import { useState, type PointerEvent as ReactPointerEvent } from 'react';
import type { PlanPoint } from '../../core/room/planPolygon';
import type { ActionGate } from './actionGate';
import { screenToWorld, type PlanView } from './viewTransform';

/** What the room-shape editor's sheet edits: a wall, a corner or an opening by index. */
export type Picked = { kind: 'wall' | 'corner' | 'opening'; index: number } | null;
export type Dragging = { kind: 'corner'; index: number; at: PlanPoint } | { kind: 'opening'; index: number; offset: number; grab: number } | null;

/** A press that moves less than this (px) is a tap: it picks what it is on instead of dragging it. */
const TAP_PX = 6;

/** The room-shape editor's pointer state: a press becomes a tap (pick) or a drag (one action when it ends). */
export function useShapeDrag(view: PlanView, gate: ActionGate, setPicked: (p: Picked) => void) {
  const [dragging, setDragging] = useState<Dragging>(null);
  const [press, setPress] = useState<{ x: number; y: number; moved: boolean } | null>(null);
  // Where a pointer is on the plan, metres.
  const planPoint = (e: ReactPointerEvent): PlanPoint => {
    const box = (e.currentTarget as HTMLElement).closest('.plan-wrap')!.getBoundingClientRect();
    const w = screenToWorld(view, { sx: e.clientX - box.left, sy: e.clientY - box.top });
    return [w.x, w.z];
  };
  const begin = (e: ReactPointerEvent) => {
    (e.currentTarget as HTMLElement).setPointerCapture?.(e.pointerId);
    setPress({ x: e.clientX, y: e.clientY, moved: false });
  };
  const moved = (e: ReactPointerEvent) => press !== null && (press.moved || Math.hypot(e.clientX - press.x, e.clientY - press.y) > TAP_PX);
  const markMoved = () => setPress((old) => old && { ...old, moved: true });
  const finish = (run: () => string | null, tap: Picked) => {
    if (press && !press.moved) setPicked(tap);
    else {
      const refused = run();
      if (refused) gate.explain(refused);
    }
    setPress(null);
    setDragging(null);
  };
  const cancel = () => (setPress(null), setDragging(null));
  return { dragging, setDragging, planPoint, begin, moved, markMoved, finish, cancel };
}

export type ShapeDrag = ReturnType<typeof useShapeDrag>;
