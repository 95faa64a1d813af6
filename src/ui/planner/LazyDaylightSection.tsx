import { lazy, Suspense, useState } from 'react';
import { loadRoomShapeSupport } from '../../core/model/actions/loadRoomShapeSupport';
import type { DaylightPanelProps } from './DaylightPanel';
import { useI18n } from '../i18n/useI18n';

/** The panel, a chunk of its own, with the model's room-shape chunk (its actions and rules live there). */
const Panel = lazy(() => Promise.all([import('./DaylightPanel'), loadRoomShapeSupport()]).then(([panel]) => panel));

/**
 * The side panel's Daylight section (issue 30): on the first screen only its heading; the panel
 * (DaylightPanel) is fetched when the shopper opens it.
 */
export function LazyDaylightSection(props: DaylightPanelProps) {
  const { t } = useI18n();
  const [open, setOpen] = useState(false);
  return (
    <details className="panel-section daylight-section" data-testid="daylight" onToggle={(e) => setOpen((e.currentTarget as HTMLDetailsElement).open)}>
      <summary data-testid="daylight-open">{t('planner.daylight')}</summary>
      {open && (
        <Suspense fallback={null}>
          <Panel {...props} />
        </Suspense>
      )}
    </details>
  );
}
