import type { AreaMessages } from '../../messageTypes';
import type en from '../en/exposure';

export default {
  group: 'Belichtung',
  auto: 'Automatisch',
  lock: 'Belichtung festhalten',
  lockHint: 'Aktuelle Belichtung beibehalten, damit eine andere Konfiguration oder Dimmung heller oder dunkler erscheint',
  compensation: 'Belichtung {ev} LW',
  resetCompensation: 'Zurücksetzen',
  ev100: 'LW100 {ev}',
  ev100Field: 'Lichtwert bei ISO 100 (höher ist dunkler)',
} satisfies AreaMessages<typeof en>;
