import { describe, expect, it } from 'vitest';
import { formatMetres, formatMoney } from '../../../src/ui/planner/formatMoney';

describe('formatMoney', () => {
  it('formats with Intl for the locale and currency', () => {
    expect(formatMoney(1234.5, 'EUR', 'en-US')).toBe('€1,234.50');
    expect(formatMoney(1234.5, 'EUR', 'de-DE').replace(/\s/g, ' ')).toBe('1.234,50 €');
  });
  it('falls back instead of throwing for a bad currency code, never NaN', () => {
    expect(formatMoney(3, 'not a code', 'en-US')).toBe('3.00 not a code');
    expect(formatMoney(Number.NaN, 'EUR', 'en-US')).toBe('€0.00');
  });
  it('formats metres', () => {
    expect(formatMetres(1.5, 'en-US')).toBe('1.50 m');
    expect(formatMetres(1.5, 'de-DE')).toBe('1,50 m');
  });
});
