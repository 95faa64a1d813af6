import type { Catalog } from '../../core/model/catalogSchema';
import type { Language } from './languages';
import { localName } from './localName';
import type { MessageParams, Translate } from './messageTypes';
import { translateCoded } from './translateCoded';

/**
 * A coded core message (a refusal, a status notice) as the planner shows it: `notices.<code>` with
 * its params, where a catalog entry named by id (`presetId`, `typeId`) is given its name in the
 * UI language ("kein freier Platz für „Lange Linie“"); else the English sentence it carries.
 */
export function noticeText(t: Translate, language: Language, catalog: Catalog, msg: { reason?: string; text?: string; code?: string; params?: Readonly<MessageParams> }): string {
  const params: MessageParams | undefined = msg.params ? { ...msg.params } : undefined;
  if (params && typeof params.presetId === 'string') {
    const preset = catalog.presets.find((p) => p.id === params.presetId);
    if (preset) params.name = localName(preset, language);
  }
  if (params && typeof params.typeId === 'string') {
    const type = catalog.moduleTypes.find((m) => m.id === params.typeId);
    if (type) params.name = localName(type, language);
  }
  return translateCoded(t, 'notices', { text: msg.text, reason: msg.reason, code: msg.code, params });
}
