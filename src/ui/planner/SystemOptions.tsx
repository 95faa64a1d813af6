import type { Catalog } from '../../core/model/catalogSchema';
import { MOUNTINGS, type LightSystem } from '../../core/model/configuration';
import { allowedFeedPositions, describeFeedAt, driversBySize, feedLabel, feedLoads, formatWatts, sameFeedAt } from '../../core/model/feedLoads';
import type { ActionGate } from './actionGate';
import { ChainShapeOptions } from './ChainShapeOptions';
import { CommitField } from './CommitField';
import { GatedButton } from './GatedButton';
import { OptionChips } from './OptionChips';
import { OptionsSection } from './OptionsSection';

/** Rotation steps offered for a selected system, in degrees (positive: counterclockwise, "left"). */
const ROTATIONS = [-90, -15, 15, 90] as const;

const MOUNTING_LABELS: Record<(typeof MOUNTINGS)[number], string> = { suspended: 'Suspended', surface: 'On the ceiling' };

/** A selected system's settings: suspension or surface mounting, power feeds, rotation, extending the chain with a rail, connector angles and fixing points, delete. */
export function SystemOptions({ system, catalog, gate, onClose }: { system: LightSystem; catalog: Catalog; gate: ActionGate; onClose: () => void }) {
  const systemId = system.id;
  // A flexible connector is offered at its default turn (its `angle`) either way; its angle is then adjusted below.
  const turns = catalog.connectors.flatMap((c) => (c.angle === 0 ? [{ c, turn: 0, label: `Add rail straight (${c.name})` }] : [
    { c, turn: c.angle, label: `Add rail turning left ${c.angle}°${c.flex ? ` (${c.name})` : ''}` },
    { c, turn: -c.angle, label: `Add rail turning right ${c.angle}°${c.flex ? ` (${c.name})` : ''}` },
  ]));
  return (
    <OptionsSection title="Lighting system" onClose={onClose}>
      <div className="field">
        <h3>Suspension: ceiling to light (m)</h3>
        <CommitField label="Suspension (m)" value={system.suspension} onCommit={(suspension) => gate.attempt('setSuspension', { systemId, suspension })} onRefused={gate.explain} />
        <span className="empty-note">
          {catalog.suspension.min}–{catalog.suspension.max} m; lights stay {catalog.suspension.minHeightAboveFloor} m above the floor
          {system.mounting === 'surface' ? `; on the ceiling now (lights ${catalog.surfaceMount.drop} m below it), kept for hanging it again` : ''}
        </span>
      </div>
      <OptionChips title="Mounting">
        {MOUNTINGS.map((mounting) => (
          <GatedButton key={mounting} gate={gate} action="setMounting" params={{ systemId, mounting }} label={`Mounting: ${MOUNTING_LABELS[mounting]}`} current={system.mounting === mounting} testId={`mounting-${mounting}`}>
            {MOUNTING_LABELS[mounting]}
          </GatedButton>
        ))}
      </OptionChips>
      <PowerFeeds system={system} catalog={catalog} gate={gate} />
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
            {turn === 0 ? '→' : turn > 0 ? '↰' : '↱'} rail{c.flex ? ` ${c.angle}°` : ''}
          </GatedButton>
        ))}
      </OptionChips>
      <ChainShapeOptions system={system} catalog={catalog} gate={gate} />
      <GatedButton gate={gate} action="deleteSystem" params={{ systemId }} label="Delete system" />
    </OptionsSection>
  );
}

/**
 * Load per feed ("Feed 1: 129 / 153.6 W", what is left), each feed's driver choice and removal, and
 * a new feed at any free position the catalog allows. Every control is a GatedButton: disabled ones
 * carry the model's reason ("the 60 W … cannot carry the 129 W on Feed 1; …").
 */
function PowerFeeds({ system, catalog, gate }: { system: LightSystem; catalog: Catalog; gate: ActionGate }) {
  const systemId = system.id;
  const loads = feedLoads(system, catalog);
  const free = allowedFeedPositions(system, catalog).filter((at) => !system.feeds.some((f) => sameFeedAt(f.at, at)));
  return (
    <div className="field" data-testid="power-feeds">
      <h3>Power</h3>
      {loads.map((l) => (
        <div key={l.feed.id} data-testid={`feed-${l.feed.id}`}>
          <p className="feed-load" data-testid={`feed-load-${l.feed.id}`}>
            <strong>
              {feedLabel(l.index)}: {formatWatts(l.load)} / {formatWatts(l.capacity)} W
            </strong>{' '}
            <span className="preset-detail">
              at {describeFeedAt(l.feed.at)}, {formatWatts(l.capacity - l.load)} W left
            </span>
          </p>
          <OptionChips title={`${feedLabel(l.index)} driver`}>
            {driversBySize(catalog).map((d) => (
              <GatedButton key={d.id} gate={gate} action="setFeedDriver" params={{ feedId: l.feed.id, driver: d.id }} label={`${d.name}, ${formatWatts(d.capacity)} W`} current={l.feed.driver === d.id} testId={`driver-${l.feed.id}-${d.id}`}>
                {formatWatts(d.capacity)} W
              </GatedButton>
            ))}
            <GatedButton gate={gate} action="removeFeed" params={{ feedId: l.feed.id }} label={`Remove ${feedLabel(l.index)}`} testId={`remove-feed-${l.feed.id}`}>
              Remove
            </GatedButton>
          </OptionChips>
        </div>
      ))}
      {free.length > 0 && (
        <OptionChips title="Add a feed">
          {free.map((at) => (
            <GatedButton key={JSON.stringify(at)} gate={gate} action="addFeed" params={{ systemId, at }} label={`Add a feed at ${describeFeedAt(at)}`} testId={`add-feed-${typeof at === 'string' ? at : `joint-${at.joint}`}`}>
              + {describeFeedAt(at)}
            </GatedButton>
          ))}
        </OptionChips>
      )}
    </div>
  );
}
