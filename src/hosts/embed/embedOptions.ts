import { parseAdaptation, type AdaptationSetting } from '../../engines/view/adaptationSetting';
import { readLocal } from './localStore';
import { DEFAULT_BRAND, type Brand } from '../../core/store/uiStore';
import type { LuxboxOptions } from './types';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import { isQualityLevel, QUALITY_LEVEL_NAMES } from '../../engines/relight/qualityLevels';
import { EV100_MAX, EV100_MIN, isEv100 } from '../../engines/view/photographicExposure';
import { EmbedOptionsError, resolveCatalog } from './resolveCatalog';
import { isLocaleTag } from '../../ui/i18n/resolveLocale';

/** options.locale checked: a string must be a BCP 47 tag; a list (navigator.languages) may hold tags resolveLocale skips. */
function checkLocale(locale: unknown): string | readonly string[] | undefined {
  if (locale === undefined) return typeof navigator === 'undefined' ? undefined : navigator.languages;
  if (typeof locale === 'string') {
    if (!isLocaleTag(locale)) throw new EmbedOptionsError(`options.locale: '${locale}' is not a BCP 47 language tag (e.g. 'de-CH')`);
    return locale;
  }
  if (Array.isArray(locale) && locale.every((t) => typeof t === 'string')) return locale;
  throw new EmbedOptionsError("options.locale must be a BCP 47 tag such as 'de-CH' or a list of them");
}

/** The header's brand from options.brand: absent → luxbox, null → none, else a name (1–80 characters) and an optional logo URL. */
function checkBrand(brand: unknown): Brand | null {
  if (brand === undefined) return DEFAULT_BRAND;
  if (brand === null) return null;
  const b = brand as { name?: unknown; logo?: unknown };
  if (typeof brand !== 'object' || typeof b.name !== 'string' || b.name.trim() === '' || b.name.length > 80) {
    throw new EmbedOptionsError('options.brand must be null or { name, logo? } with a name of 1 to 80 characters');
  }
  if (b.logo !== undefined && (typeof b.logo !== 'string' || b.logo === '')) throw new EmbedOptionsError('options.brand.logo must be an image URL');
  return { name: b.name, ...(b.logo !== undefined ? { logo: b.logo as string } : {}) };
}

/** Where the user's Expert switch is kept (option rememberExpert): '1' on, '0' off. */
export const EXPERT_KEY = 'luxbox.expert';

/**
 * options.expert checked: true shows the expert tools (no switch), false hides them (no switch;
 * the default), 'switch' offers the user the switch, off at first unless rememberExpert finds it on.
 */
export function checkExpert(expert: unknown, remember: boolean): { expert: boolean; expertSwitch: boolean } {
  if (expert === undefined || expert === false) return { expert: false, expertSwitch: false };
  if (expert === true) return { expert: true, expertSwitch: false };
  if (expert === 'switch') return { expert: remember && readLocal(EXPERT_KEY) === '1', expertSwitch: true };
  throw new EmbedOptionsError(`options.expert: ${JSON.stringify(expert)} is not true, false or 'switch'`);
}

/** What mountLuxbox takes from its options once they are checked. */
export interface CheckedOptions {
  catalog: Catalog;
  adaptation: AdaptationSetting | undefined;
  brand: Brand | null;
  expert: { expert: boolean; expertSwitch: boolean };
  locale: string | readonly string[] | undefined;
}

/** The element and every option checked: the first bad one throws an EmbedOptionsError, before the element is touched. */
export function checkEmbedOptions(element: Element, options: LuxboxOptions, bundledCatalog: Catalog | undefined): CheckedOptions {
  if (typeof Element === 'undefined' || !(element instanceof Element)) throw new EmbedOptionsError('mountLuxbox needs a DOM element to mount into');
  const catalog = resolveCatalog(options, bundledCatalog);
  if (options.quality !== undefined && !isQualityLevel(options.quality)) throw new EmbedOptionsError(`options.quality: '${String(options.quality)}' is not a quality level (expected ${QUALITY_LEVEL_NAMES.join(', ')})`);
  if (options.exposure !== undefined && options.exposure !== 'auto' && !isEv100(options.exposure)) {
    throw new EmbedOptionsError(`options.exposure: ${JSON.stringify(options.exposure)} is neither 'auto' nor an EV100 number in ${EV100_MIN}..${EV100_MAX}`);
  }
  const adaptation = options.adapt === undefined ? undefined : parseAdaptation(String(options.adapt));
  if (adaptation === null) throw new EmbedOptionsError(`options.adapt: ${JSON.stringify(options.adapt)} is neither 'eye', 'none' nor 'camera:<K>' with K in 1000..20000`);
  if (options.landmarks !== undefined && options.landmarks !== 'page' && options.landmarks !== 'region') {
    throw new EmbedOptionsError(`options.landmarks: ${JSON.stringify(options.landmarks)} is neither 'page' nor 'region'`);
  }
  const brand = checkBrand(options.brand);
  const expert = checkExpert(options.expert, options.rememberExpert === true);
  if (options.apiLanguage !== undefined && options.apiLanguage !== 'ui' && options.apiLanguage !== 'en') {
    throw new EmbedOptionsError(`options.apiLanguage: ${JSON.stringify(options.apiLanguage)} is neither 'ui' nor 'en'`);
  }
  return { catalog, adaptation, brand, expert, locale: checkLocale(options.locale) };
}
