import type { IlluminanceStats } from '../../engines/view/lightStats';
import { useI18n } from '../i18n/useI18n';
import './registerView3dEnglish';

/** Lux with as many decimals as a meter shows: 0 from 100 lx, 1 from 10 lx, else 2. */
const digits = (v: number) => (v >= 100 ? 0 : v >= 10 ? 1 : 2);

function StatsRow({ label, s, testId }: { label: string; s: IlluminanceStats | null; testId: string }) {
  const { format } = useI18n();
  const fmt = (v: number) => format.number(v, { minimumFractionDigits: digits(v), maximumFractionDigits: digits(v), useGrouping: false });
  return (
    <tr data-testid={testId}>
      <th scope="row">{label}</th>
      <td>{s ? fmt(s.avg) : '–'}</td>
      <td>{s ? fmt(s.min) : '–'}</td>
      <td>{s ? fmt(s.max) : '–'}</td>
      <td>{s ? format.number(s.u0, { minimumFractionDigits: 2, maximumFractionDigits: 2 }) : '–'}</td>
    </tr>
  );
}

/** Ē, Emin, Emax, U0 of the floor and, when shown, the work plane ('–' until computed). */
export function IlluminanceTable({ floor, plane }: { floor: IlluminanceStats | null; plane: { height: number; stats: IlluminanceStats | null } | null }) {
  const { t, format } = useI18n();
  return (
    <table className="viewer3d-stats" aria-label={t('view3d.illuminance')}>
      <thead>
        <tr>
          {/* The corner cell heads the column of row names (floor, plane): named for screen readers, not shown. */}
          <th scope="col">
            <span className="sr-only">{t('view3d.statsSurface')}</span>
          </th>
          <th scope="col">Ē lx</th>
          <th scope="col">Emin</th>
          <th scope="col">Emax</th>
          <th scope="col">U0</th>
        </tr>
      </thead>
      <tbody>
        <StatsRow label={t('app.floor')} s={floor} testId="stats-floor" />
        {plane && <StatsRow label={t('view3d.planeAt', { height: format.metres(plane.height) })} s={plane.stats} testId="stats-plane" />}
      </tbody>
    </table>
  );
}
