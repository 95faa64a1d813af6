import type { AreaMessages } from '../../messageTypes';
import type en from '../en/furniture';

export default {
  'dining-table': 'Table à manger',
  'coffee-table': 'Table basse',
  chair: 'Chaise',
  sofa: 'Canapé (trois places)',
  armchair: 'Fauteuil',
  sideboard: 'Buffet',
  'open-shelf': 'Étagère ouverte avec livres',
  bed: 'Lit double',
  desk: 'Bureau',
  'kitchen-island': 'Îlot de cuisine',
  picture: 'Tableau encadré',
  'floor-plant': 'Plante en pot',
  person: 'Personne debout',
} satisfies AreaMessages<typeof en>;
