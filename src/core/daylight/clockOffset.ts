/**
 * The clock's offset from UTC at a place on a day, summer time included, from the platform's time
 * zone database (Intl, IANA zones): a shopper's "10:00 in Zurich on 21 June" is 10:00 CEST (+2 h),
 * "17:00 on 21 December" 17:00 CET (+1 h). Without a usable Intl time zone (a runtime built
 * without ICU data) the city's standard offset is kept.
 */

/** Offset (hours) Intl reports for `zone` at the UTC instant `ms`, or null when it cannot say. */
function offsetAt(zone: string, ms: number): number | null {
  try {
    const name = new Intl.DateTimeFormat('en-US', { timeZone: zone, timeZoneName: 'longOffset' }).formatToParts(new Date(ms)).find((p) => p.type === 'timeZoneName')?.value;
    if (name === 'GMT') return 0;
    const m = /^GMT([+-])(\d{2}):(\d{2})$/.exec(name ?? '');
    return m ? (m[1] === '-' ? -1 : 1) * (Number(m[2]) + Number(m[3]) / 60) : null;
  } catch {
    return null;
  }
}

/**
 * Hours ahead of UTC of the clock in `zone` at local `hours` on year-month-day; `standard` (the
 * zone's winter offset) when Intl cannot tell. The instant is found by two fixed-point steps from
 * the standard offset, which settle on the offset in force at that local time (in the hour a clock
 * skips or repeats, one of the two, as clocks do).
 */
export function clockOffsetHours(zone: string, standard: number, year: number, month: number, day: number, hours: number): number {
  const local = Date.UTC(year, month - 1, day) + hours * 3_600_000;
  let offset = standard;
  for (let i = 0; i < 2; i++) {
    const found = offsetAt(zone, local - offset * 3_600_000);
    if (found === null) return standard;
    offset = found;
  }
  return offset;
}
