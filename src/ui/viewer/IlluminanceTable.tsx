import type { IlluminanceStats } from '../../engines/view/lightStats';

const fmt = (v: number) => (v >= 100 ? v.toFixed(0) : v >= 10 ? v.toFixed(1) : v.toFixed(2));

function StatsRow({ label, s, testId }: { label: string; s: IlluminanceStats | null; testId: string }) {
  return (
    <tr data-testid={testId}>
      <th scope="row">{label}</th>
      <td>{s ? fmt(s.avg) : '–'}</td>
      <td>{s ? fmt(s.min) : '–'}</td>
      <td>{s ? fmt(s.max) : '–'}</td>
      <td>{s ? s.u0.toFixed(2) : '–'}</td>
    </tr>
  );
}

/** Ē, Emin, Emax, U0 of the floor and, when shown, the work plane ('–' until computed). */
export function IlluminanceTable({ floor, plane }: { floor: IlluminanceStats | null; plane: { height: number; stats: IlluminanceStats | null } | null }) {
  return (
    <table className="viewer3d-stats" aria-label="Illuminance">
      <thead>
        <tr>
          <th />
          <th scope="col">Ē lx</th>
          <th scope="col">Emin</th>
          <th scope="col">Emax</th>
          <th scope="col">U0</th>
        </tr>
      </thead>
      <tbody>
        <StatsRow label="Floor" s={floor} testId="stats-floor" />
        {plane && <StatsRow label={`Plane ${plane.height.toFixed(2)} m`} s={plane.stats} testId="stats-plane" />}
      </tbody>
    </table>
  );
}
