import './registerDaylightEnglish';
import './daylight.css';
import { useEffect, useRef, useState } from 'react';
import { CITIES, cityNamed } from '../../core/daylight/cities';
import { citiesInOrder } from './daylightCityNames';
import { DaylightDatePicker } from './DaylightDatePicker';
import { wallClockInstant } from './daylightDate';
import { solarPosition } from '../../core/daylight/solarPosition';
import type { Configuration } from '../../core/model/configuration/configuration';
import { DEFAULT_DAYLIGHT, isCityPlace, type DaylightSettings, type SkyType } from '../../core/model/configuration/daylightSettings';
import { daylightSun } from '../../core/model/files/lightingDaylight';
import type { ActionGate } from './actionGate';
import { CommitField } from '../shared/CommitField';
import { useI18n } from '../i18n/useI18n';
import type { MessageKey } from '../i18n/messageTypes';

/** What the 3D view shows: electric light, daylight or both (the view's controller, issue 30). */
export type LightSources = 'electric' | 'daylight' | 'both';

export interface DaylightPanelProps {
  config: Configuration;
  gate: ActionGate;
  /** The 3D view's light sources, when its controller can show them apart (absent: the buttons are not shown). */
  lightSources?: { value: LightSources; set: (sources: LightSources) => void };
}

const SKY_KEYS = { 'cie-clear': 'daylight.skyClear', 'cie-overcast': 'daylight.skyOvercast', uniform: 'daylight.skyUniform' } as const satisfies Record<SkyType, MessageKey>;
const SOURCE_KEYS = { electric: 'daylight.electric', daylight: 'daylight.daylight', both: 'daylight.both' } as const satisfies Record<LightSources, MessageKey>;
/** The time slider's step, minutes. */
const STEP_MINUTES = 15;
const COORDINATES = '';

const clock = (minutes: number) => `${String(Math.floor(minutes / 60)).padStart(2, '0')}:${String(minutes % 60).padStart(2, '0')}`;
const minutesOf = (time: string) => Number(time.slice(0, 2)) * 60 + Number(time.slice(3, 5));

/** A city of the list or coordinates (three fields). */
function PlacePicker({ daylight, gate }: { daylight: DaylightSettings; gate: ActionGate }) {
  const { t, language, locale } = useI18n();
  const place = daylight.place;
  const run = (params: Parameters<typeof gate.attempt<'setDaylight'>>[1]) => gate.attempt('setDaylight', params);
  return (
    <>
      <label className="daylight-field">
        <span>{t('daylight.place')}</span>
        <select
          value={isCityPlace(place) ? place.city : COORDINATES}
          data-testid="daylight-city"
          onChange={(e) => {
            const city = e.currentTarget.value;
            // Coordinates start from the city's own (its standard zone).
            const refused = city === COORDINATES ? run({ latitude: isCityPlace(place) ? (cityNamed(place.city)?.latitude ?? 0) : place.latitude }) : run({ city });
            if (refused) gate.explain(refused);
          }}
        >
          {citiesInOrder(CITIES, language, locale).map(({ city, label }) => (
            <option key={city.name} value={city.name}>
              {label}
            </option>
          ))}
          <option value={COORDINATES}>{t('daylight.coordinates')}</option>
        </select>
      </label>
      {!isCityPlace(place) &&
        (['latitude', 'longitude', 'timeZone'] as const).map((field) => (
          <label key={field} className="daylight-field">
            <span>{t(`daylight.${field}`)}</span>
            <CommitField label={t(`daylight.${field}`)} value={place[field]} decimals={field === 'timeZone' ? 2 : 1} onCommit={(v) => run({ [field]: v })} onRefused={gate.explain} testId={`daylight-${field}`} />
          </label>
        ))}
    </>
  );
}

/**
 * The time of day in 15-minute steps: the label follows the thumb, the action runs once when it is
 * let go (the input's native `change`), so a drag is one undo step and one rebake, not dozens.
 */
function TimeSlider({ daylight, gate }: { daylight: DaylightSettings; gate: ActionGate }) {
  const { t, format } = useI18n();
  const [draft, setDraft] = useState<number | null>(null);
  const ref = useRef<HTMLInputElement>(null);
  const shown = draft ?? minutesOf(daylight.time);
  // The place's clock time in the UI locale's way ("10:00", "10:00 AM"), not the browser's zone: its fields are the instant's UTC ones.
  const text = t('daylight.timeValue', { time: format.date(wallClockInstant(daylight.date, clock(shown)), { timeZone: 'UTC', hour: '2-digit', minute: '2-digit' }) });
  useEffect(() => {
    const input = ref.current;
    if (!input) return;
    const commit = () => {
      const refused = gate.attempt('setDaylight', { time: clock(Number(input.value)) });
      if (refused) gate.explain(refused);
      setDraft(null);
    };
    input.addEventListener('change', commit);
    return () => input.removeEventListener('change', commit);
  }, [gate]);
  return (
    <label className="daylight-field daylight-time">
      <span>{t('daylight.time')}</span>
      <input ref={ref} type="range" min={0} max={24 * 60 - STEP_MINUTES} step={STEP_MINUTES} value={shown} data-testid="daylight-time" aria-valuetext={text} onInput={(e) => setDraft(Number(e.currentTarget.value))} />
      <output data-testid="daylight-time-value" data-time={clock(shown)}>
        {text}
      </output>
    </label>
  );
}

/** Where the sun stands at the chosen place and time (NOAA's algorithm), or that it has set. */
function SunLine({ daylight }: { daylight: DaylightSettings }) {
  const { t, format } = useI18n();
  const sun = daylightSun(daylight);
  const p = solarPosition(sun, sun);
  const deg = (v: number) => format.number(v, { maximumFractionDigits: 0 });
  return (
    <p className="daylight-sun" data-testid="daylight-sun" data-elevation={p.elevation.toFixed(2)} data-azimuth={p.azimuth.toFixed(2)}>
      {p.elevation > 0 ? t('daylight.sunUp', { elevation: deg(p.elevation), azimuth: deg(p.azimuth) }) : t('daylight.sunDown')}
    </p>
  );
}

/** Electric light, daylight or both in the 3D view. */
function SourceButtons({ sources }: { sources: NonNullable<DaylightPanelProps['lightSources']> }) {
  const { t } = useI18n();
  return (
    <div className="daylight-sources" role="group" aria-label={t('daylight.sources')}>
      {(['electric', 'daylight', 'both'] as const).map((s) => (
        <button key={s} type="button" className="btn" aria-pressed={sources.value === s} data-testid={`light-sources-${s}`} onClick={() => sources.set(s)}>
          {t(SOURCE_KEYS[s])}
        </button>
      ))}
    </div>
  );
}

/**
 * The daylight panel (issue 30, docs/daylight.md "The shopper's daylight"): on and off, the place,
 * the day, the time of day and the sky; every change one setDaylight through the gate. A chunk of
 * its own (LazyDaylightSection), loaded with the model's room-shape chunk its actions live in.
 */
export default function DaylightPanel({ config, gate, lightSources }: DaylightPanelProps) {
  const { t } = useI18n();
  const daylight = config.daylight ?? DEFAULT_DAYLIGHT;
  const windows = (config.room.shape?.openings ?? []).filter((o) => o.kind === 'window').length;
  const sky = (value: SkyType) => {
    const refused = gate.attempt('setDaylight', { sky: value });
    if (refused) gate.explain(refused);
  };
  return (
    <div className="daylight-panel" data-testid="daylight-panel">
      <label className="daylight-on">
        <input type="checkbox" checked={daylight.on} data-testid="daylight-on" onChange={(e) => gate.run('setDaylight', { on: e.currentTarget.checked })} />
        <span>{t('daylight.on')}</span>
      </label>
      {windows === 0 && <p className="daylight-hint">{t('daylight.noWindows')}</p>}
      <PlacePicker daylight={daylight} gate={gate} />
      <DaylightDatePicker daylight={daylight} gate={gate} />
      <TimeSlider daylight={daylight} gate={gate} />
      <label className="daylight-field">
        <span>{t('daylight.sky')}</span>
        <select value={daylight.sky} data-testid="daylight-sky" onChange={(e) => sky(e.currentTarget.value as SkyType)}>
          {(Object.keys(SKY_KEYS) as SkyType[]).map((s) => (
            <option key={s} value={s}>
              {t(SKY_KEYS[s])}
            </option>
          ))}
        </select>
      </label>
      <SunLine daylight={daylight} />
      {lightSources && <SourceButtons sources={lightSources} />}
    </div>
  );
}
