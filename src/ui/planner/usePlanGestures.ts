import { type RefObject, useLayoutEffect, useRef } from 'react';
import type { PlanGestureSink } from './planGestureListener';

export type { PlanGestureSink } from './planGestureListener';

type ListenerModule = typeof import('./planGestureListener');
let listenerModule: Promise<ListenerModule> | null = null;
/** The chunk once it is there: later plan elements listen at once, in the layout effect. */
let loaded: ListenerModule | null = null;

/**
 * @use-gesture is a lazy chunk (7.3 kB gzip that the first screen cannot carry; docs/benchmarks.md,
 * "First screen"), requested when the first plan mounts, so it arrives while the plan is first
 * drawn. A failed request (offline) is asked again by the next plan element.
 */
export function loadPlanGestures(): Promise<ListenerModule> {
  listenerModule ??= import('./planGestureListener').then(
    (m) => (loaded = m),
    (error: unknown) => {
      listenerModule = null;
      throw error;
    },
  );
  return listenerModule;
}

interface Binding {
  readonly el: HTMLElement;
  readonly controller: PlanGestureSink;
  unlisten(): void;
}

/** The element listens now if the chunk is there, else once it arrives (if it is still the plan's element then). */
function bind(el: HTMLElement, controller: PlanGestureSink, isCurrent: (b: Binding) => boolean): Binding {
  const binding: Binding = { el, controller, unlisten: () => undefined };
  const listen = ({ listenToPlanGestures }: ListenerModule) => {
    binding.unlisten = listenToPlanGestures(el, controller);
  };
  if (loaded) listen(loaded);
  else {
    loadPlanGestures().then(
      (m) => {
        if (isCurrent(binding)) listen(m);
      },
      () => undefined, // offline: the plan stays still; the next plan element asks again
    );
  }
  return binding;
}

/**
 * Mouse, touch and trackpad input on the plan, recognised by @use-gesture and handed to the
 * controller in plan pixels (planGestureListener.ts). The plan element keeps `touch-action: none`
 * (app.css) so the browser neither scrolls nor zooms the page under a finger, and carries
 * `data-gestures="ready"` once it listens (until the chunk is there, a press does nothing).
 */
export function usePlanGestures(target: RefObject<HTMLElement | null>, controller: PlanGestureSink): void {
  const bound = useRef<Binding | null>(null);
  // After every render: the plan element comes and goes with the 2D/3D switch, so the listeners
  // follow whichever element the ref holds now (and are not re-added while it stays the same).
  useLayoutEffect(() => {
    const el = target.current;
    const b = bound.current;
    if (b && b.el === el && b.controller === controller) return;
    b?.unlisten();
    bound.current = el ? bind(el, controller, (binding) => bound.current === binding) : null;
  });
  useLayoutEffect(
    () => () => {
      bound.current?.unlisten();
      bound.current = null;
    },
    [],
  );
}
