import { useEffect } from 'react';
import type { PlannerController } from './PlannerController';

function typingIn(target: EventTarget | null): boolean {
  return target instanceof HTMLElement && (target.isContentEditable || /^(INPUT|TEXTAREA|SELECT)$/.test(target.tagName));
}

/**
 * Keyboard use on a desktop: every key of the command table (plannerCommands.ts) while
 * `enabled`. Keys typed into fields are left to the fields, and a key no command takes is
 * left to the browser.
 */
export function usePlannerKeys(controller: PlannerController, enabled: boolean): void {
  useEffect(() => {
    if (!enabled) return;
    const onKey = (e: KeyboardEvent) => {
      if (typingIn(e.target)) return;
      if (controller.keyDown({ key: e.key, mod: e.ctrlKey || e.metaKey, shift: e.shiftKey, alt: e.altKey })) e.preventDefault();
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [controller, enabled]);
}
