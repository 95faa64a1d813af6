import type en from '../en/daylight';
import type { AreaMessages } from '../../messageTypes';

export default {
  on: 'Cielo e sole attraverso le finestre',
  noWindows: 'Aggiungere finestre nella forma della stanza per far entrare la luce diurna.',
  place: 'Luogo',
  coordinates: 'Coordinate…',
  latitude: 'Latitudine (°, nord +)',
  longitude: 'Longitudine (°, est +)',
  timeZone: 'Fuso orario (h avanti su UTC)',
  date: 'Data',
  day: 'Giorno',
  month: 'Mese',
  year: 'Anno',
  time: 'Ora del giorno',
  timeValue: 'ore {time}',
  sky: 'Cielo',
  skyClear: 'Sereno con sole',
  skyOvercast: 'Coperto',
  skyUniform: 'Uniforme (test)',
  sunUp: 'Sole a {elevation}° sopra l’orizzonte, {azimuth}° da nord',
  sunDown: 'Il sole è sotto l’orizzonte: nessuna luce diurna a quest’ora',
  sources: 'Mostra',
  electric: 'Luce elettrica',
  daylight: 'Luce diurna',
  both: 'Entrambe',
} satisfies AreaMessages<typeof en>;
