import type en from '../en/daylight';
import type { AreaMessages } from '../../messageTypes';

export default {
  on: 'Ciel et soleil par les fenêtres',
  noWindows: 'Ajoutez des fenêtres dans la forme de la pièce pour laisser entrer la lumière du jour.',
  place: 'Lieu',
  coordinates: 'Coordonnées…',
  latitude: 'Latitude (°, nord +)',
  longitude: 'Longitude (°, est +)',
  timeZone: 'Fuseau horaire (h d’avance sur UTC)',
  date: 'Date du jour',
  day: 'Jour',
  month: 'Mois',
  year: 'Année',
  time: 'Heure du jour',
  timeValue: '{time} h',
  sky: 'Ciel',
  skyClear: 'Clair avec soleil',
  skyOvercast: 'Couvert',
  skyUniform: 'Uniforme (test)',
  sunUp: 'Soleil à {elevation}° au-dessus de l’horizon, {azimuth}° depuis le nord',
  sunDown: 'Le soleil est sous l’horizon\u00a0: pas de lumière du jour à cette heure',
  sources: 'Afficher',
  electric: 'Lumière électrique',
  daylight: 'Lumière du jour',
  both: 'Les deux',
} satisfies AreaMessages<typeof en>;
