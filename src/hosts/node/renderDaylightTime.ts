/**
 * `luxbox render --date/--time` (docs/daylight.md, "On the command line") on either kind of input:
 * a lighting scene's sun is moved by the contract's own rules (daylightTimeOverride.ts: a clear sky
 * needs the sun up); a configuration's daylight settings are moved as the Daylight panel moves them
 * (the date and the clock time of its place, summer time included), so after sunset it renders as
 * the browser shows it: no daylight, the night sky in the windows.
 */
import { InputError } from '../../core/inputError';
import { daylightDate, daylightHours } from '../../core/model/validation/daylightProblems';
import { DATE_FLAG, TIME_FLAG, withDaylightTime, type DaylightTime } from './daylightTimeOverride';
import { configurationRenderInput, type RenderInput } from './renderInput';

/** `input` at `when` (unchanged without flags); `file` names the input in a refusal. */
export function renderInputAtTime(input: RenderInput, when: DaylightTime | null, file: string): RenderInput {
  if (!when) return input;
  const config = input.configuration;
  if (!config) return withDaylightTime(input, when, 'render', file);
  const flags = [when.date !== undefined ? `${DATE_FLAG} ${when.date}` : '', when.time !== undefined ? `${TIME_FLAG} ${when.time}` : ''].filter(Boolean).join(' ');
  if (!config.daylight) throw new InputError(`render: ${flags}: ${file} has no daylight to move (switch it on in the Daylight panel: docs/daylight.md)`);
  if (when.date !== undefined && !daylightDate(when.date)) throw new InputError(`render: ${DATE_FLAG} ${when.date} (${file}): a configuration's date is YYYY-MM-DD, a day of 1901–2099`);
  if (when.time !== undefined && daylightHours(when.time) === null) throw new InputError(`render: ${TIME_FLAG} ${when.time} (${file}): a configuration's time is HH:MM, 00:00–23:59`);
  const daylight = { ...config.daylight, ...(when.date !== undefined ? { date: when.date } : {}), ...(when.time !== undefined ? { time: when.time } : {}) };
  return configurationRenderInput({ ...config, daylight }, input.source ?? file);
}
