import { lazy, Suspense } from 'react';
import type { Configuration } from '../../core/model/configuration/configuration';
import type { DaylightFactorPartProps } from './DaylightFactorOverlay';

/** The overlay's parts, one chunk (with the work-plane grid's code): fetched when the plan first offers the toggle. */
const Part = lazy(() => import('./DaylightFactorOverlay'));

/** The plan offers the daylight-factor overlay when the configuration lets daylight in through a window (as the 3D view's DF mode). */
export function daylightFactorOffered(config: Configuration): boolean {
  return config.daylight?.on === true && (config.room.shape?.openings ?? []).some((o) => o.kind === 'window');
}

/**
 * A part of the overlay (DaylightFactorOverlay.tsx), loaded on demand: `layer`, the false colour
 * in the plan's SVG; `controls`, the toggle, legend and figures on the plan, the room fitted below
 * its card (`onInsets`), `hidden` while the room-shape editor covers the plan (the map keeps
 * following the edits).
 */
export function LazyDaylightFactor(props: DaylightFactorPartProps) {
  return (
    <Suspense fallback={null}>
      <Part {...props} />
    </Suspense>
  );
}
