import { DISTRIBUTIONS, type Distribution } from '../../core/model/catalogSchema/railSystemSchema';
import { GatedButton } from './GatedButton';
import type { ActionGate } from './actionGate';

export const DISTRIBUTION_LABELS: Record<Distribution, { short: string; long: string }> = {
  start: { short: '▮▮··', long: 'Start: packed from the rail start' },
  'inside-centred': { short: '·▮·▮·', long: 'Inside-centred: each module centred in an equal share of the rail' },
  'outside-centred': { short: '▮··▮', long: 'Outside-centred: outer modules at the ends, even spacing' },
  end: { short: '··▮▮', long: 'End: packed against the rail end' },
};

/**
 * The four distribution options of a rail (configurator paper, fig. 9): each enabled
 * exactly when the model's `setDistribution` would accept it. `current` is null on a
 * freely arranged rail (none is pressed; choosing one clears the free positions). `compact` shows
 * the pictogram (in the plan, next to the rail); otherwise the option's name
 * (options panel). The long label is always the accessible name.
 */
export function DistributionButtons({ railId, current, gate, compact = false }: { railId: string; current: Distribution | null; gate: ActionGate; compact?: boolean }) {
  return (
    <>
      {DISTRIBUTIONS.map((d) => (
        <GatedButton
          key={d}
          gate={gate}
          action="setDistribution"
          params={{ railId, distribution: d }}
          label={DISTRIBUTION_LABELS[d].long}
          current={current === d}
          testId={compact ? `distribution-${railId}-${d}` : undefined}
        >
          {compact ? <span aria-hidden>{DISTRIBUTION_LABELS[d].short}</span> : d}
        </GatedButton>
      ))}
    </>
  );
}
