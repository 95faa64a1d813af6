import { DISTRIBUTIONS, type Distribution } from '../../core/model/catalogSchema';
import { ActionButton } from './ActionButton';
import type { ActionGate } from './actionGate';

export const DISTRIBUTION_LABELS: Record<Distribution, { short: string; long: string }> = {
  start: { short: '▮▮··', long: 'Start: packed from the rail start' },
  'inside-centred': { short: '·▮·▮·', long: 'Inside-centred: each module centred in an equal share of the rail' },
  'outside-centred': { short: '▮··▮', long: 'Outside-centred: outer modules at the ends, even spacing' },
  end: { short: '··▮▮', long: 'End: packed against the rail end' },
};

/**
 * The four distribution options of a rail (configurator paper, fig. 9): each enabled
 * exactly when the model's `setDistribution` would accept it. `compact` shows
 * the pictogram (in the plan, next to the rail); otherwise the option's name
 * (options panel). The long label is always the accessible name.
 */
export function DistributionButtons({ railId, current, gate, compact = false }: { railId: string; current: Distribution; gate: ActionGate; compact?: boolean }) {
  return (
    <>
      {DISTRIBUTIONS.map((d) => (
        <ActionButton
          key={d}
          label={DISTRIBUTION_LABELS[d].long}
          pressed={current === d}
          disabledReason={current === d ? null : gate.reason('setDistribution', { railId, distribution: d })}
          onPress={() => current !== d && gate.run('setDistribution', { railId, distribution: d })}
          onDisabledPress={gate.explain}
          testId={compact ? `distribution-${railId}-${d}` : undefined}
        >
          {compact ? <span aria-hidden>{DISTRIBUTION_LABELS[d].short}</span> : d}
        </ActionButton>
      ))}
    </>
  );
}
