import type { Configuration } from '../../core/model/configuration/configuration';
import type { Selection } from '../../core/store/createConfiguratorStore';

/**
 * The store's selection ({kind, id}, outside the undo history) expanded to the chain of ids
 * the plan needs for highlighting: a selected module also marks its rail and system. A
 * selected object (furniture, an imported model) stands alone.
 */
export interface SelectionPath {
  systemId?: string;
  railId?: string;
  moduleId?: string;
  objectId?: string;
}

export function selectionPath(config: Configuration, sel: Selection): SelectionPath {
  if (!sel) return {};
  if (sel.kind === 'object') return config.objects.some((o) => o.id === sel.id) ? { objectId: sel.id } : {};
  for (const s of config.systems) {
    if (sel.kind === 'system' && s.id === sel.id) return { systemId: s.id };
    for (const r of s.rails) {
      if (sel.kind === 'rail' && r.id === sel.id) return { systemId: s.id, railId: r.id };
      for (const m of r.modules) if (sel.kind === 'module' && m.id === sel.id) return { systemId: s.id, railId: r.id, moduleId: m.id };
    }
  }
  return {};
}
