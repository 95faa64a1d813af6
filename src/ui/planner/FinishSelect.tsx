import type { Reflectance } from '../../core/model/lightingScene/lightingScene';
import { luminousReflectance } from '../../core/model/lightingScene/reflectance';
import { finishesFor, matchFinish, type FinishUse, type SurfaceFinish } from '../../core/model/catalogSchema/surfaceFinish';
import { finishColour } from './finishColour';
import { useI18n } from '../i18n/useI18n';
import { finishName } from '../i18n/catalogNames';

export interface FinishSelectProps {
  id: string;
  label: string;
  use: FinishUse;
  /** The surface's reflectance; null when the surfaces it stands for differ (walls set one by one). */
  value: Reflectance | null;
  finishes: readonly SurfaceFinish[];
  onChoose: (finish: SurfaceFinish) => void;
  /** The model's reason a finish cannot be chosen, or null (the planner's action gate). */
  disabledReason?: (finish: SurfaceFinish) => string | null;
  testId?: string;
}

const CURRENT = '';

/**
 * A labelled native select of the finishes offered for a surface, with a swatch. Native selects
 * give a large touch target and the platform's own picker on phones. A value not in the list
 * (an older file, the embedding API) shows as "Custom" with its luminous reflectance.
 */
export function FinishSelect({ id, label, use, value, finishes, onChoose, disabledReason, testId }: FinishSelectProps) {
  const { t, format } = useI18n();
  // What a shopper reads: the share of light the finish reflects, in whole percent (its luminous reflectance).
  const percent = (r: Reflectance) => format.percent(Math.round(luminousReflectance(r) * 100) / 100);
  const offered = finishesFor(finishes, use);
  const current = value === null ? null : matchFinish(offered, value);
  const swatch = value === null ? 'repeating-linear-gradient(45deg, #ffffff 0 4px, #c8ccd3 4px 8px)' : finishColour(value, finishes);
  return (
    <div className="finish-row">
      <span className="finish-swatch" style={{ background: swatch }} aria-hidden data-testid={testId ? `${testId}-swatch` : undefined} />
      <label htmlFor={id}>{label}</label>
      <select
        id={id}
        value={current?.id ?? CURRENT}
        data-testid={testId}
        onChange={(e) => {
          const f = offered.find((x) => x.id === e.target.value);
          if (f) onChoose(f);
        }}
      >
        {!current && (
          <option value={CURRENT} disabled>
            {value === null ? t('planner.finishMixed') : t('planner.finishCustom', { percent: percent(value) })}
          </option>
        )}
        {offered.map((f) => {
          const reason = disabledReason?.(f) ?? null;
          return (
            <option key={f.id} value={f.id} disabled={reason !== null} title={reason ?? undefined}>
              {t('planner.finishOption', { name: finishName(t, f), percent: percent(f.reflectance) })}
            </option>
          );
        })}
      </select>
    </div>
  );
}
