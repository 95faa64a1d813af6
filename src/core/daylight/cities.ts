/**
 * A short list of cities for picking a place (latitude, longitude, standard time zone), so a
 * shopper need not know their coordinates. Coordinates of the city centre to 0.1°, east and
 * north positive; `timeZone` is the standard (winter) offset in hours and `ianaZone` the
 * zone a UI may use to add summer time for a date.
 */
export interface City {
  name: string;
  latitude: number;
  longitude: number;
  timeZone: number;
  ianaZone: string;
}

export const CITIES: readonly City[] = [
  { name: 'Zurich', latitude: 47.4, longitude: 8.5, timeZone: 1, ianaZone: 'Europe/Zurich' },
  { name: 'Geneva', latitude: 46.2, longitude: 6.1, timeZone: 1, ianaZone: 'Europe/Zurich' },
  { name: 'Berlin', latitude: 52.5, longitude: 13.4, timeZone: 1, ianaZone: 'Europe/Berlin' },
  { name: 'Munich', latitude: 48.1, longitude: 11.6, timeZone: 1, ianaZone: 'Europe/Berlin' },
  { name: 'Hamburg', latitude: 53.6, longitude: 10.0, timeZone: 1, ianaZone: 'Europe/Berlin' },
  { name: 'Vienna', latitude: 48.2, longitude: 16.4, timeZone: 1, ianaZone: 'Europe/Vienna' },
  { name: 'Paris', latitude: 48.9, longitude: 2.4, timeZone: 1, ianaZone: 'Europe/Paris' },
  { name: 'Lyon', latitude: 45.8, longitude: 4.8, timeZone: 1, ianaZone: 'Europe/Paris' },
  { name: 'Rome', latitude: 41.9, longitude: 12.5, timeZone: 1, ianaZone: 'Europe/Rome' },
  { name: 'Milan', latitude: 45.5, longitude: 9.2, timeZone: 1, ianaZone: 'Europe/Rome' },
  { name: 'Madrid', latitude: 40.4, longitude: -3.7, timeZone: 1, ianaZone: 'Europe/Madrid' },
  { name: 'Amsterdam', latitude: 52.4, longitude: 4.9, timeZone: 1, ianaZone: 'Europe/Amsterdam' },
  { name: 'Copenhagen', latitude: 55.7, longitude: 12.6, timeZone: 1, ianaZone: 'Europe/Copenhagen' },
  { name: 'Stockholm', latitude: 59.3, longitude: 18.1, timeZone: 1, ianaZone: 'Europe/Stockholm' },
  { name: 'London', latitude: 51.5, longitude: -0.1, timeZone: 0, ianaZone: 'Europe/London' },
  { name: 'Lisbon', latitude: 38.7, longitude: -9.1, timeZone: 0, ianaZone: 'Europe/Lisbon' },
  { name: 'Athens', latitude: 38.0, longitude: 23.7, timeZone: 2, ianaZone: 'Europe/Athens' },
  { name: 'New York', latitude: 40.7, longitude: -74.0, timeZone: -5, ianaZone: 'America/New_York' },
  { name: 'Los Angeles', latitude: 34.1, longitude: -118.2, timeZone: -8, ianaZone: 'America/Los_Angeles' },
  { name: 'Sydney', latitude: -33.9, longitude: 151.2, timeZone: 10, ianaZone: 'Australia/Sydney' },
  { name: 'Tokyo', latitude: 35.7, longitude: 139.7, timeZone: 9, ianaZone: 'Asia/Tokyo' },
  { name: 'Singapore', latitude: 1.3, longitude: 103.8, timeZone: 8, ianaZone: 'Asia/Singapore' },
];

/** The city of that name (case and accents as written in CITIES, compared case-insensitively), or undefined. */
export function cityNamed(name: string): City | undefined {
  const key = name.trim().toLowerCase();
  return CITIES.find((c) => c.name.toLowerCase() === key);
}
