import type { AreaMessages } from '../../messageTypes';
import type en from '../en/shared';

export default {
  photometryWarnings: 'Avertissements sur les données photométriques',
  photometryWarningCount: { one: 'Données photométriques : {count} avertissement', many: 'Données photométriques : {count} d’avertissements', other: 'Données photométriques : {count} avertissements' },
} satisfies AreaMessages<typeof en>;
