import type en from '../en/expert';
import type { AreaMessages } from '../../messageTypes';

export default {
  switch: 'Strumenti per esperti',
  note: 'Controllo DMX dal vivo, download Radiance, note sui dati fotometrici',
  savedRadiance: '{name} salvato (estrai, poi sh render.sh)',
  radianceFailed: 'L’esportazione per Radiance non è riuscita: {problem}',
  radianceTitle: 'Una cartella per il renderer Radiance: scena, apparecchi, viste, render.sh',
  downloadRadiance: 'Scarica per Radiance',
} satisfies AreaMessages<typeof en>;
