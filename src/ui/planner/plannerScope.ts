import type { RefObject } from 'react';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import type { BillOfMaterials } from '../../core/model/power/billOfMaterials';
import type { InstallationNeeds } from '../../core/model/power/installationNeeds';
import type { Selection } from '../../core/store/createConfiguratorStore';
import type { UiState } from '../../core/store/uiStore';
import type { I18nValue } from '../i18n/createI18n';
import type { ActionGate } from './actionGate';
import type { DragPreview } from './dragPreview';
import type { PlannerProps } from './Planner';
import type { PlannerController } from './PlannerController';
import type { SelectionPath } from './selection';
import type { PlanView, Viewport } from './viewTransform';

/**
 * What the planner's parts (PlannerHeader, PlanPane, PlannerSidePanel) share: its props, the
 * language, the UI state and the configuration it follows and what it derived from them. One object,
 * so the parts read what the Planner already subscribed to (the first screen pays for no second copy).
 */
export interface PlannerScope extends PlannerProps, UiState, I18nValue {
  config: Configuration;
  catalog: Catalog;
  controller: PlannerController;
  view: PlanView;
  viewport: Viewport;
  drag: DragPreview | null;
  gate: ActionGate;
  path: SelectionPath;
  selection: Selection;
  select: (sel: Selection) => void;
  bom: BillOfMaterials;
  needs: InstallationNeeds;
  wrapRef: RefObject<HTMLDivElement | null>;
  panelRef: RefObject<HTMLElement | null>;
  /** A system was just placed: it is selected and the drawer closes to show it. */
  placedNew: () => void;
}
