import type { DaylightSettings } from '../../core/model/configuration/daylightSettings';
import type { ActionGate } from './actionGate';
import { CommitField } from '../shared/CommitField';
import { useI18n } from '../i18n/useI18n';
import { calendarDay, daysInMonth, isoDate, wallClockInstant, type CalendarDay } from './daylightDate';

const MONTHS = Array.from({ length: 12 }, (_, i) => i + 1);
/** Formats a calendar day as written, whatever the browser's time zone (daylightDate.ts, wallClockInstant). */
const UTC = { timeZone: 'UTC' } as const;

/**
 * The date as day, month and year in the UI language (Intl.DateTimeFormat of the UI locale), not
 * an `<input type=date>`, which writes the browser's locale ("06/21/2026" beside a German panel);
 * the whole date written out below them, and the two days a shopper compares, the longest and the
 * shortest (their year kept), also written by Intl ("21 June", "21. Juni", "21 juin", "21 giugno").
 */
export function DaylightDatePicker({ daylight, gate }: { daylight: DaylightSettings; gate: ActionGate }) {
  const { t, format } = useI18n();
  const parts = calendarDay(daylight.date);
  const attempt = (next: Partial<CalendarDay>) => gate.attempt('setDaylight', { date: isoDate({ ...parts, ...next }) });
  const set = (next: Partial<CalendarDay>) => {
    const refused = attempt(next);
    if (refused) gate.explain(refused);
  };
  const dayOfYear = (month: number, day: number) => format.date(Date.UTC(parts.year, month - 1, day), { ...UTC, day: 'numeric', month: 'long' });
  const preset = (month: number, testId: string) => {
    const date = isoDate({ year: parts.year, month, day: 21 });
    return (
      <button type="button" className="btn" data-testid={testId} aria-pressed={daylight.date === date} onClick={() => set({ month, day: 21 })}>
        {dayOfYear(month, 21)}
      </button>
    );
  };
  return (
    <fieldset className="daylight-field daylight-date">
      <legend>{t('daylight.date')}</legend>
      <div className="daylight-date-parts">
        <select aria-label={t('daylight.day')} value={parts.day} data-testid="daylight-day" onChange={(e) => set({ day: Number(e.currentTarget.value) })}>
          {Array.from({ length: daysInMonth(parts.year, parts.month) }, (_, i) => (
            <option key={i} value={i + 1}>
              {format.number(i + 1)}
            </option>
          ))}
        </select>
        <select aria-label={t('daylight.month')} value={parts.month} data-testid="daylight-month" onChange={(e) => set({ month: Number(e.currentTarget.value) })}>
          {MONTHS.map((m) => (
            <option key={m} value={m}>
              {format.date(Date.UTC(2001, m - 1, 1), { ...UTC, month: 'long' })}
            </option>
          ))}
        </select>
        <CommitField label={t('daylight.year')} value={parts.year} decimals={0} onCommit={(year) => attempt({ year: Math.round(year) })} onRefused={gate.explain} testId="daylight-year" />
      </div>
      <output data-testid="daylight-date-text">{format.date(wallClockInstant(daylight.date, '12:00'), { ...UTC, weekday: 'long', day: 'numeric', month: 'long', year: 'numeric' })}</output>
      <div className="daylight-date-presets">
        {preset(6, 'daylight-june')}
        {preset(12, 'daylight-december')}
      </div>
    </fieldset>
  );
}
