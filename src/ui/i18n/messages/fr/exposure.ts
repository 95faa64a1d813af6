import type { AreaMessages } from '../../messageTypes';
import type en from '../en/exposure';

export default {
  group: 'Exposition',
  auto: 'Automatique',
  lock: 'Verrouiller l’exposition',
  lockHint: 'Garder l’exposition actuelle, pour qu’une autre configuration ou gradation paraisse plus claire ou plus sombre',
  compensation: 'Exposition {ev} IL',
  resetCompensation: 'Réinitialiser',
  ev100: 'IL100 {ev}',
  ev100Field: 'Indice de lumination à ISO 100 (plus haut = plus sombre)',
  reAdapt: 'Réadapter',
  reAdaptHint:
    'S’adapter maintenant à la lumière affichée. L’exposition automatique reste fixe pendant la gradation, les filtres et les scènes lumineuses, pour que plus sombre paraisse plus sombre ; une nouvelle pièce ou vue de caméra la réadapte.',
  adaptation: 'Adaptation chromatique',
  adaptEye: 'Œil',
  adaptEyeHint: 'Comme le voit une personne dans la pièce : l’œil s’adapte en grande partie, mais pas entièrement, à la couleur de la lumière',
  adaptCamera: 'Appareil photo',
  adaptCameraHint: 'Un appareil photo avec la balance des blancs sur la température de couleur ci-dessous',
  adaptNone: 'Aucune',
  adaptNoneHint: 'La couleur physique de la lumière, sans adaptation',
  whiteBalance: 'Balance des blancs {cct} K',
} satisfies AreaMessages<typeof en>;
