import { useEffect, useLayoutEffect, useRef, type RefObject } from 'react';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { ViewerController } from '../../engines/view/createViewerController';
import { CLOSED_STATUS, setViewerStatus, type ViewerStatus } from './viewerStatus';

/** The 3D view's status record (viewerStatus.ts) and what its first-lit timing counts from. */
export interface ViewerStatusRecord {
  status: RefObject<ViewerStatus>;
  /** When the view was last shown (firstLitMs counts from there). */
  mountedAt: RefObject<number>;
  /** The controller's frame count when the view was last shown (firstLitFrame counts from there). */
  framesAtShow: RefObject<number>;
  visibleRef: RefObject<boolean>;
  /** Merge a patch into the record; hosts see it while the view is shown. */
  publish(patch: Partial<ViewerStatus>): void;
}

/**
 * The view's status for hosts: closed on unmount; a new opening each time it is shown (lit on its
 * first frame when the maps are there), closed and without frames while hidden behind the plan.
 */
export function useViewerStatus(store: ConfiguratorStore, visible: boolean, controllerRef: RefObject<ViewerController | null>, wrapRef: RefObject<HTMLDivElement | null>): ViewerStatusRecord {
  const status = useRef<ViewerStatus>({ ...CLOSED_STATUS, open: true });
  const mountedAt = useRef(0);
  const framesAtShow = useRef(0);
  const visibleRef = useRef(visible);
  const unmounted = useRef(false);

  // The view's own record is kept while it is hidden behind the plan; hosts see a closed view then.
  const publish = (patch: Partial<ViewerStatus>) => {
    if (unmounted.current) return; // late events after unmount
    status.current = { ...status.current, ...patch };
    if (visibleRef.current) setViewerStatus(store, status.current);
  };

  useEffect(() => {
    unmounted.current = false;
    return () => {
      unmounted.current = true;
      status.current = { ...CLOSED_STATUS };
      setViewerStatus(store, status.current);
    };
  }, [store]);

  // Shown (first mount or back from the plan): a new opening, lit on its first frame when the maps are there; hidden: closed, no frames.
  // A layout effect, so the status changes with the screen: React flushes passive effects of a click
  // before the next event, preact (the browser build) only after the next frame.
  useLayoutEffect(() => {
    visibleRef.current = visible;
    if (visible) {
      mountedAt.current = performance.now();
      framesAtShow.current = status.current.frames;
      status.current = { ...status.current, open: true, lit: false, firstLitMs: null, firstLitFrame: null };
      setViewerStatus(store, status.current);
      const wrap = wrapRef.current;
      const r = wrap?.getBoundingClientRect();
      if (r && r.width > 0 && r.height > 0) controllerRef.current?.resize(Math.round(r.width), Math.round(r.height));
      controllerRef.current?.setActive(true);
    } else {
      controllerRef.current?.setActive(false);
      setViewerStatus(store, { ...CLOSED_STATUS });
    }
  }, [visible, store, controllerRef, wrapRef]);

  return { status, mountedAt, framesAtShow, visibleRef, publish };
}
