import { lazy, Suspense, useState } from 'react';
import { ImportPicker } from './ImportPicker';
import type { ImportPanelProps } from './ImportPanel';

/**
 * The model import section (ImportPanel: reading the files, the preview, the units) is a chunk of
 * its own, outside the first screen (docs/benchmarks.md, "First screen"); until it arrives its
 * button and hint show in its place, in the same markup. Files picked meanwhile are handed to the
 * panel when it mounts, so an early pick is read as any other.
 */
let loading: Promise<{ default: typeof import('./ImportPanel').ImportPanel }> | null = null;
function loadImportPanel() {
  loading ??= import('./ImportPanel').then((m) => ({ default: m.ImportPanel }));
  return loading;
}

const Panel = lazy(loadImportPanel);

/** ImportPanel, loaded on demand (same props). */
export function LazyImportPanel({ onAdd }: Pick<ImportPanelProps, 'onAdd'>) {
  const [picked, setPicked] = useState<File[] | null>(null);
  const waiting = (
    <div className="import-model" data-testid="import-panel">
      <ImportPicker onPick={setPicked} />
    </div>
  );
  return (
    <Suspense fallback={waiting}>
      <Panel onAdd={onAdd} {...(picked ? { picked } : {})} />
    </Suspense>
  );
}
