/** The clock's offset with summer time, from the IANA zones (core/daylight/clockOffset.ts). */
import { describe, expect, it } from 'vitest';
import { clockOffsetHours } from '../../../src/core/daylight/clockOffset';

describe('clockOffsetHours', () => {
  it('keeps summer time: Zurich +2 h on 21 June and +1 h on 21 December, Sydney the other way round', () => {
    expect(clockOffsetHours('Europe/Zurich', 1, 2026, 6, 21, 10)).toBe(2);
    expect(clockOffsetHours('Europe/Zurich', 1, 2026, 12, 21, 17)).toBe(1);
    expect(clockOffsetHours('Australia/Sydney', 10, 2026, 6, 21, 10)).toBe(10);
    expect(clockOffsetHours('Australia/Sydney', 10, 2026, 12, 21, 10)).toBe(11);
    expect(clockOffsetHours('America/New_York', -5, 2026, 7, 4, 12)).toBe(-4);
    expect(clockOffsetHours('Asia/Singapore', 8, 2026, 7, 4, 12)).toBe(8);
  });

  it('switches at the local hour the law says: Zurich on 29 March 2026 is +1 at 01:00 and +2 at 03:00', () => {
    expect(clockOffsetHours('Europe/Zurich', 1, 2026, 3, 29, 1)).toBe(1);
    expect(clockOffsetHours('Europe/Zurich', 1, 2026, 3, 29, 3)).toBe(2);
  });

  it('keeps the standard offset where the platform knows no such zone', () => {
    expect(clockOffsetHours('Nowhere/Atlantis', 3, 2026, 6, 21, 10)).toBe(3);
  });
});
