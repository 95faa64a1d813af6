import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import { findFurnitureItem } from '../../core/model/objects/furniture/furnitureLibrary';
import { furnitureName } from './catalogNames';
import { feedAtText } from './feedText';
import type { Language } from './languages';
import { localName } from './localName';
import type { MessageKey, MessageParams, Translate } from './messageTypes';
import { isMessageKey } from './createTranslator';
import { translateCoded, type CodedMessage } from './translateCoded';

const SOURCES: Record<string, MessageKey> = { 'share link': 'fileErrors.sourceShareLink', 'saved configuration': 'fileErrors.sourceSaved', 'scene file': 'fileErrors.sourceSceneFile' };

/** A feed position parameter ('start', 'end', 'joint:k', 'rail:i'; core feedAtParam) as the FeedAt feedAtText words. */
function feedAt(param: string): unknown {
  const m = /^(joint|rail):(\d+)$/.exec(param);
  if (!m) return param;
  return m[1] === 'joint' ? { joint: Number(m[2]) } : { end: Number(m[2]) };
}

/**
 * The parameters of a core message as the UI words them: a catalog entry named by id (`presetId`,
 * `typeId`, `otherTypeId`, `connectorId`) gets its name in the UI language, a library item
 * (`furnitureId`) its translated name, a wall (`wall`, `wall2`) its word, a feed position
 * (`feedAt`) its phrase; everything else is shown as the core gave it (numbers formatted by `t`).
 */
export function coreParams(t: Translate, language: Language, catalog?: Catalog): (params: MessageParams) => MessageParams {
  return (raw) => {
    const params = { ...raw };
    const id = (key: string) => (typeof params[key] === 'string' ? (params[key] as string) : undefined);
    if (catalog) {
      const preset = catalog.presets.find((p) => p.id === id('presetId'));
      if (preset) params.name = localName(preset, language);
      const type = catalog.moduleTypes.find((m) => m.id === id('typeId'));
      if (type) params.name = localName(type, language);
      const other = catalog.moduleTypes.find((m) => m.id === id('otherTypeId'));
      if (other) params.other = localName(other, language);
      const connector = catalog.connectors.find((c) => c.id === id('connectorId'));
      if (connector) {
        // A connector quoted by id ('connector') or named ('name'): its name in the UI language.
        if (typeof params.connector === 'string') params.connector = localName(connector, language);
        else params.name = localName(connector, language);
      }
    }
    const item = id('furnitureId') !== undefined ? findFurnitureItem(id('furnitureId')!) : undefined;
    if (item) params.name = furnitureName(t, item);
    for (const key of ['wall', 'wall2']) {
      const wall = id(key);
      if (wall && ['north', 'east', 'south', 'west'].includes(wall)) params[key] = t(`planner.wall_${wall}` as MessageKey);
    }
    // A source the core names in English words (a share link, the saved configuration) rather than by a file name.
    const source = id('name') !== undefined ? SOURCES[id('name')!] : undefined;
    if (source && isMessageKey(source)) params.name = t(source);
    const at = id('feedAt');
    if (at !== undefined) params.feedAt = feedAtText(t, feedAt(at));
    return params;
  };
}

/**
 * A coded core message (a refusal, a status notice, a file error) as the planner shows it:
 * `notices.<code>` (or the core's areas, translateCoded) with its params worded by coreParams
 * ("kein freier Platz für „Lange Linie“"); in English, or without a message for its code, the
 * English sentence it carries.
 */
export function noticeText(t: Translate, language: Language, catalog: Catalog | undefined, msg: CodedMessage): string {
  // English shows the core's own sentence, byte for byte what the CLI, logs and the API say (the
  // English messages mirror it; zod's words for a bad field and digit grouping are all that could differ).
  if (language === 'en') return msg.text ?? msg.reason ?? msg.message ?? '';
  return translateCoded(t, 'notices', msg, coreParams(t, language, catalog));
}
