import './registerOptionsEnglish';
import { DISTRIBUTIONS, type Distribution } from '../../core/model/catalogSchema/railSystemSchema';
import { GatedButton } from './GatedButton';
import type { ActionGate } from './actionGate';
import { DistributionPicture } from './DistributionPicture';
import { useI18n } from '../i18n/useI18n';
import type { MessageKey } from '../i18n/messageTypes';

/** Each distribution's short name (under its picture in the options) and its full name (the accessible name). */
export const DISTRIBUTION_TEXT: Record<Distribution, { short: MessageKey; long: MessageKey }> = {
  start: { short: 'options.distShort_start', long: 'options.distLong_start' },
  end: { short: 'options.distShort_end', long: 'options.distLong_end' },
  'inside-centred': { short: 'options.distShort_inside', long: 'options.distLong_inside' },
  'outside-centred': { short: 'options.distShort_outside', long: 'options.distLong_outside' },
};

/**
 * The four distribution options of a rail (configurator paper, fig. 9), as pictures of the rail
 * with its modules where each option puts them, named in shopper words: each enabled exactly when
 * the model's `setDistribution` would accept it. `current` is null on a freely arranged rail (none
 * is pressed; choosing one clears the free positions). `compact` shows the picture alone (in the
 * plan, next to the rail; `flipped` where the rail runs right to left on screen); otherwise the
 * picture over its short name (options panel). The full name is always the accessible name.
 */
export default function DistributionButtons({ railId, current, gate, compact = false, flipped = false }: { railId: string; current: Distribution | null; gate: ActionGate; compact?: boolean; flipped?: boolean }) {
  const { t } = useI18n();
  return (
    <>
      {DISTRIBUTIONS.map((d) => (
        <GatedButton
          key={d}
          gate={gate}
          action="setDistribution"
          params={{ railId, distribution: d }}
          label={t(DISTRIBUTION_TEXT[d].long)}
          current={current === d}
          testId={compact ? `distribution-${railId}-${d}` : `distribution-option-${d}`}
        >
          <span className={compact ? 'distribution-chip' : 'distribution-chip distribution-chip-named'}>
            <DistributionPicture distribution={d} flipped={flipped} />
            {!compact && <span aria-hidden="true">{t(DISTRIBUTION_TEXT[d].short)}</span>}
          </span>
        </GatedButton>
      ))}
    </>
  );
}

export { DistributionButtons };
