import type en from '../en/daylightPlan';
import type { AreaMessages } from '../../messageTypes';

export default {
  toggle: 'Facteur de lumière du jour',
  hint: 'Facteur de lumière du jour sur le plan de travail par ciel couvert\u00a0: éclairement intérieur ÷ extérieur',
  computing: 'Calcul en cours…',
  noSky: 'Le soleil est sous l’horizon à cette heure\u00a0: choisissez une heure de jour.',
  unavailable: 'Le facteur de lumière du jour demande le graphisme 3D (WebGL 2), que ce navigateur n’offre pas.',
  band: 'Vide\u00a0: 0,5 m le long des murs (EN 17037).',
} satisfies AreaMessages<typeof en>;
