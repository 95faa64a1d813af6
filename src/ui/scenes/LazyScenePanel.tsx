import { lazy, Suspense } from 'react';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';

/**
 * The light-scenes section of the side panel (record, recall, GO / BACK and their keys) sits below
 * the presets and the furniture, in the closed drawer on a phone and in the shop embed: its code is
 * a chunk of its own, outside the first screen (docs/benchmarks.md, "First screen"), fetched in idle
 * time like the options panel (LazyOptionsPanel), so it is there by the time anyone scrolls to it.
 */
let loading: Promise<{ default: typeof import('./ScenePanel').ScenePanel }> | null = null;
function loadScenePanel() {
  loading ??= import('./ScenePanel').then((m) => ({ default: m.ScenePanel }));
  return loading;
}

const Panel = lazy(loadScenePanel);

if (typeof window !== 'undefined') {
  const idle = window.requestIdleCallback ?? ((run: () => void) => window.setTimeout(run, 200));
  idle(() => void loadScenePanel().catch(() => undefined));
}

/** ScenePanel, loaded on demand (same props). */
export function LazyScenePanel({ store }: { store: ConfiguratorStore }) {
  return (
    <Suspense fallback={null}>
      <Panel store={store} />
    </Suspense>
  );
}
