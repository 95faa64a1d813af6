import type { AreaMessages } from '../../messageTypes';
import type en from '../en/common';

export default {
  languageLabel: 'Lingua',
  dismissMessage: 'Chiudi il messaggio',
  close: 'Chiudi',
  cancel: 'Annulla',
  ok: 'OK',
  loading: 'Caricamento…',
  notANumber: '{label}: «{value}» non è un numero',
  labelWithReason: '{label}: {reason}',
} satisfies AreaMessages<typeof en>;
