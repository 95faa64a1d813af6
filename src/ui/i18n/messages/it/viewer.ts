import type { AreaMessages } from '../../messageTypes';
import type en from '../en/viewer';

export default {
  backTo2d: 'Torna alla pianta 2D',
  loading: 'Caricamento della vista 3D…',
  loadFailed: 'Non è stato possibile caricare la vista 3D ({problem}). La configurazione è invariata.',
  noDocument: 'La vista 3D richiede una pagina del browser.',
  noWebgl2: 'Questo browser o dispositivo non ha WebGL2, necessario per la vista 3D della luce. Il planner 2D funziona come prima.',
  noFloatTargets: 'Questo dispositivo non può eseguire il rendering su texture in virgola mobile (EXT_color_buffer_float), necessarie al calcolo della luce. Il planner 2D funziona come prima.',
} satisfies AreaMessages<typeof en>;
