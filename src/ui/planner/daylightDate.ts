/**
 * The daylight panel's calendar arithmetic on the configuration's "YYYY-MM-DD" (docs/daylight.md,
 * "The shopper's daylight"): the panel edits day, month and year apart, each in the UI language,
 * so a change of month or year keeps the day where the new month has it and else takes its last.
 */
export interface CalendarDay {
  year: number;
  /** 1 … 12. */
  month: number;
  day: number;
}

/** The parts of "YYYY-MM-DD". */
export function calendarDay(date: string): CalendarDay {
  return { year: Number(date.slice(0, 4)), month: Number(date.slice(5, 7)), day: Number(date.slice(8, 10)) };
}

/** Days in a month of the Gregorian calendar (Date.UTC's day 0 of the next month is this month's last). */
export function daysInMonth(year: number, month: number): number {
  return new Date(Date.UTC(year, month, 0)).getUTCDate();
}

/** "YYYY-MM-DD" of the parts, the day clamped to the month's last (31 January → February: the 28th or 29th). */
export function isoDate({ year, month, day }: CalendarDay): string {
  const d = Math.min(day, daysInMonth(year, month));
  return `${String(year).padStart(4, '0')}-${String(month).padStart(2, '0')}-${String(d).padStart(2, '0')}`;
}

/** The instant whose UTC fields are the day and clock time, for formatting them with `timeZone: 'UTC'` (the place's own clock, whatever the browser's zone). */
export function wallClockInstant(date: string, time: string): Date {
  const { year, month, day } = calendarDay(date);
  // The contract's years are 1901 … 2099, which Date.UTC takes as written (it reads 0 … 99 as 1900 …).
  return new Date(Date.UTC(year, month - 1, day, Number(time.slice(0, 2)), Number(time.slice(3, 5))));
}
