import './registerOptionsEnglish';
import { type Catalog } from '../../core/model/catalogSchema/catalogSchema';
import { connectorPorts } from '../../core/model/catalogSchema/connectorTurns';
import { type ConnectorSpec } from '../../core/model/catalogSchema/railSystemSchema';
import type { LightSystem, Rail } from '../../core/model/configuration/configuration';
import { nodeJoints } from '../../core/model/rails/railTree';
import type { ActionGate } from './actionGate';
import { GatedButton } from './GatedButton';
import { OptionChips } from './OptionChips';
import { useI18n } from '../i18n/useI18n';
import { localName } from '../i18n/localName';
import type { MessageKey } from '../i18n/messageTypes';

/** Branch length offered by the buttons, metres (then set on the new rail like any other). */
const BRANCH_LENGTH = 1;

/** The ports a connector offers, as turns (left +): a T or X all three directions, a corner both sides, a straight or flexible one its default turn. */
function portTurns(con: ConnectorSpec): number[] {
  if (connectorPorts(con) > 2) return [con.angle, 0, -con.angle];
  if (con.angle === 0) return [0];
  return [con.angle, -con.angle];
}

function directionKey(turn: number): MessageKey {
  return turn > 0 ? 'connectors.left' : turn < 0 ? 'connectors.right' : 'connectors.straight';
}

/**
 * The end of a selected rail as a place to branch (docs/planner.md, "Branches"): with a connector
 * there, its name, its free ports (a branch through each) and the connectors it can become; at a
 * free end, a branch through any connector, in each direction it offers. Every button is gated by
 * the model (addBranch, setConnector), so a port that is taken, a branch that would leave the room
 * or a connector whose ports do not fit is disabled with the model's reason.
 */
export function BranchOptions({ rail, system, catalog, gate }: { rail: Rail; system: LightSystem; catalog: Catalog; gate: ActionGate }) {
  const { t, language } = useI18n();
  const railIndex = system.rails.indexOf(rail);
  const at = nodeJoints(system, railIndex);
  const n = railIndex + 1;
  const node = at.length > 0 ? catalog.connectors.find((c) => c.id === system.joints[at[0]].connector) : undefined;
  const taken = new Set(at.map((k) => system.joints[k].turn));
  const branchButton = (con: ConnectorSpec, turn: number, withConnector: boolean) => {
    const direction = t(directionKey(turn));
    return (
      <GatedButton
        key={`${con.id}:${turn}`}
        gate={gate}
        action="addBranch"
        params={{ railId: rail.id, ...(withConnector ? { connector: con.id } : {}), turn, length: BRANCH_LENGTH }}
        label={t('connectors.branchLabel', { name: localName(con, language), direction, n })}
        testId={`branch-${rail.id}-${con.id}-${turn}`}
      >
        + {t('connectors.branchChip', { direction })}
      </GatedButton>
    );
  };
  return (
    <div className="field" data-testid={`branches-${rail.id}`}>
      <h3>{t('connectors.title', { n })}</h3>
      {node ? (
        <>
          <p className="preset-detail">{t('connectors.ports', { name: localName(node, language), free: Math.max(0, connectorPorts(node) - 1 - at.length), ports: connectorPorts(node) })}</p>
          <OptionChips title={t('connectors.addBranch')}>
            {portTurns(node)
              .filter((turn) => !taken.has(turn))
              .map((turn) => branchButton(node, turn, false))}
          </OptionChips>
          <OptionChips title={t('connectors.change')}>
            {catalog.connectors.map((c) => (
              <GatedButton
                key={c.id}
                gate={gate}
                action="setConnector"
                params={{ railId: rail.id, connector: c.id }}
                label={t('connectors.changeTo', { n, name: localName(c, language) })}
                current={c.id === node.id}
                testId={`connector-${rail.id}-${c.id}`}
              >
                {localName(c, language)}
              </GatedButton>
            ))}
          </OptionChips>
        </>
      ) : (
        <>
          <p className="preset-detail">{t('connectors.freeEnd')}</p>
          {catalog.connectors.map((c) => (
            <OptionChips key={c.id} title={t('connectors.addBranchVia', { name: localName(c, language) })}>
              {portTurns(c).map((turn) => branchButton(c, turn, true))}
            </OptionChips>
          ))}
        </>
      )}
    </div>
  );
}
