import './registerOptionsEnglish';
import { useSyncExternalStore } from 'react';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { ModuleInstance } from '../../core/model/configuration/configuration';
import { useI18n } from '../i18n/useI18n';
import type { AimAtMode } from '../shared/aimAtMode';
import type { ActionGate } from './actionGate';
import { GatedButton } from './GatedButton';
import { OptionChips } from './OptionChips';

export interface AimOptionsProps {
  module: ModuleInstance;
  catalog: Catalog;
  gate: ActionGate;
  /** Aim-at mode shared with the 3D view (aimAtMode.ts). */
  aimMode: AimAtMode;
}

/**
 * An adjustable module's aim (docs/aiming.md): its rotation and tilt, straight down again, and
 * "aim at": the next tap in the plan (a floor point) or the 3D view (a surface point) turns it
 * there. Nothing for a fixed module.
 */
export function AimOptions({ module, catalog, gate, aimMode }: AimOptionsProps) {
  const { t, format } = useI18n();
  const active = useSyncExternalStore(aimMode.subscribe, aimMode.get, aimMode.get) === module.id;
  const type = catalog.moduleTypes.find((x) => x.id === module.type);
  if (!type?.adjustable) return null;
  const aim = module.aim ?? { rotation: 0, tilt: 0 };
  const deg = (x: number) => format.number(x, { maximumFractionDigits: 1 });
  const { rotation, tilt } = type.adjustable;
  return (
    <OptionChips title={t('aim.title')}>
      <span
        className="aim-values"
        data-testid="aim-values"
        data-rotation={aim.rotation}
        data-tilt={aim.tilt}
        title={t('aim.limits', { rotationMin: deg(rotation.min), rotationMax: deg(rotation.max), tiltMin: deg(tilt.min), tiltMax: deg(tilt.max) })}
      >
        <span>{t('aim.rotation', { degrees: deg(aim.rotation) })}</span> <span>{t('aim.tilt', { degrees: deg(aim.tilt) })}</span>
      </span>
      <GatedButton gate={gate} action="setAim" params={{ moduleId: module.id, aim: { rotation: aim.rotation, tilt: 0 } }} label={t('aim.straightDown')} current={aim.tilt === 0} testId="aim-straight-down" />
      <button type="button" className={`btn${active ? ' btn-primary' : ''}`} aria-pressed={active} title={t('aim.aimAtHint')} onClick={() => aimMode.set(active ? null : module.id)} data-testid="aim-at">
        {active ? t('aim.cancel') : t('aim.aimAt')}
      </button>
      {active && (
        <p className="hint" role="status" data-testid="aim-at-status">
          {t('aim.aimAtActive')}
        </p>
      )}
    </OptionChips>
  );
}
