import { lazy, Suspense, type ComponentProps } from 'react';

/**
 * The on-plan distribution pictures load with their texts when a rail is first selected at the
 * module level (the options panel's chunk shares them): not part of the first screen's download.
 */
const Buttons = lazy(() => import('./DistributionButtons'));

/** DistributionButtons, loaded on demand (same props). */
export function LazyDistributionButtons(props: ComponentProps<typeof import('./DistributionButtons').default>) {
  return (
    <Suspense fallback={null}>
      <Buttons {...props} />
    </Suspense>
  );
}
