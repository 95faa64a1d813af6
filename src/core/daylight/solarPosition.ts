/**
 * The sun's position for a place, a date and a clock time: NOAA's solar-position algorithm (NOAA
 * Global Monitoring Laboratory, "Solar Calculation Details" and its spreadsheet
 * NOAA_Solar_Calculations_day.xls, after J. Meeus, Astronomical Algorithms, Willmann-Bell 1991,
 * chapters 7, 21 to 25). NOAA states its accuracy as about 0.01° for dates 1901–2099 within ±72°
 * latitude (less near the poles, and refraction near the horizon is uncertain anyway); the test
 * checks it against the worked example of the NREL SPA (Reda & Andreas, Solar Energy 76(5),
 * 2004, table A4.1: Golden, Colorado, 2003-10-17 12:30:30 −7 h: zenith 50.11162°, azimuth
 * 194.34024°) within 0.1°. Terrestrial time is taken equal to universal time (ΔT ≈ 70 s moves
 * the sun by 0.0008°).
 */

export interface SolarPlace {
  /** Degrees north (−90 … 90). */
  latitude: number;
  /** Degrees east (−180 … 180): Zurich is +8.5, New York −74. */
  longitude: number;
  /** Hours ahead of UTC of the clock time given (Zurich in winter +1, in summer +2). */
  timeZone: number;
}

export interface SolarTime {
  year: number;
  /** 1 … 12 */
  month: number;
  /** 1 … 31 */
  day: number;
  /** Clock time in hours (12.5 = 12:30) in the place's time zone. */
  hours: number;
}

export interface SolarPosition {
  /** Degrees from the zenith, with atmospheric refraction. */
  zenith: number;
  /** Degrees above the horizon (90 − zenith). */
  elevation: number;
  /** Degrees clockwise from north (east 90, south 180). */
  azimuth: number;
  /** Degrees. */
  declination: number;
  /** Minutes (apparent minus mean solar time). */
  equationOfTime: number;
  /** Day of the year, 1 … 366. */
  dayOfYear: number;
}

const rad = Math.PI / 180;
const deg = 180 / Math.PI;
const mod = (x: number, m: number): number => ((x % m) + m) % m;

/** Julian day number at 0 h UT of a Gregorian calendar date (Meeus, chapter 7). */
export function julianDay(year: number, month: number, day: number): number {
  const [y, m] = month <= 2 ? [year - 1, month + 12] : [year, month];
  const a = Math.floor(y / 100);
  const b = 2 - a + Math.floor(a / 4);
  return Math.floor(365.25 * (y + 4716)) + Math.floor(30.6001 * (m + 1)) + day + b - 1524.5;
}

/** Day of the year (1 on 1 January). */
export function dayOfYear(year: number, month: number, day: number): number {
  return julianDay(year, month, day) - julianDay(year, 1, 1) + 1;
}

/**
 * Atmospheric refraction (degrees) to add to the geometric elevation e (degrees), NOAA's
 * piecewise formula (Bennett's and Saemundsson's fits as the spreadsheet has them).
 */
export function refractionCorrection(e: number): number {
  if (e > 85) return 0;
  const t = Math.tan(e * rad);
  let arcsec: number;
  if (e > 5) arcsec = 58.1 / t - 0.07 / t ** 3 + 0.000086 / t ** 5;
  else if (e > -0.575) arcsec = 1735 + e * (-518.2 + e * (103.4 + e * (-12.79 + e * 0.711)));
  else arcsec = -20.772 / t;
  return arcsec / 3600;
}

/** The sun's zenith, elevation and azimuth for a place and a clock time (NOAA, above). */
export function solarPosition(place: SolarPlace, time: SolarTime): SolarPosition {
  const jd = julianDay(time.year, time.month, time.day) + (time.hours - place.timeZone) / 24;
  const jc = (jd - 2451545) / 36525;
  const meanLong = mod(280.46646 + jc * (36000.76983 + jc * 0.0003032), 360);
  const meanAnom = 357.52911 + jc * (35999.05029 - 0.0001537 * jc);
  const ecc = 0.016708634 - jc * (0.000042037 + 0.0000001267 * jc);
  const m = meanAnom * rad;
  const centre = Math.sin(m) * (1.914602 - jc * (0.004817 + 0.000014 * jc)) + Math.sin(2 * m) * (0.019993 - 0.000101 * jc) + Math.sin(3 * m) * 0.000289;
  const omega = (125.04 - 1934.136 * jc) * rad;
  const apparentLong = meanLong + centre - 0.00569 - 0.00478 * Math.sin(omega);
  const meanObliquity = 23 + (26 + (21.448 - jc * (46.815 + jc * (0.00059 - jc * 0.001813))) / 60) / 60;
  const obliquity = (meanObliquity + 0.00256 * Math.cos(omega)) * rad;
  const declination = Math.asin(Math.sin(obliquity) * Math.sin(apparentLong * rad));
  const y = Math.tan(obliquity / 2) ** 2;
  const l0 = meanLong * rad;
  const equationOfTime = 4 * deg * (y * Math.sin(2 * l0) - 2 * ecc * Math.sin(m) + 4 * ecc * y * Math.sin(m) * Math.cos(2 * l0) - 0.5 * y * y * Math.sin(4 * l0) - 1.25 * ecc * ecc * Math.sin(2 * m));
  const trueSolarMinutes = mod(time.hours * 60 + equationOfTime + 4 * place.longitude - 60 * place.timeZone, 1440);
  const hourAngle = trueSolarMinutes / 4 < 0 ? trueSolarMinutes / 4 + 180 : trueSolarMinutes / 4 - 180;
  const lat = place.latitude * rad;
  const cosZenith = Math.min(1, Math.max(-1, Math.sin(lat) * Math.sin(declination) + Math.cos(lat) * Math.cos(declination) * Math.cos(hourAngle * rad)));
  const geometricZenith = Math.acos(cosZenith) * deg;
  const elevation = 90 - geometricZenith + refractionCorrection(90 - geometricZenith);
  // Azimuth from the geometric zenith (NOAA); at the zenith or a pole any azimuth is right.
  const sinZenith = Math.sin(geometricZenith * rad);
  const denominator = Math.cos(lat) * sinZenith;
  const cosAz = Math.abs(denominator) < 1e-12 ? 1 : Math.min(1, Math.max(-1, (Math.sin(lat) * cosZenith - Math.sin(declination)) / denominator));
  const a = Math.acos(cosAz) * deg;
  const azimuth = hourAngle > 0 ? mod(a + 180, 360) : mod(540 - a, 360);
  return { zenith: 90 - elevation, elevation, azimuth, declination: declination * deg, equationOfTime, dayOfYear: dayOfYear(time.year, time.month, time.day) };
}

/**
 * Unit vector toward the sun in room coordinates: x east, y up, z south (the box's north wall
 * is z = 0, its south wall z = depth; docs/scene-format.md), from elevation and azimuth in degrees.
 */
export function sunDirection(elevation: number, azimuth: number): [number, number, number] {
  const e = elevation * rad;
  const a = azimuth * rad;
  return [Math.cos(e) * Math.sin(a), Math.sin(e), -Math.cos(e) * Math.cos(a)];
}
