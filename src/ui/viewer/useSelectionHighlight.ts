import { useEffect, type RefObject } from 'react';
import type { Selection } from '../../core/store/createConfiguratorStore';
import type { ViewerController } from '../../engines/view/createViewerController';
import type { BakeFeed } from './startBakeFeed';

/** The selected object or module is highlighted in 3D too (the plan and the view share the store's selection); again once the feed's controller is made. */
export function useSelectionHighlight(controllerRef: RefObject<ViewerController | null>, selection: Selection, feed: BakeFeed | null): void {
  useEffect(() => {
    controllerRef.current?.setSelection(selection);
  }, [controllerRef, selection, feed]);
}
