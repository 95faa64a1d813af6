import { lazy, Suspense } from 'react';
import type { OptionsPanelProps } from './OptionsPanel';

/**
 * The options panel (settings of the selected part) opens only after the user selects something,
 * so its code (system, rail, module, object options, the colour-filter picker, aiming) is a chunk of
 * its own, outside the first screen (docs/benchmarks.md, "First screen"). The chunk is fetched in
 * idle time once this module is loaded, as the 3D bake service starts in idle time, so the panel
 * normally shows at once on the first selection; before that it renders nothing for the moment the
 * download takes.
 */
let loading: Promise<{ default: typeof import('./OptionsPanel').OptionsPanel }> | null = null;
function loadOptionsPanel() {
  loading ??= import('./OptionsPanel').then((m) => ({ default: m.OptionsPanel }));
  return loading;
}

const Panel = lazy(loadOptionsPanel);

if (typeof window !== 'undefined') {
  // Safari has no requestIdleCallback: a timeout after the first screen's work stands in for it.
  const idle = window.requestIdleCallback ?? ((run: () => void) => window.setTimeout(run, 200));
  idle(() => void loadOptionsPanel().catch(() => undefined));
}

/** OptionsPanel, loaded on demand (same props). */
export function LazyOptionsPanel(props: OptionsPanelProps) {
  return (
    <Suspense fallback={null}>
      <Panel {...props} />
    </Suspense>
  );
}
