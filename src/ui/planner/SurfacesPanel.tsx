import type { Room } from '../../core/model/configuration/configuration';
import type { SurfaceName } from '../../core/model/lightingScene/lightingScene';
import { WALL_NAMES, sameReflectance, type SurfaceTarget } from '../../core/model/lightingScene/reflectance';
import type { SurfaceFinish } from '../../core/model/catalogSchema/surfaceFinish';
import type { ActionGate } from './actionGate';
import { FinishSelect } from './FinishSelect';
import { useI18n } from '../i18n/useI18n';
import type { MessageKey } from '../i18n/messageTypes';

export interface SurfacesPanelProps {
  room: Room;
  finishes: readonly SurfaceFinish[];
  gate: ActionGate;
  /** Opens the plan's room-shape mode (docs/planner.md, "Rooms of any shape"). */
  onEditShape?: () => void;
}

const WALL_LABELS: Record<(typeof WALL_NAMES)[number], MessageKey> = { north: 'planner.northWall', south: 'planner.southWall', west: 'planner.westWall', east: 'planner.eastWall' };

/**
 * The room's own finishes (floor, ceiling, the walls together or one by one): each choice is one
 * undoable setReflectance, so the 3D view rebakes with the new reflectances.
 */
export function SurfacesPanel({ room, finishes, gate, onEditShape }: SurfacesPanelProps) {
  const { t } = useI18n();
  const r = room.reflectance;
  const wallsAlike = WALL_NAMES.every((w) => sameReflectance(r[w], r.north));
  const choose = (surface: SurfaceTarget) => (f: SurfaceFinish) => gate.run('setReflectance', { surface, value: f.reflectance });
  const reason = (surface: SurfaceTarget) => (f: SurfaceFinish) => gate.reason('setReflectance', { surface, value: f.reflectance });
  const row = (surface: SurfaceName, label: string) => (
    <FinishSelect
      key={surface}
      id={`finish-${surface}`}
      label={label}
      use={surface === 'floor' || surface === 'ceiling' ? surface : 'walls'}
      value={r[surface]}
      finishes={finishes}
      onChoose={choose(surface)}
      disabledReason={reason(surface)}
      testId={`finish-${surface}`}
    />
  );
  return (
    <section className="panel-section" aria-labelledby="surfaces-title" data-testid="surfaces">
      <h2 id="surfaces-title">{t('app.surfaces')}</h2>
      {onEditShape && (
        <button type="button" className="btn" onClick={onEditShape} data-testid="edit-room-shape">
          {t('planner.editRoomShape')}
        </button>
      )}
      <div className="finish-list">
        {row('floor', t('app.floor'))}
        <FinishSelect id="finish-walls" label={t('app.walls')} use="walls" value={wallsAlike ? r.north : null} finishes={finishes} onChoose={choose('walls')} disabledReason={reason('walls')} testId="finish-walls" />
        {row('ceiling', t('app.ceiling'))}
      </div>
      {/* A drawn room's walls are not the box's four: each has its finish in the room-shape mode's wall sheet. */}
      {!room.shape && (
        <details className="finish-walls">
          <summary>{t('planner.wallsOneByOne')}</summary>
          <div className="finish-list">{WALL_NAMES.map((w) => row(w, t(WALL_LABELS[w])))}</div>
        </details>
      )}
    </section>
  );
}
