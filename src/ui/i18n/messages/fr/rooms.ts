import type { AreaMessages } from '../../messageTypes';
import type en from '../en/rooms';

export default {
  'living-room': 'Salon',
  'dining-room': 'Salle à manger',
  'shop-window': 'Vitrine',
} satisfies AreaMessages<typeof en>;
