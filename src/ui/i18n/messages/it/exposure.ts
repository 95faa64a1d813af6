import type { AreaMessages } from '../../messageTypes';
import type en from '../en/exposure';

export default {
  group: 'Esposizione',
  auto: 'Automatica',
  lock: 'Blocca esposizione',
  lockHint: 'Mantieni l’esposizione attuale, così un’altra configurazione o regolazione appare più chiara o più scura',
  compensation: 'Esposizione {ev} EV',
  resetCompensation: 'Reimposta',
  ev100: 'EV100 {ev}',
  ev100Field: 'Valore di esposizione a ISO 100 (più alto = più scuro)',
  reAdapt: 'Riadatta',
  reAdaptHint: 'Adatta ora alla luce sullo schermo. L’esposizione automatica resta ferma mentre regoli, cambi filtri o scene luminose, così più scuro appare più scuro; una nuova stanza o inquadratura la riadatta.',
  adaptation: 'Adattamento cromatico',
  adaptEye: 'Occhio',
  adaptEyeHint: 'Come lo vede una persona nella stanza: l’occhio si adatta in gran parte, ma non del tutto, al colore della luce',
  adaptCamera: 'Fotocamera',
  adaptCameraHint: 'Una fotocamera con bilanciamento del bianco sulla temperatura di colore qui sotto',
  adaptNone: 'Nessuno',
  adaptNoneHint: 'Il colore fisico della luce, senza adattamento',
  whiteBalance: 'Bilanciamento del bianco {cct} K',
} satisfies AreaMessages<typeof en>;
