import type { AreaMessages } from '../../messageTypes';
import type en from '../en/a11y';

// Ansagen für Screenreader im Plan (src/ui/planner/PlanAnnouncer.tsx).
export default {
  selected: '{what} ausgewählt',
  changed: 'Geändert: {what}',
  cleared: 'Nichts ausgewählt',
  undone: 'Rückgängig gemacht. {what}',
  redone: 'Wiederhergestellt. {what}',
  module: 'Modul {index} von {count} auf Schiene {rail}',
  moduleInSystem: 'Modul {index} von {count} auf Schiene {rail} von System {system}',
  rail: 'Schiene {rail} von System {system}, {length}',
  object: 'Objekt {index}',
  system: 'System {system}',
  railCount: { one: '{count} Schiene', other: '{count} Schienen' },
  moduleCount: { one: '{count} Modul', other: '{count} Module' },
  systemCount: { one: '{count} Lichtsystem', other: '{count} Lichtsysteme' },
  objectCount: { one: '{count} Objekt', other: '{count} Objekte' },
  room: 'Raum: {systems}, {modules}, {objects}',
  moduleOff: 'aus',
} satisfies AreaMessages<typeof en>;
