/**
 * The always-valid property for daylight and glazing (issue 30): from a room with two windows and
 * a door, random sequences of setDaylight (dates, clock times, places, skies, ground reflectances,
 * a good share of them impossible), setWindowGlazing (presets and numbers, some out of range, on
 * windows, doors and missing openings), setRoomOpening turning openings into windows or doors, and
 * addRoomOpening. Every enabled action leaves validate() empty, a refused one performed anyway a
 * state it rejects. After each sequence an independent check of the rules, written without the
 * model's code: the date a day of the proleptic calendar (Date's own round trip), the clock time
 * 00:00 … 23:59, glazing only on windows and within 0 … 1 or a preset. Seeded.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { createConfiguration, type Configuration } from '../../../../src/core/model/configuration/configuration';
import { CITIES } from '../../../../src/core/daylight/cities';
import { run } from '../helpers';
import { alwaysValidStep } from './alwaysValidStep';

const RUNS = Number(process.env.DAYLIGHT_RUNS ?? 200);
const step = fc.record({ kind: fc.nat(5), i: fc.nat(40), j: fc.nat(40), a: fc.noBias(fc.integer({ min: 0, max: 1000 })).map((n) => -0.5 + n / 500) });
type Step = { kind: number; i: number; j: number; a: number };
const pad = (n: number) => String(n).padStart(2, '0');

function start(): Configuration {
  let s = run(createConfiguration({ width: 5, depth: 4, height: 2.6 }), 'setRoomShapePreset', { preset: 'rectangle' });
  s = run(s, 'addRoomOpening', { wall: 2, kind: 'window', offset: 0.6, width: 1.4, sill: 0.8, height: 1.4 });
  s = run(s, 'addRoomOpening', { wall: 1, kind: 'window', offset: 1, width: 1.2, sill: 0.8, height: 1.4 });
  return run(s, 'addRoomOpening', { wall: 0, kind: 'door' });
}

function toAction(s: Configuration, st: Step): [string, unknown] {
  const openings = s.room.shape?.openings.length ?? 0;
  switch (st.kind) {
    case 0:
      // Days 1 … 32 of months 1 … 13 in 1899 … 2101: the calendar's edges and beyond.
      return ['setDaylight', { on: st.a > 0.3, date: `${1899 + ((st.i * 7 + st.j) % 203)}-${pad(1 + (st.i % 13))}-${pad(1 + ((st.j * 3) % 32))}` }];
    case 1:
      return ['setDaylight', { on: st.a > 0.1, time: `${pad(st.i % 26)}:${pad((st.j * 2) % 62)}` }];
    case 2:
      if (st.a < 0.5) return ['setDaylight', { city: st.i < 36 ? CITIES[st.i % CITIES.length].name : 'Atlantis' }];
      return ['setDaylight', { latitude: (st.a - 0.5) * 200, longitude: (st.i - 20) * 10, timeZone: st.j - 20, groundReflectance: st.a - 0.4, sky: (['uniform', 'cie-overcast', 'cie-clear'] as const)[st.i % 3] }];
    case 3:
      return ['setWindowGlazing', { opening: st.i % (openings + 1), transmittance: st.j % 4 === 0 ? (['single', 'double', 'triple'] as const)[st.i % 3] : st.a }];
    case 4:
      return ['setRoomOpening', { opening: st.i % Math.max(1, openings), kind: st.a < 0.5 ? 'door' : 'window', sill: st.a < 0.5 ? 0 : 0.8, height: st.a < 0.5 ? 2 : 1.2 }];
    default:
      return ['addRoomOpening', { wall: st.i % 4, kind: 'window', width: 0.6, sill: 1 }];
  }
}

/** The rules, independently: a real calendar day within 1901 … 2099, HH:MM, glazing only on windows within 0 … 1 or a preset. */
function independentlyValid(s: Configuration): string | null {
  const d = s.daylight;
  if (d) {
    const [y, m, day] = d.date.split('-').map(Number);
    const date = new Date(Date.UTC(y, m - 1, day));
    if (!(y >= 1901 && y <= 2099 && date.getUTCFullYear() === y && date.getUTCMonth() === m - 1 && date.getUTCDate() === day)) return `date ${d.date}`;
    const [h, min] = d.time.split(':').map(Number);
    if (!(d.time.length === 5 && h >= 0 && h <= 23 && min >= 0 && min <= 59)) return `time ${d.time}`;
    if (!(d.groundReflectance >= 0 && d.groundReflectance < 1)) return `ground ${d.groundReflectance}`;
  }
  for (const o of s.room.shape?.openings ?? []) {
    if (o.transmittance === undefined) continue;
    if (o.kind !== 'window') return `glazing on a ${o.kind}`;
    if (typeof o.transmittance === 'number' && !(o.transmittance >= 0 && o.transmittance <= 1)) return `transmittance ${o.transmittance}`;
  }
  return null;
}

describe('always valid with daylight and glazing', () => {
  it('enabled actions keep validate() empty, refused ones would break it, and the rules hold independently', () => {
    const tally = { enabled: 0, refused: 0, glazed: 0, on: 0 };
    fc.assert(
      fc.property(fc.array(step, { minLength: 4, maxLength: 24 }), (steps) => {
        let s = start();
        for (const st of steps) {
          const [name, params] = toAction(s, st);
          s = alwaysValidStep(s, name, params, tally);
        }
        const wrong = independentlyValid(s);
        if (wrong) throw new Error(`reached an invalid state: ${wrong}`);
        if (s.daylight?.on) tally.on++;
        if (s.room.shape?.openings.some((o) => o.transmittance !== undefined)) tally.glazed++;
      }),
      { numRuns: RUNS, seed: 30 },
    );
    console.log(`daylight always-valid: ${RUNS} sequences, ${JSON.stringify(tally)}`);
    // The sequences reach what they test: both enabled and refused actions, daylight on, glazed windows.
    expect(tally.enabled).toBeGreaterThan(RUNS);
    expect(tally.refused).toBeGreaterThan(RUNS / 2);
    expect(tally.on).toBeGreaterThan(RUNS / 10);
    expect(tally.glazed).toBeGreaterThan(RUNS / 10);
  }, 120_000);
});
