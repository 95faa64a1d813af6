import type { AreaMessages } from '../../messageTypes';
import type en from '../en/viewer';

export default {
  backTo2d: 'Zurück zum 2D-Plan',
  loading: '3D-Ansicht wird geladen…',
  loadFailed: 'Die 3D-Ansicht konnte nicht geladen werden ({problem}). Ihre Konfiguration ist unverändert.',
  noDocument: 'Die 3D-Ansicht braucht eine Browserseite.',
  noWebgl2: 'Dieser Browser oder dieses Gerät hat kein WebGL2, das die 3D-Lichtansicht braucht. Der 2D-Planer funktioniert weiter.',
  noFloatTargets: 'Dieses Gerät kann nicht in Gleitkomma-Texturen rendern (EXT_color_buffer_float), die die Lichtberechnung braucht. Der 2D-Planer funktioniert weiter.',
} satisfies AreaMessages<typeof en>;
