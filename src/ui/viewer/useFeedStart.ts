import { useEffect } from 'react';
import type { BakeHost } from './bakeHost';
import type { BakeFeed } from './startBakeFeed';

/** The bake service: running already (started in idle time after the planner showed), or started now; `fail` hears why it could not start. */
export function useFeedStart(host: BakeHost, feed: BakeFeed | null, setFeed: (feed: BakeFeed) => void, fail: (message: string) => void): void {
  useEffect(() => {
    if (feed) return;
    let cancelled = false;
    host
      .get()
      .then((f) => !cancelled && setFeed(f))
      .catch((e: Error) => {
        if (cancelled) return;
        fail(`The 3D view could not start: ${e.message}`);
      });
    return () => {
      cancelled = true;
    };
    // eslint-disable-next-line react-hooks/exhaustive-deps
  }, [host, feed]);
}
