import './registerPanelExtrasEnglish';
import { useId } from 'react';
import { useStore } from 'zustand';
import type { UiStore } from '../../core/store/uiStore';
import { useI18n } from '../i18n/useI18n';

/**
 * The Expert switch of the side panel (docs/embedding.md, option `expert: 'switch'`): shows or hides
 * the expert tools (DMX live control in 3D, the Radiance download, the photometric files' data
 * notes). A checkbox with the switch role, so it is read as on/off. A chunk of its own, loaded only
 * where the shop lets the user choose (Planner.tsx).
 */
export default function ExpertSwitch({ ui }: { ui: UiStore }) {
  const { t } = useI18n();
  const on = useStore(ui, (s) => s.expert);
  const noteId = useId();
  return (
    <label className="expert-switch">
      <input type="checkbox" role="switch" checked={on} onChange={(e) => ui.setState({ expert: e.target.checked })} aria-describedby={noteId} data-testid="expert-switch" />
      <span>
        {t('expert.switch')}
        <small id={noteId}>{t('expert.note')}</small>
      </span>
    </label>
  );
}
