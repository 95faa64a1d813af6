import type { AreaMessages } from '../../messageTypes';
import type en from '../en/furniture';

export default {
  'dining-table': 'Esstisch',
  'coffee-table': 'Couchtisch',
  chair: 'Stuhl',
  sofa: 'Sofa (drei Sitze)',
  armchair: 'Sessel',
  sideboard: 'Sideboard',
  'open-shelf': 'Offenes Regal mit Büchern',
  bed: 'Doppelbett',
  desk: 'Schreibtisch',
  'kitchen-island': 'Kochinsel',
  picture: 'Gerahmtes Bild',
  'floor-plant': 'Bodenpflanze',
  person: 'Stehende Person',
} satisfies AreaMessages<typeof en>;
