import type { Catalog } from '../../core/model/catalogSchema';
import type { LightSystem } from '../../core/model/configuration';
import type { ActionGate } from './actionGate';
import { CommitField } from './CommitField';
import { GatedButton } from './GatedButton';
import { OptionChips } from './OptionChips';
import { OptionsSection } from './OptionsSection';

/** Rotation steps offered for a selected system, in degrees (positive: counterclockwise, "left"). */
const ROTATIONS = [-90, -15, 15, 90] as const;

/** A selected system's settings: suspension, rotation, extending the chain with a rail, delete. */
export function SystemOptions({ system, catalog, gate, onClose }: { system: LightSystem; catalog: Catalog; gate: ActionGate; onClose: () => void }) {
  const systemId = system.id;
  const turns = catalog.connectors.flatMap((c) => (c.angle === 0 ? [{ c, turn: 0, label: `Add rail straight (${c.name})` }] : [
    { c, turn: c.angle, label: `Add rail turning left ${c.angle}°` },
    { c, turn: -c.angle, label: `Add rail turning right ${c.angle}°` },
  ]));
  return (
    <OptionsSection title="Lighting system" onClose={onClose}>
      <div className="field">
        <h3>Suspension: ceiling to light (m)</h3>
        <CommitField label="Suspension (m)" value={system.suspension} onCommit={(suspension) => gate.attempt('setSuspension', { systemId, suspension })} onRefused={gate.explain} />
        <span className="empty-note">
          {catalog.suspension.min}–{catalog.suspension.max} m; lights stay {catalog.suspension.minHeightAboveFloor} m above the floor
        </span>
      </div>
      <OptionChips title="Rotate">
        {ROTATIONS.map((by) => (
          <GatedButton key={by} gate={gate} action="rotateSystem" params={{ systemId, by }} label={`Rotate ${by > 0 ? 'left' : 'right'} ${Math.abs(by)}°`}>
            {by > 0 ? '⟲' : '⟳'} {Math.abs(by)}°
          </GatedButton>
        ))}
      </OptionChips>
      <OptionChips title="Extend the chain">
        {turns.map(({ c, turn, label }) => (
          <GatedButton key={`${c.id}${turn}`} gate={gate} action="addRail" params={{ systemId, connector: c.id, turn }} label={label}>
            {turn === 0 ? '→' : turn > 0 ? '↰' : '↱'} rail
          </GatedButton>
        ))}
      </OptionChips>
      <GatedButton gate={gate} action="deleteSystem" params={{ systemId }} label="Delete system" />
    </OptionsSection>
  );
}
