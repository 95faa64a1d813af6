import type { AreaMessages } from '../../messageTypes';
import type en from '../en/a11y';

// Annonces du plan pour les lecteurs d'écran (src/ui/planner/PlanAnnouncer.tsx).
export default {
  selected: 'Sélection : {what}',
  changed: 'Modifié : {what}',
  cleared: 'Aucune sélection',
  undone: 'Annulé. {what}',
  redone: 'Rétabli. {what}',
  module: 'Module {index} sur {count} du rail {rail}',
  moduleInSystem: 'Module {index} sur {count} du rail {rail} du système {system}',
  rail: 'Rail {rail} du système {system}, {length}',
  object: 'Objet {index}',
  system: 'Système {system}',
  railCount: { one: '{count} rail', other: '{count} rails' },
  moduleCount: { one: '{count} module', other: '{count} modules' },
  systemCount: { one: '{count} système d’éclairage', other: '{count} systèmes d’éclairage' },
  objectCount: { one: '{count} objet', other: '{count} objets' },
  room: 'Pièce : {systems}, {modules}, {objects}',
  moduleOff: 'éteint',
} satisfies AreaMessages<typeof en>;
