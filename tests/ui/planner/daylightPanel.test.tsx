/** The daylight panel and the window glazing field as rendered (issue 30): what they show for a configuration. */
import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import { solarPosition } from '../../../src/core/daylight/solarPosition';
import { createConfiguration, type Configuration } from '../../../src/core/model/configuration/configuration';
import { createActionGate } from '../../../src/ui/planner/actionGate';
import DaylightPanel from '../../../src/ui/planner/DaylightPanel';
import { WindowGlazing } from '../../../src/ui/planner/WindowGlazing';
import { run } from '../../core/model/helpers';
import { createI18n } from '../../../src/ui/i18n/createI18n';
import { I18nProvider } from '../../../src/ui/i18n/I18nProvider';
import type { Language } from '../../../src/ui/i18n/languages';

const gate = (config: Configuration) =>
  createActionGate(
    config,
    defaultCatalog,
    () => {},
    () => {},
  );

function withWindow(): Configuration {
  const s = run(createConfiguration({ width: 5, depth: 4, height: 2.6 }), 'setRoomShapePreset', { preset: 'rectangle' });
  return run(s, 'addRoomOpening', { wall: 2, kind: 'window' });
}

/** The option a select shows as chosen (React marks it `selected`). */
function chosen(html: string, testId: string): string {
  const select = new RegExp(`<select[^>]*data-testid="${testId}"[^>]*>(.*?)</select>`).exec(html);
  if (!select) throw new Error(`no select ${testId}`);
  return /<option[^>]*selected=""[^>]*>([^<]*)<\/option>/.exec(select[1])?.[1] ?? '';
}

describe('DaylightPanel', () => {
  it('10:00 in Rome on 21 June: the city, the time and the sun NOAA puts there at 08:00 UTC (summer time)', () => {
    const config = run(withWindow(), 'setDaylight', { on: true, city: 'Rome', date: '2026-06-21', time: '10:00' });
    const html = renderToStaticMarkup(<DaylightPanel config={config} gate={gate(config)} />);
    expect(chosen(html, 'daylight-city')).toBe('Rome');
    expect(chosen(html, 'daylight-sky')).toBe('Clear with sun');
    // The clock and the date in the UI locale (English outside a provider, 'en': a 12-hour clock), the model's value beside.
    expect(html).toContain('data-time="10:00">10:00 AM</output>');
    expect(html).toContain('>Sunday, June 21, 2026</output>');
    expect(chosen(html, 'daylight-month')).toBe('June');
    expect(chosen(html, 'daylight-day')).toBe('21');
    expect(html).toMatch(/data-testid="daylight-june"[^>]*>June 21<\/button>/);
    const p = solarPosition({ latitude: 41.9, longitude: 12.5, timeZone: 0 }, { year: 2026, month: 6, day: 21, hours: 8 });
    expect(html).toContain(`data-elevation="${p.elevation.toFixed(2)}"`);
    expect(html).toContain(`Sun ${Math.round(p.elevation)}° above the horizon, ${Math.round(p.azimuth)}° from north`);
    expect(html).not.toContain('Add windows');
    // Without the 3D view's light-source control the buttons are not drawn; with it, the chosen one is pressed.
    expect(html).not.toContain('light-sources-');
    const withSources = renderToStaticMarkup(<DaylightPanel config={config} gate={gate(config)} lightSources={{ value: 'both', set: () => {} }} />);
    expect(withSources).toMatch(/aria-pressed="true" data-testid="light-sources-both"/);
  });

  it('17:00 on 21 December in Zurich: the sun has set; a room without windows is told to add some', () => {
    const config = run(createConfiguration(), 'setDaylight', { on: true, date: '2026-12-21', time: '17:00' });
    const html = renderToStaticMarkup(<DaylightPanel config={config} gate={gate(config)} />);
    expect(html).toContain('The sun is below the horizon');
    expect(html).toContain('Add windows in the room shape');
  });

  it('coordinates show their three fields', () => {
    const config = run(withWindow(), 'setDaylight', { latitude: 40.7, longitude: -74, timeZone: -4 });
    const html = renderToStaticMarkup(<DaylightPanel config={config} gate={gate(config)} />);
    expect(chosen(html, 'daylight-city')).toBe('Coordinates…');
    for (const f of ['latitude', 'longitude', 'timeZone']) expect(html).toContain(`data-testid="daylight-${f}"`);
  });
});

describe('DaylightPanel in four languages', () => {
  // Each language's names and dates, written out here (not asked of the code under test): the city, the month, the whole date
  // (a pattern: CLDR versions differ on the comma after an English weekday), the clock, the June button.
  const EXPECTED: Record<Language, { locale: string; city: string; month: string; date: string; time: string; june: string }> = {
    en: { locale: 'en-GB', city: 'Munich', month: 'June', date: 'Sunday,? 21 June 2026', time: '10:00', june: '21 June' },
    de: { locale: 'de-DE', city: 'München', month: 'Juni', date: 'Sonntag, 21. Juni 2026', time: '10:00 Uhr', june: '21. Juni' },
    fr: { locale: 'fr-FR', city: 'Munich', month: 'juin', date: 'dimanche 21 juin 2026', time: '10:00 h', june: '21 juin' },
    it: { locale: 'it-IT', city: 'Monaco di Baviera', month: 'giugno', date: 'domenica 21 giugno 2026', time: 'ore 10:00', june: '21 giugno' },
  };
  for (const [language, want] of Object.entries(EXPECTED)) {
    it(`${language}: ${want.city}, ${want.date}, ${want.time}`, async () => {
      const i18n = createI18n({ locale: want.locale, currency: 'EUR' });
      await i18n.ready;
      const config = run(withWindow(), 'setDaylight', { on: true, city: 'Munich', date: '2026-06-21', time: '10:00' });
      const html = renderToStaticMarkup(
        <I18nProvider i18n={i18n}>
          <DaylightPanel config={config} gate={gate(config)} />
        </I18nProvider>,
      );
      expect(chosen(html, 'daylight-city')).toBe(want.city);
      expect(chosen(html, 'daylight-month')).toBe(want.month);
      expect(html).toMatch(new RegExp(`>${want.date}</output>`));
      expect(html).toContain(`data-time="10:00">${want.time}</output>`);
      expect(html).toMatch(new RegExp(`data-testid="daylight-june"[^>]*>${want.june}</button>`));
    });
  }
});

describe('WindowGlazing', () => {
  it('shows the preset with its transmittance, or the number field', () => {
    const config = withWindow();
    expect(chosen(renderToStaticMarkup(<WindowGlazing opening={0} value={undefined} gate={gate(config)} />), 'room-glazing-select')).toBe('Double (τ 0.75)');
    expect(chosen(renderToStaticMarkup(<WindowGlazing opening={0} value="triple" gate={gate(config)} />), 'room-glazing-select')).toBe('Triple (τ 0.60)');
    const number = renderToStaticMarkup(<WindowGlazing opening={0} value={0.42} gate={gate(config)} />);
    expect(chosen(number, 'room-glazing-select')).toBe('Transmittance as a number');
    expect(number).toContain('data-testid="room-glazing-transmittance"');
  });
});
