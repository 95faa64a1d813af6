import './registerRoomShapeEnglish';
import type { Configuration, RoomShape } from '../../core/model/configuration/configuration';
import { cornerAngle, currentShape, wallFinishes, wallLength } from '../../core/model/actions/roomShapeGeometry';
import type { ActionGate } from './actionGate';
import { GatedButton } from './GatedButton';
import { FinishSelect } from './FinishSelect';
import { defaultSurfaceFinishes } from '../../core/catalog/surfaceFinishes';
import { CommitField } from '../shared/CommitField';
import { useI18n } from '../i18n/useI18n';
import type { MessageKey } from '../i18n/messageTypes';
import { KIND_KEYS } from './RoomShapeHandles';
import { WindowGlazing } from './WindowGlazing';
import type { Picked } from './useShapeDrag';

/** A labelled number field whose commit is one action (its refusal shown by the gate). */
function ShapeField({ labelKey, value, commit, testId, decimals = 2, gate }: { labelKey: MessageKey; value: number; commit: (v: number) => string | null; testId: string; decimals?: number; gate: ActionGate }) {
  const { t } = useI18n();
  return (
    <label className="room-shape-field">
      <span>{t(labelKey)}</span>
      <CommitField label={t(labelKey)} value={value} decimals={decimals} onCommit={commit} onRefused={gate.explain} testId={testId} />
    </label>
  );
}

const ADD_KEYS = { door: 'roomShape.addDoor', window: 'roomShape.addWindow', opening: 'roomShape.addOpening' } as const satisfies Record<string, MessageKey>;

/** A wall: its length, split, new openings, slope and finish. */
function WallForm({ config, shape, wall, gate }: { config: Configuration; shape: RoomShape; wall: number; gate: ActionGate }) {
  const { t } = useI18n();
  const length = wallLength(shape.outline, wall);
  const slope = shape.slopes.find((s) => s.wall === wall);
  return (
    <>
      <ShapeField gate={gate} labelKey="roomShape.wallLength" value={length} commit={(v) => gate.attempt('setRoomWallLength', { wall, length: v })} testId="room-wall-length" />
      <div className="room-shape-buttons">
        <GatedButton gate={gate} action="splitRoomWall" params={{ wall, at: Math.round((length / 2) * 1000) / 1000 }} label={t('roomShape.split')} testId="room-wall-split">
          {t('roomShape.split')}
        </GatedButton>
        {(['door', 'window', 'opening'] as const).map((kind) => (
          <GatedButton key={kind} gate={gate} action="addRoomOpening" params={{ wall, kind }} label={t(ADD_KEYS[kind])} testId={`room-add-${kind}`}>
            {t(ADD_KEYS[kind])}
          </GatedButton>
        ))}
        {!slope && (
          <GatedButton gate={gate} action="setRoomSlope" params={{ wall, kneeHeight: Math.min(1.2, config.room.height), pitch: 40 }} label={t('roomShape.addSlope')} testId="room-add-slope">
            {t('roomShape.addSlope')}
          </GatedButton>
        )}
      </div>
      <FinishSelect
        id={`room-wall-finish-${wall}`}
        label={t('app.walls')}
        use="walls"
        value={wallFinishes(config.room, shape)[wall]}
        finishes={defaultSurfaceFinishes}
        onChoose={(f) => gate.run('setWallFinish', { wall, value: f.reflectance })}
        disabledReason={(f) => gate.reason('setWallFinish', { wall, value: f.reflectance })}
        testId="room-wall-finish"
      />
      {slope && (
        <div className="room-shape-slope" data-testid="room-slope-fields">
          <ShapeField gate={gate} labelKey="roomShape.knee" value={slope.kneeHeight} commit={(v) => gate.attempt('setRoomSlope', { wall, kneeHeight: v, pitch: slope.pitch })} testId="room-slope-knee" />
          <ShapeField gate={gate} labelKey="roomShape.pitch" value={slope.pitch} commit={(v) => gate.attempt('setRoomSlope', { wall, kneeHeight: slope.kneeHeight, pitch: v })} testId="room-slope-pitch" decimals={0} />
          <GatedButton gate={gate} action="removeRoomSlope" params={{ wall }} label={t('roomShape.removeSlope')} testId="room-remove-slope">
            {t('roomShape.removeSlope')}
          </GatedButton>
        </div>
      )}
    </>
  );
}

/** A corner: its inside angle; remove it. */
function CornerForm({ shape, corner, gate, onClose }: { shape: RoomShape; corner: number; gate: ActionGate; onClose: () => void }) {
  const { t } = useI18n();
  return (
    <>
      <ShapeField gate={gate} labelKey="roomShape.angle" value={cornerAngle(shape.outline, corner)} commit={(v) => gate.attempt('setRoomCornerAngle', { corner, degrees: v })} testId="room-corner-angle" decimals={1} />
      <GatedButton gate={gate} action="removeRoomCorner" params={{ corner }} label={t('roomShape.removeCorner')} testId="room-remove-corner" onRan={onClose}>
        {t('roomShape.removeCorner')}
      </GatedButton>
    </>
  );
}

/** An opening: its place and size, a window's glazing; remove it. */
function OpeningForm({ shape, opening, gate, onClose }: { shape: RoomShape; opening: number; gate: ActionGate; onClose: () => void }) {
  const { t } = useI18n();
  const o = shape.openings[opening];
  return (
    <>
      <ShapeField gate={gate} labelKey="roomShape.offset" value={o.offset} commit={(v) => gate.attempt('setRoomOpening', { opening, offset: v })} testId="room-opening-offset" />
      <ShapeField gate={gate} labelKey="roomShape.width" value={o.width} commit={(v) => gate.attempt('setRoomOpening', { opening, width: v })} testId="room-opening-width" />
      <ShapeField gate={gate} labelKey="roomShape.height" value={o.height} commit={(v) => gate.attempt('setRoomOpening', { opening, height: v })} testId="room-opening-height" />
      {o.kind !== 'door' && <ShapeField gate={gate} labelKey="roomShape.sill" value={o.sill} commit={(v) => gate.attempt('setRoomOpening', { opening, sill: v })} testId="room-opening-sill" />}
      {o.kind === 'window' && <WindowGlazing opening={opening} value={o.transmittance} gate={gate} />}
      <GatedButton gate={gate} action="removeRoomOpening" params={{ opening }} label={t('roomShape.remove')} testId="room-remove-opening" onRan={onClose}>
        {t('roomShape.remove')}
      </GatedButton>
    </>
  );
}

/** What was tapped, edited: a wall's length, split, slope and openings; a corner's angle; an opening's place, size and glazing. */
export function RoomShapeSheet({ config, picked, gate, onClose, maxHeight }: { config: Configuration; picked: NonNullable<Picked>; gate: ActionGate; onClose: () => void; maxHeight: number }) {
  const { t } = useI18n();
  const shape = currentShape(config.room);
  const n = shape.outline.length;
  let title: string;
  let body;
  if (picked.kind === 'wall' && picked.index < n) {
    title = t('roomShape.wall', { wall: picked.index });
    body = <WallForm config={config} shape={shape} wall={picked.index} gate={gate} />;
  } else if (picked.kind === 'corner' && picked.index < n) {
    title = t('roomShape.corner', { corner: picked.index });
    body = <CornerForm shape={shape} corner={picked.index} gate={gate} onClose={onClose} />;
  } else if (picked.kind === 'opening' && shape.openings[picked.index]) {
    const o = shape.openings[picked.index];
    title = `${t(KIND_KEYS[o.kind])} · ${t('roomShape.wall', { wall: o.wall })}`;
    body = <OpeningForm shape={shape} opening={picked.index} gate={gate} onClose={onClose} />;
  } else {
    // What was picked is gone (an undo, a preset): nothing to edit.
    return null;
  }
  return (
    <section className="room-shape-sheet" data-plan-control aria-label={title} data-testid="room-shape-sheet" style={{ maxHeight }}>
      <header>
        <h3>{title}</h3>
        <button type="button" className="btn" onClick={onClose} aria-label={t('common.close')}>
          ×
        </button>
      </header>
      <div className="room-shape-fields">{body}</div>
    </section>
  );
}
