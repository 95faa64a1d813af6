import type { AreaMessages } from '../../messageTypes';
import type en from '../en/rooms';

export default {
  'living-room': 'Wohnzimmer',
  'dining-room': 'Esszimmer',
  'shop-window': 'Schaufenster',
} satisfies AreaMessages<typeof en>;
