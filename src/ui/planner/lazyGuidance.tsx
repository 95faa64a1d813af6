import { lazy, Suspense, type ComponentProps } from 'react';

/**
 * The guidance chunk (guidance.ts: the empty plan's first step, a refused control's tip and its
 * remedy), loaded when first needed: it is not part of the first screen's download.
 */
const View = lazy(() => import('./guidance').then((m) => ({ default: m.GuidanceView })));

/** guidance.ts's GuidanceView, loaded on demand (same props). */
export function LazyGuidance(props: ComponentProps<typeof import('./guidance').GuidanceView>) {
  return (
    <Suspense fallback={null}>
      <View {...props} />
    </Suspense>
  );
}
