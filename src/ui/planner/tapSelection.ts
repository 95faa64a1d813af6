import type { Selection } from '../../core/store/createConfiguratorStore';
import { detailLevel } from './detailLevel';
import type { PlanHit } from './planHitTest';

/**
 * What a tap on `hit` selects at the view's `scale`. Like the controls, it follows the zoom
 * level: whole systems when zoomed out, rails and modules when zoomed in. A tap on the floor
 * deselects (null).
 */
export function tapSelection(hit: PlanHit, scale: number): Selection {
  if (hit.objectId) return { kind: 'object', id: hit.objectId };
  if (!hit.systemId) return null;
  const zoomedIn = detailLevel(scale) === 'module';
  if (zoomedIn && hit.moduleId) return { kind: 'module', id: hit.moduleId };
  if (zoomedIn && hit.railId) return { kind: 'rail', id: hit.railId };
  return { kind: 'system', id: hit.systemId };
}
