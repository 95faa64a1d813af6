import type { Room } from '../../core/model/configuration';
import type { SurfaceName } from '../../core/model/lightingScene';
import { WALL_NAMES, sameReflectance, type SurfaceTarget } from '../../core/model/reflectance';
import type { SurfaceFinish } from '../../core/model/surfaceFinish';
import type { ActionGate } from './actionGate';
import { FinishSelect } from './FinishSelect';

export interface SurfacesPanelProps {
  room: Room;
  finishes: readonly SurfaceFinish[];
  gate: ActionGate;
}

const WALL_LABELS: Record<(typeof WALL_NAMES)[number], string> = { north: 'North wall', south: 'South wall', west: 'West wall', east: 'East wall' };

/**
 * The room's own finishes (floor, ceiling, the walls together or one by one): each choice is one
 * undoable setReflectance, so the 3D view rebakes with the new reflectances.
 */
export function SurfacesPanel({ room, finishes, gate }: SurfacesPanelProps) {
  const r = room.reflectance;
  const wallsAlike = WALL_NAMES.every((w) => sameReflectance(r[w], r.north));
  const choose = (surface: SurfaceTarget) => (f: SurfaceFinish) => gate.run('setReflectance', { surface, value: f.reflectance });
  const reason = (surface: SurfaceTarget) => (f: SurfaceFinish) => gate.reason('setReflectance', { surface, value: f.reflectance });
  const row = (surface: SurfaceName, label: string) => (
    <FinishSelect key={surface} id={`finish-${surface}`} label={label} use={surface === 'floor' || surface === 'ceiling' ? surface : 'walls'} value={r[surface]} finishes={finishes} onChoose={choose(surface)} disabledReason={reason(surface)} testId={`finish-${surface}`} />
  );
  return (
    <section className="panel-section" aria-labelledby="surfaces-title" data-testid="surfaces">
      <h2 id="surfaces-title">Surfaces</h2>
      <div className="finish-list">
        {row('floor', 'Floor')}
        <FinishSelect id="finish-walls" label="Walls" use="walls" value={wallsAlike ? r.north : null} finishes={finishes} onChoose={choose('walls')} disabledReason={reason('walls')} testId="finish-walls" />
        {row('ceiling', 'Ceiling')}
      </div>
      <details className="finish-walls">
        <summary>Walls one by one</summary>
        <div className="finish-list">{WALL_NAMES.map((w) => row(w, WALL_LABELS[w]))}</div>
      </details>
    </section>
  );
}
