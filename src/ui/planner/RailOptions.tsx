import './registerOptionsEnglish';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { LightSystem, Rail } from '../../core/model/configuration/configuration';
import { isFreeRail } from '../../core/model/rails/freePositions';
import type { ActionGate } from './actionGate';
import { BranchOptions } from './BranchOptions';
import { DistributionButtons } from './DistributionButtons';
import { GatedButton } from './GatedButton';
import { OptionChips } from './OptionChips';
import { OptionsSection } from './OptionsSection';
import { RailLengthField } from './RailLengthField';
import { useI18n } from '../i18n/useI18n';
import { localName } from '../i18n/localName';

/** A selected rail's settings: length, module distribution, add modules, and removing it (any rail of a chain of two or more: a middle one splits the chain). */
export function RailOptions({ rail, system, catalog, gate, onClose }: { rail: Rail; system: LightSystem; catalog: Catalog; gate: ActionGate; onClose: () => void }) {
  const { t, language } = useI18n();
  const railIndex = system.rails.indexOf(rail);
  return (
    <OptionsSection title={t('options.railTitle', { n: railIndex + 1 })} onClose={onClose}>
      <div className="field">
        <h3>{t('options.railLength')}</h3>
        <RailLengthField railId={rail.id} railNumber={railIndex + 1} length={rail.length} gate={gate} />
        <span className="empty-note">{t('options.railLengthRange', { min: catalog.rail.minLength, max: catalog.rail.maxLength, step: catalog.rail.step })}</span>
      </div>
      <OptionChips title={t('options.moduleDistribution')}>
        <DistributionButtons railId={rail.id} current={isFreeRail(rail) ? null : rail.distribution} gate={gate} />
      </OptionChips>
      <OptionChips title={t('options.addModule')}>
        {catalog.moduleTypes.map((m) => (
          <GatedButton key={m.id} gate={gate} action="addModule" params={{ railId: rail.id, type: m.id }} label={t('options.addModuleType', { name: localName(m, language) })}>
            + {localName(m, language)}
          </GatedButton>
        ))}
      </OptionChips>
      <BranchOptions rail={rail} system={system} catalog={catalog} gate={gate} />
      {system.rails.length > 1 && <GatedButton gate={gate} action="removeRail" params={{ railId: rail.id }} label={t('options.removeRail')} />}
    </OptionsSection>
  );
}
