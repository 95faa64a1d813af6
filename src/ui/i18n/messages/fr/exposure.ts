import type { AreaMessages } from '../../messageTypes';
import type en from '../en/exposure';

export default {
  group: 'Exposition',
  auto: 'Automatique',
  lock: 'Verrouiller l’exposition',
  lockHint: 'Garder l’exposition actuelle, pour qu’une autre configuration ou gradation paraisse plus claire ou plus sombre',
  compensation: 'Exposition {ev} IL',
  resetCompensation: 'Réinitialiser',
  ev100: 'IL100 {ev}',
  ev100Field: 'Indice de lumination à ISO 100 (plus haut = plus sombre)',
} satisfies AreaMessages<typeof en>;
