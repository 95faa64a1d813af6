import { useId, useState } from 'react';
import { defaultSurfaceFinishes } from '../../core/catalog/surfaceFinishes';
import { DEFAULT_REFLECTANCE, DEFAULT_ROOM, ROOM_LIMITS, withinRoomLimits } from '../../core/model/configuration';
import type { Reflectance, SurfaceName } from '../../core/model/lightingScene';
import { WALL_NAMES, sameReflectance, targetSurfaces, type SurfaceTarget } from '../../core/model/reflectance';
import { FinishSelect } from '../planner/FinishSelect';

export interface RoomDimensions {
  width: number;
  depth: number;
  height: number;
}

type Field = keyof RoomDimensions;

const FIELDS: { key: Field; label: string; hint: string }[] = [
  { key: 'width', label: 'Width', hint: 'west to east wall' },
  { key: 'depth', label: 'Depth', hint: 'north to south wall' },
  { key: 'height', label: 'Height', hint: 'floor to ceiling' },
];

/**
 * One field's message, or null when valid. The check is the model's withinRoomLimits, so the
 * form refuses exactly the rooms the model would refuse. Decimal commas are accepted because
 * many shoppers type "2,8".
 */
export function roomFieldError(key: Field, raw: string): string | null {
  const text = raw.trim().replace(',', '.');
  if (text === '') return `Enter the room ${key} in metres.`;
  const v = Number(text);
  if (!Number.isFinite(v)) return `The ${key} "${raw.trim()}" is not a number.`;
  const { min, max } = ROOM_LIMITS[key];
  if (!withinRoomLimits(key, v)) return `The ${key} must be between ${min} and ${max} m.`;
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
}

/** The first page (configurator paper §3.2): room dimensions with validation, then the main screen. */
export function RoomSetup({ initial, onSubmit, onDemo, onResume }: RoomSetupProps) {
  const id = useId();
  const [values, setValues] = useState<Record<Field, string>>({
    width: String(initial?.width ?? DEFAULT_ROOM.width),
    depth: String(initial?.depth ?? DEFAULT_ROOM.depth),
    height: String(initial?.height ?? DEFAULT_ROOM.height),
  });
  const [reflectance, setReflectance] = useState<Record<SurfaceName, Reflectance>>({ ...DEFAULT_REFLECTANCE, ...initial?.reflectance });
  const wallsAlike = WALL_NAMES.every((w) => sameReflectance(reflectance[w], reflectance.north));
  const chooseFinish = (target: SurfaceTarget) => (f: { reflectance: Reflectance }) =>
    setReflectance((r) => ({ ...r, ...Object.fromEntries(targetSurfaces(target).map((s) => [s, f.reflectance])) }));
  const [touched, setTouched] = useState<Record<Field, boolean>>({ width: false, depth: false, height: false });
  const errors: Record<Field, string | null> = {
    width: roomFieldError('width', values.width),
    depth: roomFieldError('depth', values.depth),
    height: roomFieldError('height', values.height),
  };
  const valid = !errors.width && !errors.depth && !errors.height;

  return (
    <div className="setup">
      <form
        className="setup-card"
        noValidate
        aria-labelledby={`${id}-title`}
        onSubmit={(e) => {
          e.preventDefault();
          setTouched({ width: true, depth: true, height: true });
          if (!valid) return;
          const num = (k: Field) => Number(values[k].trim().replace(',', '.'));
          onSubmit({ width: num('width'), depth: num('depth'), height: num('height'), reflectance });
        }}
      >
        <h2 id={`${id}-title`}>Your room</h2>
        <p>Enter the inside dimensions of the room in metres and pick its finishes. You can place lighting systems in the next step.</p>
        <div className="setup-fields">
          {FIELDS.map(({ key, label, hint }) => {
            const err = touched[key] ? errors[key] : null;
            return (
              <div className="field" key={key}>
                <label htmlFor={`${id}-${key}`}>
                  {label} (m)
                </label>
                <input
                  id={`${id}-${key}`}
                  name={key}
                  inputMode="decimal"
                  autoComplete="off"
                  value={values[key]}
                  aria-invalid={err ? true : undefined}
                  aria-describedby={`${id}-${key}-msg`}
                  onChange={(e) => {
                    const v = e.target.value;
                    setValues((s) => ({ ...s, [key]: v }));
                    setTouched((t) => ({ ...t, [key]: true }));
                  }}
                />
                <span id={`${id}-${key}-msg`} className={err ? 'error' : 'empty-note'} role={err ? 'alert' : undefined}>
                  {err ?? hint}
                </span>
              </div>
            );
          })}
        </div>
        <fieldset className="setup-finishes">
          <legend>Surfaces</legend>
          <div className="finish-list">
            <FinishSelect id={`${id}-floor`} label="Floor" use="floor" value={reflectance.floor} finishes={defaultSurfaceFinishes} onChoose={chooseFinish('floor')} testId="setup-finish-floor" />
            <FinishSelect id={`${id}-walls`} label="Walls" use="walls" value={wallsAlike ? reflectance.north : null} finishes={defaultSurfaceFinishes} onChoose={chooseFinish('walls')} testId="setup-finish-walls" />
            <FinishSelect id={`${id}-ceiling`} label="Ceiling" use="ceiling" value={reflectance.ceiling} finishes={defaultSurfaceFinishes} onChoose={chooseFinish('ceiling')} testId="setup-finish-ceiling" />
          </div>
        </fieldset>
        <div className="setup-actions">
          <button type="submit" className="btn btn-primary" aria-disabled={!valid || undefined}>
            Start planning
          </button>
          <button type="button" className="btn" onClick={onDemo}>
            Try the demo
          </button>
        </div>
        {onResume && (
          <button type="button" className="btn btn-link" onClick={onResume}>
            Continue your saved configuration
          </button>
        )}
      </form>
    </div>
  );
}
