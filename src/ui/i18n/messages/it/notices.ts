import type { AreaMessages } from '../../messageTypes';
import type en from '../en/notices';

export default {
  shareLinkNotice: 'Link di condivisione: {notice}',
  driverFull: 'il driver da {capacity} W è pieno: {used} W in uso; scegli il driver da {larger} W nelle opzioni del sistema o aggiungi una seconda alimentazione',
  driverFullAddFeed: 'il driver da {capacity} W è pieno: {used} W in uso; aggiungi una seconda alimentazione nelle opzioni del sistema',
  feedOverload: 'l’alimentazione {n} porterebbe {load} W, più del suo driver da {capacity} W; aggiungi una seconda alimentazione o scegli un driver più potente',
  driverTooSmall: 'il {driver} da {capacity} W non può portare i {load} W dell’alimentazione {n}; scegli un driver più potente o aggiungi un’alimentazione',
  noFreeSpace: 'nessuno spazio libero per «{name}» in questa stanza',
  noRoomForModule: 'non c’è spazio per un altro {name} ({length} m) su questo binario',
  noFreeGap: 'nessuno spazio libero su questo binario può ospitare un {name} ({length} m): il più grande è {gap} m; distanzia i moduli o scegli una distribuzione',
  'outside-room': 'il sistema {id} esce dalla stanza di {width} × {depth} m',
  'self-overlap': 'il sistema {id} si sovrappone a sé stesso',
  'system-overlap': 'il sistema {id} si sovrappone al sistema {other}',
  'suspension-range': 'la sospensione deve essere compresa tra {min} e {max} m (ricevuto {value})',
  'suspension-floor': 'i moduli sarebbero a {hang} m, sotto il minimo di {min} m dal pavimento',
  'rail-length-range': 'la lunghezza del binario deve essere compresa tra {min} e {max} m (ricevuto {value})',
  'rail-length-grid': 'la lunghezza del binario deve essere un multiplo di {step} m (ricevuto {value})',
  'modules-do-not-fit': 'i moduli del binario {rail} non entrano nei suoi {length} m con la distribuzione «{distribution}»',
} satisfies AreaMessages<typeof en>;
