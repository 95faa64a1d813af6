import type { CodedText } from '../../core/inputError';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { DragPreview } from './dragPreview';
import type { PlanView, Viewport } from './viewTransform';

/** A refused action as the status line shows it: its code and parameters word it in the UI language (docs/i18n.md). */
export interface RefusalToShow {
  reason: string;
  code?: string;
  params?: Readonly<Record<string, string | number>>;
  detail?: CodedText;
}

/**
 * What the plan's gestures (the drags, furniture placement) use of the PlannerController: the
 * store, the view they started under, the drag preview and the way actions are run and refused.
 */
export interface PlannerGestureHost {
  readonly store: ConfiguratorStore;
  readonly view: PlanView;
  readonly viewport: Viewport;
  readonly drag: DragPreview | null;
  setDrag(drag: DragPreview | null): void;
  explainRefusal(r: RefusalToShow): void;
  run(name: string, params: unknown): void;
}
