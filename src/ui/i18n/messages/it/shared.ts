import type { AreaMessages } from '../../messageTypes';
import type en from '../en/shared';

export default {
  photometryWarnings: 'Avvisi sui dati fotometrici',
  photometryWarningCount: { one: 'Dati fotometrici: {count} avviso', many: 'Dati fotometrici: {count} di avvisi', other: 'Dati fotometrici: {count} avvisi' },
} satisfies AreaMessages<typeof en>;
