/**
 * Aim-at mode (docs/aiming.md): the module that the next tap in the plan or in the 3D view aims
 * (the aimAt action), shared by both views of one configurator store; null: off. Transient UI
 * state, never in the configuration or its history.
 */
import { useSyncExternalStore } from 'react';

export interface AimAtMode {
  /** The module a tap aims now, or null. */
  get(): string | null;
  set(moduleId: string | null): void;
  subscribe(listener: () => void): () => void;
}

const modes = new WeakMap<object, AimAtMode>();

/** The aim-at mode of a configurator store (made on first use). */
export function aimAtMode(store: object): AimAtMode {
  let mode = modes.get(store);
  if (!mode) {
    let moduleId: string | null = null;
    const listeners = new Set<() => void>();
    mode = {
      get: () => moduleId,
      set(next) {
        if (next === moduleId) return;
        moduleId = next;
        for (const l of [...listeners]) l();
      },
      subscribe(listener) {
        listeners.add(listener);
        return () => listeners.delete(listener);
      },
    };
    modes.set(store, mode);
  }
  return mode;
}

/** The module aim-at mode aims now (re-renders when it changes). */
export function useAimAt(store: object): string | null {
  const mode = aimAtMode(store);
  return useSyncExternalStore(mode.subscribe, mode.get, mode.get);
}
