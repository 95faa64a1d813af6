import type en from '../en/daylightPlan';
import type { AreaMessages } from '../../messageTypes';

export default {
  toggle: 'Fattore di luce diurna',
  hint: 'Fattore di luce diurna sul piano di lavoro con cielo coperto: illuminamento interno ÷ esterno',
  computing: 'Calcolo in corso…',
  noSky: 'A quest’ora il sole è sotto l’orizzonte: scegliere un’ora con luce diurna.',
  unavailable: 'Il fattore di luce diurna richiede la grafica 3D (WebGL 2), che questo browser non offre.',
  band: 'Vuoto: 0,5 m lungo le pareti (EN 17037).',
} satisfies AreaMessages<typeof en>;
