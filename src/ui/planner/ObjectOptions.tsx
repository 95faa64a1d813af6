import './registerOptionsEnglish';
import { useMemo } from 'react';
import { OBJECT_SCALE_LIMITS, WALL_NAMES, type Configuration, type RoomObject } from '../../core/model/configuration/configuration';
import { findFurnitureItem } from '../../core/model/objects/furniture/furnitureLibrary';
import { findObjectFinish } from '../../core/model/objects/furniture/objectFinishes';
import { sourceMesh, sourceName } from '../../core/model/objects/objectGeometry';
import { positionBounds, type MeshMaterial } from '../../core/mesh/triangleMesh';
import type { ActionGate } from './actionGate';
import { CommitField } from '../shared/CommitField';
import { itemDimensions } from './FurniturePanel';
import { GatedButton } from './GatedButton';
import { ObjectFinishSelect } from './ObjectFinishSelect';
import { OptionChips } from './OptionChips';
import { OptionsSection } from './OptionsSection';
import { useI18n } from '../i18n/useI18n';
import { finishName, furnitureName } from '../i18n/catalogNames';

/** Turns offered for a floor object, degrees (positive: counterclockwise seen from above, "left"). */
const TURNS = [-90, -15, 15, 90] as const;

/**
 * A selected object's settings: its size (uniform scale, with the real dimensions in cm), its
 * turn (floor) or wall and height (wall items), a finish per material, and remove. Every
 * change goes through the action gate: refused choices are disabled with the model's reason.
 */
export function ObjectOptions({ config, object, gate, onClose }: { config: Configuration; object: RoomObject; gate: ActionGate; onClose: () => void }) {
  const { t } = useI18n();
  const objectId = object.id;
  const mesh = sourceMesh(config, object.source);
  const bounds = useMemo(() => (mesh ? positionBounds(mesh.positions) : null), [mesh]);
  const item = object.source.kind === 'library' ? findFurnitureItem(object.source.item) : undefined;
  const name = item ? furnitureName(t, item) : sourceName(config, object.source);
  const p = object.placement;
  const size = bounds ? { width: bounds.max[0] - bounds.min[0], depth: bounds.max[2] - bounds.min[2], height: bounds.max[1] - bounds.min[1] } : null;
  return (
    <OptionsSection title={name} onClose={onClose}>
      <ObjectSize object={object} size={size} limitsKind={object.source.kind} gate={gate} />
      {p.on === 'floor' ? <FloorObjectTurn object={object} gate={gate} /> : <WallObjectPlacement config={config} object={object} gate={gate} />}
      {mesh && <ObjectFinishList object={object} materials={mesh.materials} libraryFinishes={item?.finishes} gate={gate} />}
      <GatedButton gate={gate} action="removeObject" params={{ objectId }} label={t('options.removeObject', { name })} testId="object-remove" />
    </OptionsSection>
  );
}

interface ObjectPartProps {
  object: RoomObject;
  gate: ActionGate;
}

/** The real dimensions in cm at the present scale, the scale field and its range, and "back to real size". */
function ObjectSize({ object, size, limitsKind, gate }: ObjectPartProps & { size: { width: number; depth: number; height: number } | null; limitsKind: RoomObject['source']['kind'] }) {
  const { t, format } = useI18n();
  const objectId = object.id;
  const limits = OBJECT_SCALE_LIMITS[limitsKind];
  return (
    <div className="field">
      <h3>{t('options.size')}</h3>
      {size && (
        <p className="object-size" data-testid="object-size">
          {itemDimensions(size, object.scale, format)} <span className="empty-note">{t('options.sizeOrder')}</span>
        </p>
      )}
      <CommitField label={t('options.scale')} value={object.scale} onCommit={(scale) => gate.attempt('resizeObject', { objectId, scale })} onRefused={gate.explain} testId="object-scale" />
      <span className="empty-note">{t(limitsKind === 'library' ? 'options.scaleRangeLibrary' : 'options.scaleRangeImported', { min: limits.min, max: limits.max })}</span>
      {object.scale !== 1 && <GatedButton gate={gate} action="resizeObject" params={{ objectId, scale: 1 }} label={t('options.backToRealSize')} />}
    </div>
  );
}

/** A floor object's turn: typed in degrees, or by the offered steps. */
function FloorObjectTurn({ object, gate }: ObjectPartProps) {
  const { t } = useI18n();
  const objectId = object.id;
  return (
    <>
      <div className="field">
        <h3>{t('options.rotation')}</h3>
        <CommitField label={t('options.rotation')} value={object.yaw} decimals={0} onCommit={(yaw) => gate.attempt('rotateObject', { objectId, yaw })} onRefused={gate.explain} testId="object-yaw" />
      </div>
      <OptionChips title={t('options.rotate')}>
        {TURNS.map((by) => (
          <GatedButton key={by} gate={gate} action="rotateObject" params={{ objectId, by }} label={t(by > 0 ? 'options.rotateLeft' : 'options.rotateRight', { degrees: Math.abs(by) })} testId={`object-rotate-${by}`}>
            {by > 0 ? '⟲' : '⟳'} {Math.abs(by)}°
          </GatedButton>
        ))}
      </OptionChips>
    </>
  );
}

/** A wall item's wall (hung at the middle of the chosen one) and the height of its centre. */
function WallObjectPlacement({ config, object, gate }: ObjectPartProps & { config: Configuration }) {
  const { t } = useI18n();
  const objectId = object.id;
  const p = object.placement;
  if (p.on !== 'wall') return null;
  return (
    <>
      <OptionChips title={t('options.wall')}>
        {WALL_NAMES.map((wall) => {
          const along = wall === 'north' || wall === 'south' ? config.room.width : config.room.depth;
          return (
            <GatedButton key={wall} gate={gate} action="moveObject" params={{ objectId, placement: { on: 'wall', wall, u: along / 2, y: p.y } }} label={t('options.hangOnWall', { wall: t(`planner.wall_${wall}`) })} current={p.wall === wall}>
              {t(`planner.wall_${wall}`)}
            </GatedButton>
          );
        })}
      </OptionChips>
      <div className="field">
        <h3>{t('options.centreHeight')}</h3>
        <CommitField label={t('options.heightField')} value={p.y} onCommit={(y) => gate.attempt('moveObject', { objectId, placement: { ...p, y } })} onRefused={gate.explain} testId="object-height" />
      </div>
    </>
  );
}

/** A finish per material of the mesh; the library item's own finish (or the file's colour) as the default. */
function ObjectFinishList({ object, materials, libraryFinishes, gate }: ObjectPartProps & { materials: readonly MeshMaterial[]; libraryFinishes: Readonly<Record<string, string>> | undefined }) {
  const { t } = useI18n();
  const objectId = object.id;
  return (
    <div className="field finish-list">
      <h3>{t('options.finishes')}</h3>
      {materials.map((m, i) => {
        const defaultId = libraryFinishes?.[m.name];
        const finish = Object.prototype.hasOwnProperty.call(object.finishes, m.name) ? object.finishes[m.name] : undefined;
        return (
          <ObjectFinishSelect
            key={m.name}
            id={`object-finish-${objectId}-${i}`}
            material={m.name}
            value={finish}
            defaultRgb={m.reflectance}
            defaultName={defaultId ? finishName(t, findObjectFinish(defaultId) ?? { id: defaultId, name: defaultId }) : t('options.colourFromFile')}
            onChoose={(f) => gate.run('refinishObject', { objectId, material: m.name, finish: f })}
            disabledReason={(f) => gate.reason('refinishObject', { objectId, material: m.name, finish: f })}
            testId={`object-finish-${m.name}`}
          />
        );
      })}
    </div>
  );
}
