import type { IlluminanceStats } from '../../engines/view/lightStats';
import { useI18n } from '../i18n/useI18n';
import type { MessageKey } from '../i18n/messageTypes';
import './registerView3dEnglish';

/** Lux with as many decimals as a meter shows: 0 from 100 lx, 1 from 10 lx, else 2. */
const digits = (v: number) => (v >= 100 ? 0 : v >= 10 ? 1 : 2);

/** The rows: Ē, Emin, Emax and U0 = Emin / Ē (EN 12464-1), named in words ("Average", "Lowest", …). */
const ROWS: { key: 'avg' | 'min' | 'max' | 'u0'; messageKey: MessageKey }[] = [
  { key: 'avg', messageKey: 'view3d.statsAverage' },
  { key: 'min', messageKey: 'view3d.statsMin' },
  { key: 'max', messageKey: 'view3d.statsMax' },
  { key: 'u0', messageKey: 'view3d.statsUniformity' },
];

/**
 * Ē, Emin, Emax, U0 of the floor and, when shown, the work plane ('–' until computed). One layout
 * at every panel width (issue 27): a row per quantity and a column per surface, the table as wide
 * as the panel with fixed column shares, the unit once in the caption, so at most three short
 * columns sit side by side: numbers never wrap, names wrap between words (German's long word at its
 * soft hyphens), nothing overflows its cell, from the desktop's 220 px 3D panel to a phone.
 */
export function IlluminanceTable({ floor, plane }: { floor: IlluminanceStats | null; plane: { height: number; stats: IlluminanceStats | null } | null }) {
  const { t, format } = useI18n();
  const columns = [{ id: 'floor', label: t('app.floor'), s: floor }, ...(plane ? [{ id: 'plane', label: t('view3d.planeAt', { height: format.metres(plane.height) }), s: plane.stats }] : [])];
  const value = (s: IlluminanceStats | null, key: (typeof ROWS)[number]['key']) => {
    if (!s) return '–';
    const v = s[key];
    return key === 'u0' ? format.number(v, { minimumFractionDigits: 2, maximumFractionDigits: 2 }) : format.number(v, { minimumFractionDigits: digits(v), maximumFractionDigits: digits(v), useGrouping: false });
  };
  return (
    <table className="viewer3d-stats" data-columns={columns.length}>
      {/* The unit once, for the whole table: the numbers stay short enough for three columns in a 220 px panel. */}
      <caption>{t('view3d.statsCaption')}</caption>
      <thead>
        <tr>
          {/* The corner cell heads the column of quantities: named for screen readers, not shown. */}
          <th scope="col">
            <span className="sr-only">{t('view3d.statsQuantity')}</span>
          </th>
          {columns.map((c) => (
            <th key={c.id} scope="col" data-testid={`stats-${c.id}`}>
              {c.label}
            </th>
          ))}
        </tr>
      </thead>
      <tbody>
        {ROWS.map((r) => (
          <tr key={r.key}>
            <th scope="row">{t(r.messageKey)}</th>
            {columns.map((c) => (
              <td key={c.id} data-testid={`stats-${c.id}-${r.key}`}>
                {value(c.s, r.key)}
              </td>
            ))}
          </tr>
        ))}
      </tbody>
    </table>
  );
}
