import { describe, expect, it } from 'vitest';
import { sentenceStart } from '../../../src/ui/i18n/sentenceStart';

describe('sentenceStart', () => {
  it('capitalises the first letter only, by the locale’s rules', () => {
    expect(sentenceStart('the 240 W driver is full: 215 W used', 'en')).toBe('The 240 W driver is full: 215 W used');
    expect(sentenceStart('kein freier Platz für „Lange Linie“', 'de')).toBe('Kein freier Platz für „Lange Linie“');
    expect(sentenceStart('il', 'tr')).toBe('İl');
    expect(sentenceStart('', 'en')).toBe('');
    expect(sentenceStart('« déjà »', 'fr')).toBe('« déjà »');
  });
});
