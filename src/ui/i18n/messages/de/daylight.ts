import type en from '../en/daylight';
import type { AreaMessages } from '../../messageTypes';

export default {
  on: 'Himmel und Sonne durch die Fenster',
  noWindows: 'Fügen Sie in der Raumform Fenster hinzu, um Tageslicht hereinzulassen.',
  place: 'Ort',
  coordinates: 'Koordinaten…',
  latitude: 'Breite (°, Nord +)',
  longitude: 'Länge (°, Ost +)',
  timeZone: 'Zeitzone (h vor UTC)',
  date: 'Datum',
  day: 'Tag',
  month: 'Monat',
  year: 'Jahr',
  time: 'Tageszeit',
  timeValue: '{time} Uhr',
  sky: 'Himmel',
  skyClear: 'Klar mit Sonne',
  skyOvercast: 'Bedeckt',
  skyUniform: 'Gleichförmig (Test)',
  sunUp: 'Sonne {elevation}° über dem Horizont, {azimuth}° von Norden',
  sunDown: 'Die Sonne steht unter dem Horizont: zu dieser Zeit kein Tageslicht',
  sources: 'Zeigen',
  electric: 'Kunstlicht',
  daylight: 'Tageslicht',
  both: 'Beides',
} satisfies AreaMessages<typeof en>;
