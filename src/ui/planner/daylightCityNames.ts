import type { Language } from '../i18n/languages';
import type { City } from '../../core/daylight/cities';

/**
 * The daylight panel's cities (core/daylight/cities.ts, whose `name` is the key the
 * configuration stores) as each UI language writes them: exonyms where the language has one in
 * common use (Munich / München, Rome / Roma, Geneva / Genève), the city's own name where not.
 * One table, so a city added to the list without its four names fails cityNames.test.ts.
 */
export const CITY_DISPLAY_NAMES: Readonly<Record<string, Readonly<Record<Language, string>>>> = {
  Zurich: { en: 'Zurich', de: 'Zürich', fr: 'Zurich', it: 'Zurigo' },
  Geneva: { en: 'Geneva', de: 'Genf', fr: 'Genève', it: 'Ginevra' },
  Berlin: { en: 'Berlin', de: 'Berlin', fr: 'Berlin', it: 'Berlino' },
  Munich: { en: 'Munich', de: 'München', fr: 'Munich', it: 'Monaco di Baviera' },
  Hamburg: { en: 'Hamburg', de: 'Hamburg', fr: 'Hambourg', it: 'Amburgo' },
  Vienna: { en: 'Vienna', de: 'Wien', fr: 'Vienne', it: 'Vienna' },
  Paris: { en: 'Paris', de: 'Paris', fr: 'Paris', it: 'Parigi' },
  Lyon: { en: 'Lyon', de: 'Lyon', fr: 'Lyon', it: 'Lione' },
  Rome: { en: 'Rome', de: 'Rom', fr: 'Rome', it: 'Roma' },
  Milan: { en: 'Milan', de: 'Mailand', fr: 'Milan', it: 'Milano' },
  Madrid: { en: 'Madrid', de: 'Madrid', fr: 'Madrid', it: 'Madrid' },
  Amsterdam: { en: 'Amsterdam', de: 'Amsterdam', fr: 'Amsterdam', it: 'Amsterdam' },
  Copenhagen: { en: 'Copenhagen', de: 'Kopenhagen', fr: 'Copenhague', it: 'Copenaghen' },
  Stockholm: { en: 'Stockholm', de: 'Stockholm', fr: 'Stockholm', it: 'Stoccolma' },
  London: { en: 'London', de: 'London', fr: 'Londres', it: 'Londra' },
  Lisbon: { en: 'Lisbon', de: 'Lissabon', fr: 'Lisbonne', it: 'Lisbona' },
  Athens: { en: 'Athens', de: 'Athen', fr: 'Athènes', it: 'Atene' },
  'New York': { en: 'New York', de: 'New York', fr: 'New York', it: 'New York' },
  'Los Angeles': { en: 'Los Angeles', de: 'Los Angeles', fr: 'Los Angeles', it: 'Los Angeles' },
  Sydney: { en: 'Sydney', de: 'Sydney', fr: 'Sydney', it: 'Sydney' },
  Tokyo: { en: 'Tokyo', de: 'Tokio', fr: 'Tokyo', it: 'Tokyo' },
  Singapore: { en: 'Singapore', de: 'Singapur', fr: 'Singapour', it: 'Singapore' },
};

/** The city's name in `language` (the list's own name where the table has none). */
export function cityDisplayName(city: Pick<City, 'name'>, language: Language): string {
  return CITY_DISPLAY_NAMES[city.name]?.[language] ?? city.name;
}

/** The cities in the alphabetical order of `locale` by their names in `language`, so a shopper finds "Wien" under W in German. */
export function citiesInOrder<C extends Pick<City, 'name'>>(cities: readonly C[], language: Language, locale: string): { city: C; label: string }[] {
  const collator = new Intl.Collator(locale);
  return cities.map((city) => ({ city, label: cityDisplayName(city, language) })).sort((a, b) => collator.compare(a.label, b.label));
}
