import { describe, expect, it } from 'vitest';
import { CITIES, cityNamed } from '../../../src/core/daylight/cities';
import { dayOfYear, julianDay, solarPosition, sunDirection } from '../../../src/core/daylight/solarPosition';

describe('solar position (NOAA algorithm)', () => {
  it('matches the NREL SPA worked example (Reda & Andreas 2004, Golden, 2003-10-17 12:30:30 −7 h) within 0.1°', () => {
    const p = solarPosition({ latitude: 39.742476, longitude: -105.1786, timeZone: -7 }, { year: 2003, month: 10, day: 17, hours: 12 + 30 / 60 + 30 / 3600 });
    expect(Math.abs(p.zenith - 50.11162)).toBeLessThan(0.1);
    expect(Math.abs(p.azimuth - 194.34024)).toBeLessThan(0.1);
    // NOAA's own result is far closer than the bar: record it so a change in the algorithm shows.
    expect(Math.abs(p.zenith - 50.11162)).toBeLessThan(0.02);
    expect(Math.abs(p.azimuth - 194.34024)).toBeLessThan(0.02);
  });

  it('gives the Julian day of Meeus example 7.a and days of the year', () => {
    // Meeus, Astronomical Algorithms, example 7.a: 1957 October 4.81 = JD 2436116.31.
    expect(julianDay(1957, 10, 4) + 0.81).toBeCloseTo(2436116.31, 6);
    expect(julianDay(2000, 1, 1)).toBe(2451544.5);
    expect(dayOfYear(2026, 1, 1)).toBe(1);
    expect(dayOfYear(2026, 12, 31)).toBe(365);
    expect(dayOfYear(2024, 12, 31)).toBe(366);
  });

  it('puts the declination at ±23.44° at the solstices and the equation of time at its known extremes', () => {
    const at = (month: number, day: number) => solarPosition({ latitude: 0, longitude: 0, timeZone: 0 }, { year: 2026, month, day, hours: 12 });
    expect(Math.abs(at(6, 21).declination - 23.44)).toBeLessThan(0.05);
    expect(Math.abs(at(12, 21).declination + 23.44)).toBeLessThan(0.05);
    // The equation of time peaks near +16.4 min in early November and −14.2 min in mid-February.
    expect(Math.abs(at(11, 3).equationOfTime - 16.4)).toBeLessThan(0.3);
    expect(Math.abs(at(2, 11).equationOfTime + 14.2)).toBeLessThan(0.3);
  });

  it('has the sun due south at true solar noon in Zurich, at 90° − φ + δ', () => {
    const place = { latitude: 47.4, longitude: 8.5, timeZone: 1 };
    const noon = solarPosition(place, { year: 2026, month: 6, day: 21, hours: 12 });
    // True solar noon: 12:00 − 4 min/° × longitude + zone − equation of time.
    const hours = 12 + (60 * place.timeZone - 4 * place.longitude - noon.equationOfTime) / 60;
    const p = solarPosition(place, { year: 2026, month: 6, day: 21, hours });
    expect(Math.abs(p.azimuth - 180)).toBeLessThan(0.05);
    expect(Math.abs(p.elevation - (90 - 47.4 + p.declination))).toBeLessThan(0.05); // refraction at 66° is 0.007°
    // Morning sun in the east, evening sun in the west.
    expect(solarPosition(place, { year: 2026, month: 6, day: 21, hours: 8 }).azimuth).toBeLessThan(120);
    expect(solarPosition(place, { year: 2026, month: 6, day: 21, hours: 19 }).azimuth).toBeGreaterThan(260);
    expect(solarPosition(place, { year: 2026, month: 12, day: 21, hours: 22 }).elevation).toBeLessThan(0);
  });

  it('maps elevation and azimuth to room directions: x east, y up, z south', () => {
    const close = (a: number[], b: number[]) => a.forEach((v, i) => expect(v).toBeCloseTo(b[i], 12));
    close(sunDirection(0, 90), [1, 0, 0]);
    close(sunDirection(0, 180), [0, 0, 1]);
    close(sunDirection(0, 0), [0, 0, -1]);
    close(sunDirection(90, 123), [0, 1, 0]);
    const d = sunDirection(30, 200);
    expect(Math.hypot(...d)).toBeCloseTo(1, 12);
    expect(d[1]).toBeCloseTo(0.5, 12);
  });

  it('lists cities with plausible coordinates and finds them by name', () => {
    expect(CITIES.length).toBeGreaterThanOrEqual(10);
    for (const c of CITIES) {
      expect(Math.abs(c.latitude)).toBeLessThanOrEqual(90);
      expect(Math.abs(c.longitude)).toBeLessThanOrEqual(180);
      // The standard zone lies within 2.5 h of the longitude's own (15° per hour).
      expect(Math.abs(c.timeZone - c.longitude / 15)).toBeLessThan(2.5);
    }
    expect(new Set(CITIES.map((c) => c.name)).size).toBe(CITIES.length);
    expect(cityNamed(' zurich ')?.latitude).toBe(47.4);
    expect(cityNamed('Atlantis')).toBeUndefined();
  });
});
