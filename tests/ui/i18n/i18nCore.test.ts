import { describe, expect, it } from 'vitest';
import { createFormat } from '../../../src/ui/i18n/createFormat';
import { createI18n } from '../../../src/ui/i18n/createI18n';
import { localeForLanguage, resolveLocale } from '../../../src/ui/i18n/resolveLocale';
import { createTranslator, isMessageKey } from '../../../src/ui/i18n/createTranslator';
import type { MessageTree } from '../../../src/ui/i18n/messageTypes';
import en from '../../../src/ui/i18n/messages/en/index';

describe('resolveLocale', () => {
  it('takes the first supported primary subtag and keeps the full tag for formatting', () => {
    expect(resolveLocale('de-CH')).toEqual({ language: 'de', locale: 'de-CH' });
    expect(resolveLocale(['es-ES', 'fr-BE', 'de'])).toEqual({ language: 'fr', locale: 'fr-BE' });
    expect(resolveLocale('IT-ch')).toEqual({ language: 'it', locale: 'it-CH' });
  });
  it('falls back to English, formatted for the first valid tag, and skips tags Intl rejects', () => {
    expect(resolveLocale(['es-ES', 'nl'])).toEqual({ language: 'en', locale: 'es-ES' });
    expect(resolveLocale(['not a tag!!', 'de-AT'])).toEqual({ language: 'de', locale: 'de-AT' });
    expect(resolveLocale(undefined)).toEqual({ language: 'en', locale: 'en' });
    expect(resolveLocale([])).toEqual({ language: 'en', locale: 'en' });
  });
  it('keeps the region when the user switches language', () => {
    expect(localeForLanguage('fr', 'de-CH')).toBe('fr-CH');
    expect(localeForLanguage('it', 'de')).toBe('it');
  });
});

describe('createFormat', () => {
  // Expected strings are CLDR's conventions (Node's full ICU): Swiss apostrophe grouping,
  // French narrow no-break space (U+202F) grouping and no-break space (U+00A0) before the currency.
  // CLDR 44+ writes the Swiss group separator as U+0027, older data as U+2019: both are Swiss.
  it('formats de-CH numbers and prices with the Swiss apostrophe', () => {
    const f = createFormat('de-CH', 'CHF');
    expect(f.number(1234.5)).toMatch(/^1['’]234\.5$/);
    expect(f.money(1234.5)).toMatch(/^CHF\u00a01['’]234\.50$/);
  });
  it('formats fr-FR with a narrow no-break space between thousands', () => {
    const f = createFormat('fr-FR', 'EUR');
    expect(f.number(1234567.25)).toBe('1\u202f234\u202f567,25');
    expect(f.money(1627)).toBe('1\u202f627,00\u00a0€');
    expect(f.percent(0.25)).toBe('25\u00a0%');
  });
  it('formats en-GB with comma grouping and the symbol in front', () => {
    const f = createFormat('en-GB', 'EUR');
    expect(f.money(1627)).toBe('€1,627.00');
    expect(f.metres(2.5)).toBe('2.50 m');
    expect(f.date(Date.UTC(2026, 10, 23, 12), { timeZone: 'UTC' })).toBe('23/11/2026');
  });
  it('never shows NaN and survives a bad currency code', () => {
    const f = createFormat('en-GB', 'EUR');
    expect(f.money(Number.NaN)).toBe('€0.00');
    expect(f.money(3, 'not a code')).toBe('3.00 not a code');
  });
});

describe('createTranslator', () => {
  const tree = {
    ...en,
    common: { ...en.common, loading: 'Loading {what} of {total}…' },
  } as MessageTree;
  const plural = { common: { ...en.common, loading: { one: '{count} module', other: '{count} modules' } } } as unknown as MessageTree;
  it('interpolates parameters, formatting numbers for the locale, and keeps unknown placeholders visible', () => {
    const t = createTranslator(tree, 'de-DE', (x) => createFormat('de-DE').number(x));
    expect(t('common.loading', { what: 'Pläne', total: 1234.5 })).toBe('Loading Pläne of 1.234,5…');
    expect(t('common.loading', { what: 'x' })).toBe('Loading x of {total}…');
  });
  it('selects the plural form with Intl.PluralRules', () => {
    const t = createTranslator(plural, 'en', String);
    expect(t('common.loading', { count: 1 })).toBe('1 module');
    expect(t('common.loading', { count: 0 })).toBe('0 modules');
    expect(t('common.loading', { count: 2 })).toBe('2 modules');
  });
  it('knows which run-time keys exist', () => {
    expect(isMessageKey('common.close')).toBe(true);
    expect(isMessageKey('common.nope')).toBe(false);
    expect(isMessageKey('nope')).toBe(false);
  });
});

describe('createI18n', () => {
  it('is ready at once for English and loads German before it says ready', async () => {
    expect(createI18n({ locale: 'en-GB' }).getSnapshot().ready).toBe(true);
    const i18n = createI18n({ locale: ['de-CH'], currency: 'EUR' });
    await i18n.ready;
    const s = i18n.getSnapshot();
    expect(s.ready).toBe(true);
    expect(s.language).toBe('de');
    expect(s.t('common.languageLabel')).toBe('Sprache');
    // de-CH writes the ISO code for euros (CLDR), the catalog's currency in Swiss style.
    expect(s.format.money(10)).toBe('EUR\u00a010.00');
  });
  it('switches language, keeps the region and tells the listener and the host', async () => {
    const changed: string[] = [];
    const i18n = createI18n({ locale: 'de-CH', onLanguageChange: (l) => changed.push(l) });
    await i18n.ready;
    let calls = 0;
    i18n.subscribe(() => calls++);
    await i18n.setLanguage('fr');
    expect(i18n.getSnapshot().locale).toBe('fr-CH');
    expect(i18n.getSnapshot().t('common.languageLabel')).toBe('Langue');
    expect(changed).toEqual(['fr']);
    expect(calls).toBe(1);
  });
});
