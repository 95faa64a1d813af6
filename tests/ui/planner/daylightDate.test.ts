/** The daylight panel's calendar arithmetic (daylightDate.ts) against the Gregorian rules written out here. */
import { describe, expect, it } from 'vitest';
import { calendarDay, daysInMonth, isoDate, wallClockInstant } from '../../../src/ui/planner/daylightDate';

/** Gregorian leap years: every fourth, not every hundredth, every four-hundredth. */
const leap = (y: number) => (y % 4 === 0 && y % 100 !== 0) || y % 400 === 0;
const DAYS = [31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31];

describe('daylight date', () => {
  it('days in every month of 1901 … 2099 follow the Gregorian rule', () => {
    for (let year = 1901; year <= 2099; year++) {
      for (let month = 1; month <= 12; month++) expect(daysInMonth(year, month)).toBe(month === 2 && leap(year) ? 29 : DAYS[month - 1]);
    }
    expect(daysInMonth(2000, 2)).toBe(29);
    expect(daysInMonth(2100, 2)).toBe(28);
  });

  it('a day the new month lacks becomes its last; a day it has is kept', () => {
    expect(isoDate({ ...calendarDay('2026-01-31'), month: 2 })).toBe('2026-02-28');
    expect(isoDate({ ...calendarDay('2024-01-31'), month: 2 })).toBe('2024-02-29');
    expect(isoDate({ ...calendarDay('2024-02-29'), year: 2025 })).toBe('2025-02-28');
    expect(isoDate({ ...calendarDay('2026-06-21'), month: 12 })).toBe('2026-12-21');
    expect(calendarDay('1901-03-09')).toEqual({ year: 1901, month: 3, day: 9 });
  });

  it('the wall-clock instant carries the day and time in its UTC fields', () => {
    const d = wallClockInstant('1905-12-21', '17:45');
    expect([d.getUTCFullYear(), d.getUTCMonth() + 1, d.getUTCDate(), d.getUTCHours(), d.getUTCMinutes()]).toEqual([1905, 12, 21, 17, 45]);
  });
});
