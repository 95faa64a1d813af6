import { CommitField } from '../shared/CommitField';
import type { ActionGate } from './actionGate';
import { useI18n } from '../i18n/useI18n';

/**
 * The rail length input (configurator paper, fig. 6, blue fields): commits through the
 * always-valid `setRailLength` action, so a refused length snaps back and the
 * model's reason is shown. Used next to the rail in the plan and in the options panel.
 */
export function RailLengthField({ railId, railNumber, length, gate }: { railId: string; railNumber: number; length: number; gate: ActionGate }) {
  const { t } = useI18n();
  return <CommitField label={t('planner.railLengthField', { n: railNumber })} value={length} onCommit={(value) => gate.attempt('setRailLength', { railId, length: value })} onRefused={gate.explain} />;
}
