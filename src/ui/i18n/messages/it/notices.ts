import type { AreaMessages } from '../../messageTypes';
import type en from '../en/notices';

export default {
  shareLinkNotice: 'Link di condivisione: {notice}',
  driverFull: 'il driver da {capacity} W è pieno: {used} W in uso; aggiungi una seconda alimentazione o scegli un driver più potente',
  feedOverload: 'l’alimentazione {n} porterebbe {load} W, più del suo driver da {capacity} W; aggiungi una seconda alimentazione o scegli un driver più potente',
  driverTooSmall: 'il {driver} da {capacity} W non può portare i {load} W dell’alimentazione {n}; scegli un driver più potente o aggiungi un’alimentazione',
  noFreeSpace: 'nessuno spazio libero per «{name}» in questa stanza',
  noRoomForModule: 'non c’è spazio per un altro {name} ({length} m) su questo binario',
  noFreeGap: 'nessuno spazio libero su questo binario può ospitare un {name} ({length} m): il più grande è {gap} m; distanzia i moduli o scegli una distribuzione',
} satisfies AreaMessages<typeof en>;
