import type { AreaMessages } from '../../messageTypes';
import type en from '../en/a11y';

// Annunci della pianta per i lettori di schermo (src/ui/planner/PlanAnnouncer.tsx).
export default {
  selected: 'Selezionato: {what}',
  changed: 'Modificato: {what}',
  cleared: 'Nessuna selezione',
  undone: 'Annullato. {what}',
  redone: 'Ripristinato. {what}',
  module: 'Modulo {index} di {count} sul binario {rail}',
  moduleInSystem: 'Modulo {index} di {count} sul binario {rail} del sistema {system}',
  rail: 'Binario {rail} del sistema {system}, {length}',
  object: 'Oggetto {index}',
  system: 'Sistema {system}',
  railCount: { one: '{count} binario', other: '{count} binari' },
  moduleCount: { one: '{count} modulo', other: '{count} moduli' },
  systemCount: { one: '{count} sistema di illuminazione', other: '{count} sistemi di illuminazione' },
  objectCount: { one: '{count} oggetto', other: '{count} oggetti' },
  room: 'Stanza: {systems}, {modules}, {objects}',
  moduleOff: 'spento',
} satisfies AreaMessages<typeof en>;
