import type { AreaMessages } from '../../messageTypes';
import type en from '../en/viewer';

export default {
  backTo2d: 'Retour au plan 2D',
  loading: 'Chargement de la vue 3D…',
  loadFailed: 'La vue 3D n’a pas pu être chargée ({problem}). Votre configuration est inchangée.',
  noDocument: 'La vue 3D a besoin d’une page de navigateur.',
  noWebgl2: 'Ce navigateur ou cet appareil n’a pas WebGL2, nécessaire à la vue 3D de la lumière. Le planificateur 2D fonctionne comme avant.',
  noFloatTargets: 'Cet appareil ne peut pas rendre dans des textures à virgule flottante (EXT_color_buffer_float), nécessaires au calcul de la lumière. Le planificateur 2D fonctionne comme avant.',
} satisfies AreaMessages<typeof en>;
