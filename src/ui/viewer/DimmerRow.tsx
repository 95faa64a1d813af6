import { useState } from 'react';
import { useI18n } from '../i18n/useI18n';
import './registerView3dEnglish';
import '../i18n/registerScenesEnglish';

/**
 * A module's dimmer, labelled by `name` (its catalog name and place, never its id: issue 27, "Words for shoppers"): moves freely while dragged, commits one undoable action on release (follows the stored value when that changes, e.g. on undo).
 * With `onSwitch`, an on/off switch in front (setModuleOn: off keeps the level for switching back on; docs/light-scenes.md).
 */
export function DimmerRow({ id, name, dimming, onCommit, on = true, onSwitch }: { id: string; name: string; dimming: number; onCommit: (d: number) => void; on?: boolean; onSwitch?: (on: boolean) => void }) {
  const { t, format } = useI18n();
  const [value, setValue] = useState(dimming);
  const [stored, setStored] = useState(dimming);
  if (stored !== dimming) {
    // Derived state, adjusted during render (react.dev: "storing information from previous renders").
    setStored(dimming);
    setValue(dimming);
  }
  const commit = () => {
    if (value !== dimming) onCommit(value);
  };
  return (
    <label className="viewer3d-field">
      {onSwitch && <input type="checkbox" checked={on} onChange={(e) => onSwitch(e.target.checked)} aria-label={t('scenes.moduleOn', { name })} data-testid={`on-${id}`} />}
      {name}: {format.percent(value)}
      <input type="range" min={0} max={1} step={0.05} value={value} onChange={(e) => setValue(Number(e.target.value))} onPointerUp={commit} onKeyUp={commit} onBlur={commit} data-testid={`dim-${id}`} />
    </label>
  );
}
