import type { AreaMessages } from '../../messageTypes';
import type en from '../en/rooms';

export default {
  'living-room': 'Soggiorno',
  'dining-room': 'Sala da pranzo',
  'shop-window': 'Vetrina',
} satisfies AreaMessages<typeof en>;
