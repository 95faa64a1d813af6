import { useMemo } from 'react';
import { OBJECT_SCALE_LIMITS, WALL_NAMES, type Configuration, type RoomObject } from '../../core/model/configuration';
import { findFurnitureItem } from '../../core/model/furniture/furnitureLibrary';
import { findObjectFinish } from '../../core/model/furniture/objectFinishes';
import { sourceMesh, sourceName } from '../../core/model/objectGeometry';
import { positionBounds } from '../../core/mesh/triangleMesh';
import type { ActionGate } from './actionGate';
import { CommitField } from './CommitField';
import { itemDimensions } from './FurniturePanel';
import { GatedButton } from './GatedButton';
import { ObjectFinishSelect } from './ObjectFinishSelect';
import { OptionChips } from './OptionChips';
import { OptionsSection } from './OptionsSection';

/** Turns offered for a floor object, degrees (positive: counterclockwise seen from above, "left"). */
const TURNS = [-90, -15, 15, 90] as const;

/**
 * A selected object's settings: its size (uniform scale, with the real dimensions in cm), its
 * turn (floor) or wall and height (wall items), a finish per material, and remove. Every
 * change goes through the action gate: refused choices are disabled with the model's reason.
 */
export function ObjectOptions({ config, object, gate, onClose }: { config: Configuration; object: RoomObject; gate: ActionGate; onClose: () => void }) {
  const objectId = object.id;
  const mesh = sourceMesh(config, object.source);
  const bounds = useMemo(() => (mesh ? positionBounds(mesh.positions) : null), [mesh]);
  const item = object.source.kind === 'library' ? findFurnitureItem(object.source.item) : undefined;
  const limits = OBJECT_SCALE_LIMITS[object.source.kind];
  const name = sourceName(config, object.source);
  const p = object.placement;
  const size = bounds ? { width: bounds.max[0] - bounds.min[0], depth: bounds.max[2] - bounds.min[2], height: bounds.max[1] - bounds.min[1] } : null;
  return (
    <OptionsSection title={name} onClose={onClose}>
      <div className="field">
        <h3>Size</h3>
        {size && (
          <p className="object-size" data-testid="object-size">
            {itemDimensions(size, object.scale)} <span className="empty-note">(width × depth × height)</span>
          </p>
        )}
        <CommitField label="Scale (× real size)" value={object.scale} onCommit={(scale) => gate.attempt('resizeObject', { objectId, scale })} onRefused={gate.explain} testId="object-scale" />
        <span className="empty-note">
          {limits.min}–{limits.max} × {object.source.kind === 'library' ? 'its real size' : 'the size it was imported at'}
        </span>
        {object.scale !== 1 && <GatedButton gate={gate} action="resizeObject" params={{ objectId, scale: 1 }} label="Back to real size" />}
      </div>
      {p.on === 'floor' ? (
        <>
          <div className="field">
            <h3>Rotation (°)</h3>
            <CommitField label="Rotation (°)" value={object.yaw} decimals={0} onCommit={(yaw) => gate.attempt('rotateObject', { objectId, yaw })} onRefused={gate.explain} testId="object-yaw" />
          </div>
          <OptionChips title="Rotate">
            {TURNS.map((by) => (
              <GatedButton key={by} gate={gate} action="rotateObject" params={{ objectId, by }} label={`Rotate ${by > 0 ? 'left' : 'right'} ${Math.abs(by)}°`} testId={`object-rotate-${by}`}>
                {by > 0 ? '⟲' : '⟳'} {Math.abs(by)}°
              </GatedButton>
            ))}
          </OptionChips>
        </>
      ) : (
        <>
          <OptionChips title="Wall">
            {WALL_NAMES.map((wall) => {
              const along = wall === 'north' || wall === 'south' ? config.room.width : config.room.depth;
              return (
                <GatedButton key={wall} gate={gate} action="moveObject" params={{ objectId, placement: { on: 'wall', wall, u: along / 2, y: p.y } }} label={`Hang on the ${wall} wall`} current={p.wall === wall}>
                  {wall}
                </GatedButton>
              );
            })}
          </OptionChips>
          <div className="field">
            <h3>Height of its centre above the floor (m)</h3>
            <CommitField label="Height (m)" value={p.y} onCommit={(y) => gate.attempt('moveObject', { objectId, placement: { ...p, y } })} onRefused={gate.explain} testId="object-height" />
          </div>
        </>
      )}
      {mesh && (
        <div className="field finish-list">
          <h3>Finishes</h3>
          {mesh.materials.map((m, i) => {
            const defaultId = item?.finishes[m.name];
            const finish = Object.prototype.hasOwnProperty.call(object.finishes, m.name) ? object.finishes[m.name] : undefined;
            return (
              <ObjectFinishSelect
                key={m.name}
                id={`object-finish-${objectId}-${i}`}
                material={m.name}
                value={finish}
                defaultRgb={m.reflectance}
                defaultName={defaultId ? (findObjectFinish(defaultId)?.name ?? defaultId) : 'colour from the file'}
                onChoose={(f) => gate.run('refinishObject', { objectId, material: m.name, finish: f })}
                disabledReason={(f) => gate.reason('refinishObject', { objectId, material: m.name, finish: f })}
                testId={`object-finish-${m.name}`}
              />
            );
          })}
        </div>
      )}
      <GatedButton gate={gate} action="removeObject" params={{ objectId }} label={`Remove ${name}`} testId="object-remove" />
    </OptionsSection>
  );
}
