import type en from '../en/expert';
import type { AreaMessages } from '../../messageTypes';

export default {
  switch: 'Expertenwerkzeuge',
  note: 'DMX-Livesteuerung, Radiance-Download, Hinweise zu Lichtdaten',
  savedRadiance: '{name} gespeichert (entpacken, dann sh render.sh)',
  radianceFailed: 'Der Radiance-Export ist fehlgeschlagen: {problem}',
  radianceTitle: 'Ein Ordner für den Radiance-Renderer: Szene, Leuchten, Ansichten, render.sh',
  downloadRadiance: 'Für Radiance herunterladen',
} satisfies AreaMessages<typeof en>;
