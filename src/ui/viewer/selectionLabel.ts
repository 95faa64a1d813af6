import type { Configuration } from '../../core/model/configuration/configuration';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import { findFurnitureItem } from '../../core/model/objects/furniture/furnitureLibrary';
import { sourceName } from '../../core/model/objects/objectGeometry';
import type { Selection } from '../../core/store/createConfiguratorStore';
import { furnitureName } from '../i18n/catalogNames';
import type { Language } from '../i18n/languages';
import { localName } from '../i18n/localName';
import type { Translate } from '../i18n/messageTypes';

/**
 * The selected object's or module's name for the panel ('Selected: …') as a shopper knows it: a
 * library piece by its name in the UI language, an imported model by its file name, a module by
 * its catalog type's name (never an id); null when nothing of those is selected.
 */
export function selectionLabel(t: Translate, language: Language, catalog: Catalog, config: Configuration, selection: Selection): string | null {
  if (!selection) return null;
  if (selection.kind === 'object') {
    const o = config.objects.find((x) => x.id === selection.id);
    if (!o) return null;
    const item = o.source.kind === 'library' ? findFurnitureItem(o.source.item) : undefined;
    return item ? furnitureName(t, item) : sourceName(config, o.source);
  }
  if (selection.kind === 'module') {
    for (const s of config.systems) {
      for (const r of s.rails) {
        for (const m of r.modules) {
          if (m.id !== selection.id) continue;
          const type = catalog.moduleTypes.find((x) => x.id === m.type);
          return t('view3d.selectedModule', { type: type ? localName(type, language) : m.type });
        }
      }
    }
  }
  return null;
}
