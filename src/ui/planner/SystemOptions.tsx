import './registerOptionsEnglish';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import { MOUNTINGS, type LightSystem } from '../../core/model/configuration/configuration';
import { allowedFeedPositions, driversBySize, feedLoads, formatWatts, sameFeedAt } from '../../core/model/power/feedLoads';
import type { ActionGate } from './actionGate';
import { ChainShapeOptions } from './ChainShapeOptions';
import { CommitField } from '../shared/CommitField';
import { GatedButton } from './GatedButton';
import { OptionChips } from './OptionChips';
import { OptionsSection } from './OptionsSection';
import { useI18n } from '../i18n/useI18n';
import type { MessageKey } from '../i18n/messageTypes';
import { feedAtText } from '../i18n/feedText';
import { localName } from '../i18n/localName';
import { railPlacements } from '../../core/model/rails/geometry';
import { TurnArrow } from './TurnArrow';

/** Rotation steps offered for a selected system, in degrees (positive: counterclockwise, "left"). */
const ROTATIONS = [-90, -15, 15, 90] as const;

const MOUNTING_LABELS: Record<(typeof MOUNTINGS)[number], MessageKey> = { suspended: 'options.mountingSuspended', surface: 'options.mountingSurface' };

/** A selected system's settings: suspension or surface mounting, power feeds, rotation, extending the chain with a rail, connector angles and fixing points, delete. */
export function SystemOptions({ system, catalog, gate, onClose }: { system: LightSystem; catalog: Catalog; gate: ActionGate; onClose: () => void }) {
  const { t, language } = useI18n();
  const systemId = system.id;
  // Each connector either way it turns (a flexible one at its default angle, adjusted below), named by
  // direction — straight on, left, right — with the connector as the second line, in that order.
  const turns = catalog.connectors.flatMap((c) =>
    c.angle === 0
      ? [{ c, turn: 0 }]
      : [
          { c, turn: c.angle },
          { c, turn: -c.angle },
        ],
  );
  const rank = (turn: number) => (turn === 0 ? 0 : turn > 0 ? 1 : 2);
  turns.sort((a, b) => rank(a.turn) - rank(b.turn));
  const direction = (turn: number, angle: number) => (turn === 0 ? t('options.extendStraight') : t(turn > 0 ? 'options.extendLeft' : 'options.extendRight', { angle }));
  // The chain grows at the end of its last rail (addRail): the arrows start along that rail's heading on the plan.
  const endHeading = railPlacements(system, catalog).at(-1)?.heading ?? system.rotation;
  return (
    <OptionsSection title={t('options.systemTitle')} onClose={onClose}>
      <div className="field">
        <h3>{t('options.suspensionHeading')}</h3>
        <CommitField label={t('options.suspensionField')} value={system.suspension} onCommit={(suspension) => gate.attempt('setSuspension', { systemId, suspension })} onRefused={gate.explain} />
        <span className="empty-note">
          {t('options.suspensionRange', { min: catalog.suspension.min, max: catalog.suspension.max, above: catalog.suspension.minHeightAboveFloor })}
          {system.mounting === 'surface' ? t('options.suspensionKept', { drop: catalog.surfaceMount.drop }) : ''}
        </span>
      </div>
      <OptionChips title={t('options.mounting')}>
        {MOUNTINGS.map((mounting) => (
          <GatedButton
            key={mounting}
            gate={gate}
            action="setMounting"
            params={{ systemId, mounting }}
            label={t('options.mountingLabel', { mounting: t(MOUNTING_LABELS[mounting]) })}
            current={system.mounting === mounting}
            testId={`mounting-${mounting}`}
          >
            {t(MOUNTING_LABELS[mounting])}
          </GatedButton>
        ))}
      </OptionChips>
      <PowerFeeds system={system} catalog={catalog} gate={gate} />
      <OptionChips title={t('options.rotate')}>
        {ROTATIONS.map((by) => (
          <GatedButton key={by} gate={gate} action="rotateSystem" params={{ systemId, by }} label={t(by > 0 ? 'options.rotateLeft' : 'options.rotateRight', { degrees: Math.abs(by) })}>
            {by > 0 ? '⟲' : '⟳'} {Math.abs(by)}°
          </GatedButton>
        ))}
      </OptionChips>
      <OptionChips title={t('options.extendChain')}>
        {turns.map(({ c, turn }) => {
          const name = localName(c, language);
          return (
            <GatedButton
              key={`${c.id}${turn}`}
              gate={gate}
              action="addRail"
              params={{ systemId, connector: c.id, turn }}
              label={t('options.extendLabel', { direction: direction(turn, Math.abs(turn)), name })}
              testId={`extend-${c.id}-${turn > 0 ? 'left' : turn < 0 ? 'right' : 'straight'}`}
            >
              <span className="extend-chip">
                <TurnArrow heading={endHeading} turn={turn} />
                <span aria-hidden="true">
                  {direction(turn, Math.abs(turn))}
                  <small>{name}</small>
                </span>
              </span>
            </GatedButton>
          );
        })}
      </OptionChips>
      <ChainShapeOptions system={system} catalog={catalog} gate={gate} />
      <GatedButton gate={gate} action="deleteSystem" params={{ systemId }} label={t('options.deleteSystem')} />
    </OptionsSection>
  );
}

/**
 * Load per feed ("Feed 1: 129 / 153.6 W", what is left), each feed's driver choice and removal, and
 * a new feed at any free position the catalog allows. Every control is a GatedButton: disabled ones
 * carry the model's reason ("the 60 W … cannot carry the 129 W on Feed 1; …").
 */
function PowerFeeds({ system, catalog, gate }: { system: LightSystem; catalog: Catalog; gate: ActionGate }) {
  const { t, format } = useI18n();
  // Watts as the core rounds them (two decimals at most), written in the locale.
  const watts = (w: number) => Number(formatWatts(w));
  const systemId = system.id;
  const loads = feedLoads(system, catalog);
  const free = allowedFeedPositions(system, catalog).filter((at) => !system.feeds.some((f) => sameFeedAt(f.at, at)));
  return (
    <div className="field" data-testid="power-feeds">
      <h3>{t('options.power')}</h3>
      {loads.map((l) => (
        <div key={l.feed.id} data-testid={`feed-${l.feed.id}`}>
          <p className="feed-load" data-testid={`feed-load-${l.feed.id}`}>
            <strong>{t('options.feedLoad', { n: l.index + 1, load: watts(l.load), capacity: watts(l.capacity) })}</strong>{' '}
            <span className="preset-detail">{t('options.feedWhere', { at: feedAtText(t, l.feed.at), left: watts(l.capacity - l.load) })}</span>
          </p>
          <OptionChips title={t('options.feedDriver', { n: l.index + 1 })}>
            {driversBySize(catalog).map((d) => (
              <GatedButton
                key={d.id}
                gate={gate}
                action="setFeedDriver"
                params={{ feedId: l.feed.id, driver: d.id }}
                label={t('options.driverChoice', { name: d.name, watts: watts(d.capacity) })}
                current={l.feed.driver === d.id}
                testId={`driver-${l.feed.id}-${d.id}`}
              >
                {format.number(watts(d.capacity))} W
              </GatedButton>
            ))}
            <GatedButton gate={gate} action="removeFeed" params={{ feedId: l.feed.id }} label={t('options.removeFeed', { n: l.index + 1 })} testId={`remove-feed-${l.feed.id}`}>
              {t('options.remove')}
            </GatedButton>
          </OptionChips>
        </div>
      ))}
      {free.length > 0 && (
        <OptionChips title={t('options.addFeed')}>
          {free.map((at) => (
            <GatedButton
              key={JSON.stringify(at)}
              gate={gate}
              action="addFeed"
              params={{ systemId, at }}
              label={t('options.addFeedAt', { at: feedAtText(t, at) })}
              testId={`add-feed-${typeof at === 'string' ? at : 'joint' in at ? `joint-${at.joint}` : `end-${at.end}`}`}
            >
              + {feedAtText(t, at)}
            </GatedButton>
          ))}
        </OptionChips>
      )}
    </div>
  );
}
