import { useId, useState } from 'react';
import { defaultSurfaceFinishes } from '../../core/catalog/surfaceFinishes';
import { DEFAULT_REFLECTANCE, DEFAULT_ROOM, ROOM_LIMITS, withinRoomLimits } from '../../core/model/configuration/configuration';
import type { Reflectance, SurfaceName } from '../../core/model/lightingScene/lightingScene';
import { WALL_NAMES, sameReflectance, targetSurfaces, type SurfaceTarget } from '../../core/model/lightingScene/reflectance';
import { FinishSelect } from '../planner/FinishSelect';
import { useI18n } from '../i18n/useI18n';
import { ENGLISH } from '../i18n/english';
import type { MessageKey, Translate } from '../i18n/messageTypes';
import type { Landmarks } from '../shared/landmarks';
import { decimalFieldFormat, parseDecimal } from '../i18n/decimalInput';

export interface RoomDimensions {
  width: number;
  depth: number;
  height: number;
}

type Field = keyof RoomDimensions;

const FIELDS: { key: Field; labelKey: MessageKey; hintKey: MessageKey; nameKey: MessageKey }[] = [
  { key: 'width', labelKey: 'app.width', hintKey: 'app.widthHint', nameKey: 'app.widthName' },
  { key: 'depth', labelKey: 'app.depth', hintKey: 'app.depthHint', nameKey: 'app.depthName' },
  { key: 'height', labelKey: 'app.height', hintKey: 'app.heightHint', nameKey: 'app.heightName' },
];

/**
 * One field's message, or null when valid. The check is the model's withinRoomLimits, so the
 * form refuses exactly the rooms the model would refuse. "2,8" and "2.8" are both accepted in
 * every language (parseDecimal, docs/i18n.md "Decimal input").
 */
export function roomFieldError(key: Field, raw: string, t: Translate = ENGLISH.t): string | null {
  const field = t(FIELDS.find((f) => f.key === key)!.nameKey);
  if (raw.trim() === '') return t('app.roomFieldEmpty', { field });
  const v = parseDecimal(raw);
  if (!Number.isFinite(v)) return t('app.roomFieldNotNumber', { field, value: raw.trim() });
  const { min, max } = ROOM_LIMITS[key];
  if (!withinRoomLimits(key, v)) return t('app.roomFieldRange', { field, min, max });
  return null;
}

/** What the first page produces: the dimensions and the finishes of the user's room. */
export interface RoomSetupResult extends RoomDimensions {
  reflectance: Record<SurfaceName, Reflectance>;
}

export interface RoomSetupProps {
  initial?: Partial<RoomSetupResult>;
  onSubmit: (room: RoomSetupResult) => void;
  onDemo: () => void;
  /** Present when a saved configuration exists. */
  onResume?: () => void;
  /** 'page': the form is the page's main landmark (the standalone app); 'region': a plain box inside the embed's region. */
  landmarks?: Landmarks;
}

/** The first page (configurator paper §3.2): room dimensions with validation, then the main screen. */
export function RoomSetup({ initial, onSubmit, onDemo, onResume, landmarks = 'region' }: RoomSetupProps) {
  const id = useId();
  const { t, format } = useI18n();
  // Shown with the locale's decimal separator ("2,7" in German); both separators are accepted back.
  const shown = (v: number) => format.number(v, decimalFieldFormat({ max: 3 }));
  const [values, setValues] = useState<Record<Field, string>>(() => ({
    width: shown(initial?.width ?? DEFAULT_ROOM.width),
    depth: shown(initial?.depth ?? DEFAULT_ROOM.depth),
    height: shown(initial?.height ?? DEFAULT_ROOM.height),
  }));
  const [reflectance, setReflectance] = useState<Record<SurfaceName, Reflectance>>({ ...DEFAULT_REFLECTANCE, ...initial?.reflectance });
  const [touched, setTouched] = useState<Record<Field, boolean>>({ width: false, depth: false, height: false });
  const errors: Record<Field, string | null> = {
    width: roomFieldError('width', values.width, t),
    depth: roomFieldError('depth', values.depth, t),
    height: roomFieldError('height', values.height, t),
  };
  const valid = !errors.width && !errors.depth && !errors.height;

  const Root = landmarks === 'page' ? 'main' : 'div';
  return (
    <Root className="setup">
      <form
        className="setup-card"
        noValidate
        aria-labelledby={`${id}-title`}
        onSubmit={(e) => {
          e.preventDefault();
          setTouched({ width: true, depth: true, height: true });
          if (!valid) return;
          const num = (k: Field) => parseDecimal(values[k]);
          onSubmit({ width: num('width'), depth: num('depth'), height: num('height'), reflectance });
        }}
      >
        <h2 id={`${id}-title`}>{t('app.yourRoom')}</h2>
        <p>{t('app.setupIntro')}</p>
        <div className="setup-fields">
          {FIELDS.map(({ key, labelKey, hintKey }) => (
            <RoomDimensionField
              key={key}
              inputId={`${id}-${key}`}
              name={key}
              label={t('app.fieldInMetres', { field: t(labelKey) })}
              hint={t(hintKey)}
              value={values[key]}
              error={touched[key] ? errors[key] : null}
              onChange={(v) => {
                setValues((s) => ({ ...s, [key]: v }));
                setTouched((t) => ({ ...t, [key]: true }));
              }}
            />
          ))}
        </div>
        <SetupFinishes idPrefix={id} reflectance={reflectance} onReflectance={setReflectance} />
        <div className="setup-actions">
          <button type="submit" className="btn btn-primary" aria-disabled={!valid || undefined}>
            {t('app.startPlanning')}
          </button>
          <button type="button" className="btn" onClick={onDemo}>
            {t('app.tryDemo')}
          </button>
        </div>
        {onResume && (
          <button type="button" className="btn btn-link" onClick={onResume}>
            {t('app.continueSaved')}
          </button>
        )}
      </form>
    </Root>
  );
}

interface RoomDimensionFieldProps {
  inputId: string;
  name: Field;
  label: string;
  hint: string;
  value: string;
  /** Shown (as an alert) instead of the hint once the field was touched. */
  error: string | null;
  onChange: (value: string) => void;
}

/** One dimension in metres, typed with either decimal mark; its hint, or its error once touched. */
function RoomDimensionField({ inputId, name, label, hint, value, error, onChange }: RoomDimensionFieldProps) {
  return (
    <div className="field">
      <label htmlFor={inputId}>{label}</label>
      <input id={inputId} name={name} inputMode="decimal" autoComplete="off" value={value} aria-invalid={error ? true : undefined} aria-describedby={`${inputId}-msg`} onChange={(e) => onChange(e.target.value)} />
      <span id={`${inputId}-msg`} className={error ? 'error' : 'empty-note'} role={error ? 'alert' : undefined}>
        {error ?? hint}
      </span>
    </div>
  );
}

type Finishes = Record<SurfaceName, Reflectance>;

/** Floor, walls (one choice for all four; none shown when they differ) and ceiling finishes. */
function SetupFinishes({ idPrefix, reflectance, onReflectance }: { idPrefix: string; reflectance: Finishes; onReflectance: (update: (r: Finishes) => Finishes) => void }) {
  const { t } = useI18n();
  const wallsAlike = WALL_NAMES.every((w) => sameReflectance(reflectance[w], reflectance.north));
  const chooseFinish = (target: SurfaceTarget) => (f: { reflectance: Reflectance }) => onReflectance((r) => ({ ...r, ...Object.fromEntries(targetSurfaces(target).map((s) => [s, f.reflectance])) }));
  return (
    <fieldset className="setup-finishes">
      <legend>{t('app.surfaces')}</legend>
      <div className="finish-list">
        <FinishSelect id={`${idPrefix}-floor`} label={t('app.floor')} use="floor" value={reflectance.floor} finishes={defaultSurfaceFinishes} onChoose={chooseFinish('floor')} testId="setup-finish-floor" />
        <FinishSelect id={`${idPrefix}-walls`} label={t('app.walls')} use="walls" value={wallsAlike ? reflectance.north : null} finishes={defaultSurfaceFinishes} onChoose={chooseFinish('walls')} testId="setup-finish-walls" />
        <FinishSelect id={`${idPrefix}-ceiling`} label={t('app.ceiling')} use="ceiling" value={reflectance.ceiling} finishes={defaultSurfaceFinishes} onChoose={chooseFinish('ceiling')} testId="setup-finish-ceiling" />
      </div>
    </fieldset>
  );
}
