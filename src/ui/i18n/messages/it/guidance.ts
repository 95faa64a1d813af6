import type { AreaMessages } from '../../messageTypes';
import type en from '../en/guidance';

// Primo avvio (issue 27): suggerimenti sulla pianta vuota e rimedi offerti su un comando rifiutato.
export default {
  firstRunTitle: 'Inizia con un modello',
  firstRunHint: 'Tocca un modello per posizionarlo nella stanza. Potrai poi cambiare ogni binario e ogni luce.',
  firstRunPlace: 'Posiziona {name}',
  firstRunAll: 'Tutti i modelli',
  useDriver: 'Usa il driver da {capacity} W',
  addFeed: 'Aggiungi un’alimentazione con il driver da {capacity} W',
  lengthenRail: 'Allunga il binario {rail} a {length} m',
  distribution_start: 'Allinea i moduli dall’inizio',
  distribution_end: 'Allinea i moduli dalla fine',
  'distribution_inside-centred': 'Distribuisci i moduli in modo uniforme',
  'distribution_outside-centred': 'Distribuisci i moduli in modo uniforme, quelli esterni alle estremità',
  and: '{first}, poi {second}',
  withPrice: '{action} ({price})',
} satisfies AreaMessages<typeof en>;
