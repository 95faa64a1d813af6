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
} satisfies AreaMessages<typeof en>;
