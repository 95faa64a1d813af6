import './registerOptionsEnglish';
import { OBJECT_FINISHES, findObjectFinish } from '../../core/model/objects/furniture/objectFinishes';
import type { ObjectFinish } from '../../core/model/configuration/configuration';
import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { luminousReflectance } from '../../core/model/lightingScene/reflectance';
import { rgbColour } from './finishColour';
import { useI18n } from '../i18n/useI18n';
import { finishName } from '../i18n/catalogNames';

export interface ObjectFinishSelectProps {
  id: string;
  /** The material's name in the mesh ("top", "legs", or the file's material). */
  material: string;
  /** The finish set on the object for this material, undefined for the default. */
  value: ObjectFinish | undefined;
  /** The material's default colour (the library item's finish or the file's colour), linear RGB. */
  defaultRgb: Rgb;
  /** What the default is called ("Oak veneer", "colour from the file"). */
  defaultName: string;
  onChoose: (finish: string | null) => void;
  /** The model's reason a finish cannot be chosen, or null (the planner's action gate). */
  disabledReason?: (finish: string | null) => string | null;
  testId?: string;
}

const DEFAULT = '';
const CUSTOM = '#custom';

/**
 * A labelled native select of the object finishes (src/core/model/objects/furniture/objectFinishes.ts)
 * for one material of an object, with a swatch; the first entry is the material's default. A
 * colour set as RGB (a file, the embedding API) shows as "Custom" with its luminous reflectance.
 */
export function ObjectFinishSelect({ id, material, value, defaultRgb, defaultName, onChoose, disabledReason, testId }: ObjectFinishSelectProps) {
  const { t, format } = useI18n();
  // What a shopper reads: the share of light the finish reflects, in whole percent (its luminous reflectance).
  const percent = (r: Rgb | number) => format.percent(Math.round(luminousReflectance(r as Rgb) * 100) / 100);
  const custom = Array.isArray(value);
  const current = value === undefined ? DEFAULT : custom ? CUSTOM : (value as string);
  const known = typeof value === 'string' ? findObjectFinish(value) : undefined;
  const swatch = known ? known.display : rgbColour(custom ? (value as Rgb) : defaultRgb);
  const option = (finish: string | null) => {
    const reason = disabledReason?.(finish) ?? null;
    return { disabled: reason !== null, title: reason ?? undefined };
  };
  return (
    <div className="finish-row object-finish-row">
      <span className="finish-swatch" style={{ background: swatch }} aria-hidden data-testid={testId ? `${testId}-swatch` : undefined} />
      <label htmlFor={id}>{material}</label>
      <select
        id={id}
        value={current}
        data-testid={testId}
        onChange={(e) => {
          const v = e.target.value;
          if (v === DEFAULT) onChoose(null);
          else if (v !== CUSTOM) onChoose(v);
        }}
      >
        <option value={DEFAULT} {...option(null)}>
          {t('options.finishDefault', { name: defaultName, percent: percent(defaultRgb) })}
        </option>
        {custom && (
          <option value={CUSTOM} disabled>
            {t('planner.finishCustom', { percent: percent(value as Rgb) })}
          </option>
        )}
        {OBJECT_FINISHES.map((f) => (
          <option key={f.id} value={f.id} {...option(f.id)}>
            {t('planner.finishOption', { name: finishName(t, f), percent: percent(f.reflectance) })}
          </option>
        ))}
      </select>
    </div>
  );
}
