import { useI18n } from '../i18n/useI18n';
import type { MessageKey } from '../i18n/messageTypes';
import type { DaylightFactorValues } from './useDaylightFactorView';
import './registerView3dEnglish';

/** The rows: mean, min, U0 = min / mean, and EN 17037's share of the work plane at DF ≥ 2 % (the report's `shareAtTarget`). */
const ROWS: { key: 'mean' | 'min' | 'u0' | 'shareAbove2'; messageKey: MessageKey }[] = [
  { key: 'mean', messageKey: 'view3d.statsAverage' },
  { key: 'min', messageKey: 'view3d.statsMin' },
  { key: 'u0', messageKey: 'view3d.statsUniformity' },
  { key: 'shareAbove2', messageKey: 'view3d.dfShareAbove2' },
];

/** The work plane's daylight factor in the daylight-factor view ('–' until the maps settle); the same layout as IlluminanceTable. */
export function DaylightFactorTable({ values }: { values: DaylightFactorValues | null }) {
  const { t, format } = useI18n();
  const value = (key: (typeof ROWS)[number]['key']) => {
    if (!values) return '–';
    const v = values[key];
    if (key === 'shareAbove2') return format.number(100 * v, { maximumFractionDigits: 0 }) + ' %';
    return format.number(v, { minimumFractionDigits: 2, maximumFractionDigits: 2 });
  };
  return (
    <table className="viewer3d-stats" data-columns={1} data-testid="df-stats">
      <caption>{t('view3d.dfCaption')}</caption>
      <thead>
        <tr>
          <th scope="col">
            <span className="sr-only">{t('view3d.statsQuantity')}</span>
          </th>
          <th scope="col">{t('view3d.dfWorkPlane')}</th>
        </tr>
      </thead>
      <tbody>
        {ROWS.map((r) => (
          <tr key={r.key}>
            <th scope="row">{t(r.messageKey)}</th>
            <td data-testid={`df-${r.key}`}>{value(r.key)}</td>
          </tr>
        ))}
      </tbody>
    </table>
  );
}
