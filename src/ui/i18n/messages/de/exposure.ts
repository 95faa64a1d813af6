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
  reAdapt: 'Neu anpassen',
  reAdaptHint:
    'Jetzt an das Licht auf dem Bildschirm anpassen. Die automatische Belichtung bleibt beim Dimmen, bei Filtern und Lichtszenen fest, damit dunkler auch dunkler aussieht; ein neuer Raum oder eine neue Kameraansicht passt sie neu an.',
  adaptation: 'Farbanpassung',
  adaptEye: 'Auge',
  adaptEyeHint: 'So, wie eine Person im Raum es sieht: Das Auge passt sich der Lichtfarbe weitgehend, aber nicht ganz an',
  adaptCamera: 'Kamera',
  adaptCameraHint: 'Eine Kamera mit Weißabgleich auf die Farbtemperatur unten',
  adaptNone: 'Keine',
  adaptNoneHint: 'Die physikalische Farbe des Lichts, ohne Anpassung',
  whiteBalance: 'Weißabgleich {cct} K',
} satisfies AreaMessages<typeof en>;
