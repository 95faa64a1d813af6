import en from './messages/en/index';
import type { MessageKey, MessageParams, MessageTree, PluralMessage, Translate } from './messageTypes';

type Lookup = Record<string, Record<string, string | PluralMessage>>;

function lookup(tree: Partial<MessageTree>, key: string): string | PluralMessage | undefined {
  const dot = key.indexOf('.');
  if (dot < 0) return undefined;
  return (tree as unknown as Lookup)[key.slice(0, dot)]?.[key.slice(dot + 1)];
}

/**
 * Whether `key` names an English message: for keys built at run time from a stable code
 * (a core refusal's `code`, a catalog item's id), so that an unknown code falls back to the
 * English sentence the core wrote instead of showing a key.
 */
export function isMessageKey(key: string): key is MessageKey {
  return lookup(en, key) !== undefined;
}

/**
 * The `t` of one language: looks `area.key` up in `tree` (English when a key is missing, which
 * tsc already prevents for the bundled languages), picks a plural form by `params.count` with
 * the locale's Intl.PluralRules, and fills `{name}` placeholders (numbers formatted for the
 * locale, e.g. 2.5 → "2,5" in German). A placeholder without a value stays visible as `{name}`
 * so a missing parameter is noticed, never silently dropped.
 */
export function createTranslator(tree: Partial<MessageTree>, locale: string, formatNumber: (x: number) => string): Translate {
  let plurals: Intl.PluralRules | null = null;
  return (key, params) => {
    const value = lookup(tree, key) ?? lookup(en, key);
    if (value === undefined) return key;
    let text: string;
    if (typeof value === 'string') text = value;
    else {
      plurals ??= new Intl.PluralRules(locale);
      const count = Number(params?.count ?? 0);
      text = value[plurals.select(Number.isFinite(count) ? count : 0)] ?? value.other;
    }
    if (!params) return text;
    return text.replace(/\{(\w+)\}/g, (whole, name: string) => {
      const p = (params as MessageParams)[name];
      if (p === undefined) return whole;
      return typeof p === 'number' ? formatNumber(p) : p;
    });
  };
}
