import { lazy, Suspense } from 'react';
import type { Configuration } from '../../core/model/configuration/configuration';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';

/** The overlay's two parts, one chunk (with the work-plane grid's code): fetched when the plan first offers the toggle. */
const chunk = () => import('./DaylightFactorOverlay');
const Layer = lazy(() => chunk().then((m) => ({ default: m.DaylightFactorLayer })));
const Controls = lazy(() => chunk().then((m) => ({ default: m.DaylightFactorControls })));

/** The plan offers the daylight-factor overlay when the configuration lets daylight in through a window (as the 3D view's DF mode). */
export function daylightFactorOffered(config: Configuration): boolean {
  return config.daylight?.on === true && (config.room.shape?.openings ?? []).some((o) => o.kind === 'window');
}

/** The false-colour layer in the plan's SVG (DaylightFactorOverlay.tsx), loaded on demand. */
export function LazyDaylightFactorLayer({ store }: { store: ConfiguratorStore }) {
  return (
    <Suspense fallback={null}>
      <Layer store={store} />
    </Suspense>
  );
}

/** The toggle, legend and statistics on the plan (DaylightFactorOverlay.tsx), loaded on demand; the room is fitted below its card (`onInsets`); `hidden` while the room-shape editor covers the plan (the map keeps following the edits). */
export function LazyDaylightFactorControls(props: { store: ConfiguratorStore; hidden: boolean; onInsets: (top: number, bottom: number) => void }) {
  return (
    <Suspense fallback={null}>
      <Controls {...props} />
    </Suspense>
  );
}
