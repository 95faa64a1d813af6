/** The daylight panel's city names in the four UI languages (issue 30f): one table, complete. */
import { describe, expect, it } from 'vitest';
import { CITIES } from '../../../src/core/daylight/cities';
import { LANGUAGES } from '../../../src/ui/i18n/languages';
import { CITY_DISPLAY_NAMES, citiesInOrder, cityDisplayName } from '../../../src/ui/planner/daylightCityNames';

describe('city display names', () => {
  it('every city of the list has a name in every language, and the table names no other city', () => {
    for (const city of CITIES) {
      for (const language of LANGUAGES) {
        const name = CITY_DISPLAY_NAMES[city.name]?.[language];
        expect(name, `${city.name} in ${language}`).toBeTypeOf('string');
        expect(name!.trim().length, `${city.name} in ${language}`).toBeGreaterThan(0);
      }
    }
    expect(Object.keys(CITY_DISPLAY_NAMES).sort()).toEqual(CITIES.map((c) => c.name).sort());
  });

  it('English keeps the list’s names; the others write their exonyms', () => {
    for (const city of CITIES) expect(cityDisplayName(city, 'en')).toBe(city.name);
    expect(['de', 'fr', 'it'].map((l) => cityDisplayName({ name: 'Munich' }, l as 'de'))).toEqual(['München', 'Munich', 'Monaco di Baviera']);
    expect(cityDisplayName({ name: 'Rome' }, 'it')).toBe('Roma');
    expect(cityDisplayName({ name: 'Geneva' }, 'fr')).toBe('Genève');
    expect(cityDisplayName({ name: 'Atlantis' }, 'de')).toBe('Atlantis');
  });

  it('sorts by the name the shopper reads: Wien after Stockholm and before Zürich in German', () => {
    const labels = citiesInOrder(CITIES, 'de', 'de-DE').map((c) => c.label);
    expect(labels).toHaveLength(CITIES.length);
    expect(labels.indexOf('Wien')).toBe(labels.length - 2);
    expect(labels.at(-1)).toBe('Zürich');
    for (let i = 1; i < labels.length; i++) expect(labels[i - 1].localeCompare(labels[i], 'de-DE')).toBeLessThan(0);
  });
});
