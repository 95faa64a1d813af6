import type { Catalog } from '../../core/model/catalogSchema';
import type { LightSystem, Rail } from '../../core/model/configuration';
import { isFreeRail } from '../../core/model/freePositions';
import type { ActionGate } from './actionGate';
import { DistributionButtons } from './DistributionButtons';
import { GatedButton } from './GatedButton';
import { OptionChips } from './OptionChips';
import { OptionsSection } from './OptionsSection';
import { RailLengthField } from './RailLengthField';

/** A selected rail's settings: length, module distribution, add modules, and removing it (any rail of a chain of two or more: a middle one splits the chain). */
export function RailOptions({ rail, system, catalog, gate, onClose }: { rail: Rail; system: LightSystem; catalog: Catalog; gate: ActionGate; onClose: () => void }) {
  const railIndex = system.rails.indexOf(rail);
  return (
    <OptionsSection title={`Rail ${railIndex + 1}`} onClose={onClose}>
      <div className="field">
        <h3>Length (m)</h3>
        <RailLengthField railId={rail.id} railNumber={railIndex + 1} length={rail.length} gate={gate} />
        <span className="empty-note">
          {catalog.rail.minLength}–{catalog.rail.maxLength} m in steps of {catalog.rail.step} m
        </span>
      </div>
      <OptionChips title="Module distribution">
        <DistributionButtons railId={rail.id} current={isFreeRail(rail) ? null : rail.distribution} gate={gate} />
      </OptionChips>
      <OptionChips title="Add a module">
        {catalog.moduleTypes.map((t) => (
          <GatedButton key={t.id} gate={gate} action="addModule" params={{ railId: rail.id, type: t.id }} label={`Add ${t.name}`}>
            + {t.name}
          </GatedButton>
        ))}
      </OptionChips>
      {system.rails.length > 1 && <GatedButton gate={gate} action="removeRail" params={{ railId: rail.id }} label="Remove this rail" />}
    </OptionsSection>
  );
}
