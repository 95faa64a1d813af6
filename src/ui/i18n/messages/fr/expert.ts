import type en from '../en/expert';
import type { AreaMessages } from '../../messageTypes';

export default {
  switch: 'Outils experts',
  note: 'Pilotage DMX en direct, export Radiance, notes sur les données photométriques',
  savedRadiance: '{name} enregistré (décompresser, puis sh render.sh)',
  radianceFailed: 'L’export Radiance a échoué : {problem}',
  radianceTitle: 'Un dossier pour le moteur de rendu Radiance : scène, luminaires, vues, render.sh',
  downloadRadiance: 'Télécharger pour Radiance',
} satisfies AreaMessages<typeof en>;
