import type { AreaMessages } from '../../messageTypes';
import type en from '../en/furniture';

export default {
  'dining-table': 'Tavolo da pranzo',
  'coffee-table': 'Tavolino',
  chair: 'Sedia',
  sofa: 'Divano (tre posti)',
  armchair: 'Poltrona',
  sideboard: 'Credenza',
  'open-shelf': 'Scaffale aperto con libri',
  bed: 'Letto matrimoniale',
  desk: 'Scrivania',
  'kitchen-island': 'Isola della cucina',
  picture: 'Quadro incorniciato',
  'floor-plant': 'Pianta da terra',
  person: 'Persona in piedi',
} satisfies AreaMessages<typeof en>;
