import type { ActionName } from '../../core/model/actions/actionDefinitions';
import type { SelectionPath } from './selection';

/**
 * What Delete removes for a selection: the module, the rail (any: a middle one splits the chain), the whole system, or the
 * selected object. null with a reason when nothing is selected. The action's own isEnabled
 * still decides.
 */
export function deleteTarget(path: SelectionPath): { name: ActionName; params: Record<string, string> } | { reason: string } {
  if (path.objectId) return { name: 'removeObject', params: { objectId: path.objectId } };
  if (path.moduleId) return { name: 'removeModule', params: { moduleId: path.moduleId } };
  if (path.railId) return { name: 'removeRail', params: { railId: path.railId } };
  if (path.systemId) return { name: 'deleteSystem', params: { systemId: path.systemId } };
  return { reason: 'select a system, a module or an object first' };
}
