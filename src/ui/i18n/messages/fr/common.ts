import type { AreaMessages } from '../../messageTypes';
import type en from '../en/common';

export default {
  languageLabel: 'Langue',
  dismissMessage: 'Fermer le message',
  close: 'Fermer',
  cancel: 'Annuler',
  ok: 'OK',
  loading: 'Chargement…',
  notANumber: '{label} : « {value} » n’est pas un nombre',
  labelWithReason: '{label} : {reason}',
} satisfies AreaMessages<typeof en>;
