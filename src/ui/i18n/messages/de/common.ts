import type { AreaMessages } from '../../messageTypes';
import type en from '../en/common';

export default {
  languageLabel: 'Sprache',
  dismissMessage: 'Meldung schließen',
  close: 'Schließen',
  cancel: 'Abbrechen',
  ok: 'OK',
  loading: 'Wird geladen…',
  notANumber: '{label}: „{value}“ ist keine Zahl',
  labelWithReason: '{label}: {reason}',
} satisfies AreaMessages<typeof en>;
