import type { AreaMessages } from '../../messageTypes';
import type en from '../en/shared';

export default {
  photometryWarnings: 'Hinweise zu den photometrischen Daten',
  photometryWarningCount: { one: 'Photometrische Daten: {count} Hinweis', other: 'Photometrische Daten: {count} Hinweise' },
} satisfies AreaMessages<typeof en>;
