import { useEffect } from 'react';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { UiStore } from '../../core/store/uiStore';
import { ROTATE_STEP } from './BottomBar';
import { deleteTarget } from './deleteTarget';
import { selectionPath } from './selection';

/** Arrow keys move the selected system this far (metres); with Shift, a tenth of it. */
export const KEY_MOVE_STEP = 0.1;

export interface PlannerKeyOptions {
  store: ConfiguratorStore;
  ui: UiStore;
  run: (name: string, params: unknown) => void;
  explain: (reason: string) => void;
  zoom: (factor: number) => void;
  enabled: boolean;
}

function typingIn(target: EventTarget | null): boolean {
  return target instanceof HTMLElement && (target.isContentEditable || /^(INPUT|TEXTAREA|SELECT)$/.test(target.tagName));
}

/**
 * Keyboard use on a desktop: Delete/Backspace, Ctrl+Z / Ctrl+Shift+Z (and Ctrl+Y), arrows move
 * the selected system, R rotates it (Shift+R the other way), + and − zoom, Escape deselects.
 * Keys typed into fields are left to the fields.
 */
export function usePlannerKeys({ store, ui, run, explain, zoom, enabled }: PlannerKeyOptions): void {
  useEffect(() => {
    if (!enabled) return;
    const onKey = (e: KeyboardEvent) => {
      if (typingIn(e.target) || e.altKey) return;
      const st = store.getState();
      const path = selectionPath(st.config, st.selection);
      const mod = e.ctrlKey || e.metaKey;
      const key = e.key.toLowerCase();
      if (mod && key === 'z') {
        e.preventDefault();
        if (!(e.shiftKey ? st.redo() : st.undo())) explain(e.shiftKey ? 'nothing to redo' : 'nothing to undo');
        return;
      }
      if (mod && key === 'y') {
        e.preventDefault();
        if (!st.redo()) explain('nothing to redo');
        return;
      }
      if (mod) return;
      if (e.key === 'Delete' || e.key === 'Backspace') {
        e.preventDefault();
        const t = deleteTarget(path);
        if ('reason' in t) explain(t.reason);
        else run(t.name, t.params);
        return;
      }
      if (e.key === 'Escape') {
        st.select(null);
        ui.setState({ optionsOpen: false });
        return;
      }
      if (e.key === '+' || e.key === '=') return zoom(1.25);
      if (e.key === '-' || e.key === '_') return zoom(0.8);
      const system = st.config.systems.find((s) => s.id === path.systemId);
      if (key === 'r') {
        e.preventDefault();
        if (!system) explain('select a system first');
        else run('rotateSystem', { systemId: system.id, by: e.shiftKey ? -ROTATE_STEP : ROTATE_STEP });
        return;
      }
      const arrows: Record<string, [number, number]> = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] };
      const dir = arrows[e.key];
      if (dir) {
        e.preventDefault();
        if (!system) return explain('select a system first');
        const step = e.shiftKey ? KEY_MOVE_STEP / 10 : KEY_MOVE_STEP;
        // Round to the millimetre so repeated steps do not accumulate float noise.
        const x = dir[0] ? Math.round((system.x + dir[0] * step) * 1000) / 1000 : system.x;
        const z = dir[1] ? Math.round((system.z + dir[1] * step) * 1000) / 1000 : system.z;
        run('moveSystem', { systemId: system.id, x, z });
      }
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [store, ui, run, explain, zoom, enabled]);
}
