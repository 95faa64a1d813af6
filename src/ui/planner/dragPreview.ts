import type { LightSystem } from '../../core/model/configuration/configuration';
import type { PlanPoint } from './viewTransform';

/**
 * A system or an object being dragged: drawn offset by `delta` (metres) until dropped; `invalid`
 * where it may not be dropped. A wall item's delta is only the part along its wall.
 */
export type DragPreview = { systemId: string; delta: PlanPoint; invalid: boolean } | { objectId: string; delta: PlanPoint; invalid: boolean } | ModuleDragPreview | FixingDragPreview;

/**
 * A fixing point being dragged along its chain (system level, its system selected): the system as
 * it would be with the point at `s`, the last position moveFixingPoint accepts (snapped to 1 cm);
 * `invalid` while the pointer is at a refused one (the reason is in the status line).
 */
export interface FixingDragPreview {
  fixingIndex: number;
  preview: LightSystem;
  s: number;
  invalid: boolean;
}

/**
 * A module being dragged along its rail: its system as it would be with the module at `offset`,
 * the last position moveModule accepts (snapped); `invalid` while the pointer is at a refused one
 * (the reason is in the status line and the module stays at `offset`).
 */
export interface ModuleDragPreview {
  moduleId: string;
  /** The module's system with the module at `offset` (what the plan draws in its place). */
  preview: LightSystem;
  offset: number;
  invalid: boolean;
}
