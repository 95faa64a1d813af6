/**
 * Growing and reshaping a tree of rails (docs/model.md, "Trees of rails"): a branch at any rail's
 * end (a free end, or a free port of the connector there) and changing the connector of a node
 * (straight ↔ corner ↔ T ↔ X where its branches fit the ports). Ports, walls, clashes, feeds and
 * fixing points are validate()'s rules, checked on the result where the action is bound; these
 * definitions build the result and word the refusals.
 */
import { z } from 'zod/mini';
import { InputError } from '../../inputError';
import { refuse, type ActionDefinition, type CodedReason, type Refusal } from './action';
import { findConnector, type Catalog } from '../catalogSchema/catalogSchema';
import { allowedTurn, connectorPorts } from '../catalogSchema/connectorTurns';
import type { Configuration, FeedAt, Rail } from '../configuration/configuration';
import { keepFixingsIfValid } from '../rails/fixingRules';
import { jointParent, nodeJoints } from '../rails/railTree';
import type { Problem } from '../configuration/problem';
import { findRail, replaceSystem, takeId } from './lookup';
import { snapRailLength } from './railActions';

const branchParams = z.object({
  /** The rail at whose END the branch starts (its free end, or the connector already there). */
  railId: z.string(),
  /** Catalog connector id; at an existing connector its own (omitted: that one). */
  connector: z.optional(z.string()),
  /** Degrees, + = left turn: the port (T, X: −angle, 0, +angle). */
  turn: z.number(),
  length: z.optional(z.number()),
});
type BranchParams = z.infer<typeof branchParams>;

/** The connector a branch at this rail's end goes through: the one asked for, else the node's own (another than the node's makes the node invalid: validate()'s node-connector). */
function branchConnector(state: Configuration, p: BranchParams): string {
  if (p.connector !== undefined) return p.connector;
  const { system, railIndex } = findRail(state, p.railId);
  const at = nodeJoints(system, railIndex);
  if (at.length > 0) return system.joints[at[0]].connector;
  throw new InputError('a branch at a free rail end needs a connector', { code: 'branchNeedsConnector' });
}

/**
 * Adds an empty rail at the end of `railId`: through a new connector at a free end, or through a
 * free port of the connector already there. The new rail is listed last (its parent comes
 * first). Feeds stay where they are: a feed at the chain end ('end') that is not on the grown
 * rail keeps its rail ({ end: i }); one at the grown free end moves on to the new end (as addRail).
 */
export const addBranch: ActionDefinition<BranchParams> = {
  name: 'addBranch',
  label: 'Add branch',
  params: branchParams,
  isEnabled(state, p) {
    const { system, railIndex } = findRail(state, p.railId);
    const at = nodeJoints(system, railIndex);
    if (at.length > 0 && p.connector !== undefined && p.connector !== system.joints[at[0]].connector) {
      const connector = system.joints[at[0]].connector;
      return refuse(`a connector already sits at the end of this rail ('${connector}'); change it first`, { code: 'connectorAlreadyThere', params: { connector, connectorId: connector } });
    }
    return true;
  },
  perform(state, p, catalog) {
    const { systemIndex: si, railIndex } = findRail(state, p.railId);
    const connector = branchConnector(state, p);
    const [id, next] = takeId(state, 'r');
    const s = next.systems[si];
    const n = s.rails.length;
    const rail: Rail = { id, length: snapRailLength(p.length ?? catalog.rail.defaultLength, catalog), distribution: 'inside-centred', modules: [] };
    const grown = nodeJoints(s, railIndex).length === 0;
    const feeds = s.feeds.map((f) => {
      const at: FeedAt = f.at;
      const onGrownEnd = grown && ((at === 'end' && railIndex === n - 1) || (typeof at === 'object' && 'end' in at && at.end === railIndex));
      if (onGrownEnd) return { ...f, at: 'end' as const };
      if (at === 'end') return { ...f, at: { end: n - 1 } };
      return f;
    });
    const joint = railIndex === n - 1 ? { connector, turn: p.turn } : { connector, turn: p.turn, parent: railIndex };
    return replaceSystem(next, si, keepFixingsIfValid({ ...s, rails: [...s.rails, rail], joints: [...s.joints, joint], feeds }, catalog));
  },
  explain(problem, state, p, catalog) {
    const con = findConnector(catalog, branchConnector(state, p));
    const named = { name: con.name, connectorId: con.id };
    if (problem.code === 'bad-turn') {
      if (connectorPorts(con) > 2) return { reason: `the ${con.name} takes branches straight on or at ±${con.angle}°`, code: 'branchTurnNode', params: { ...named, angle: con.angle } };
      if (con.flex) return { reason: `the ${con.name} turns by a multiple of ${con.flex.step}° within ±${con.flex.maxAngle}°`, code: 'connectorTurnFlex', params: { ...named, step: con.flex.step, max: con.flex.maxAngle } };
      return con.angle === 0 ? { reason: `the ${con.name} does not turn`, code: 'branchNoTurn', params: named } : { reason: `the ${con.name} turns by ±${con.angle}°`, code: 'branchTurnAngle', params: { ...named, angle: con.angle } };
    }
    if (problem.code === 'node-ports') return { reason: `the ${con.name} at the end of this rail has no free port; change it to one with more ports`, code: 'nodeNoFreePort', params: named };
    if (problem.code === 'node-port-taken') return { reason: `the ${con.name}'s port at ${p.turn}° is taken`, code: 'nodePortTaken', params: { ...named, turn: p.turn } };
    return branchReason(problem);
  },
};

const connectorParams = z.object({
  /** The rail at whose end the connector node sits. */
  railId: z.string(),
  connector: z.string(),
});

/**
 * Changes the connector at the end of `railId` (every branch there goes through the new one,
 * each keeping its port). Refused when the branches do not fit its ports: a straight connector
 * holds one branch straight on, a corner one at ±angle, a flexible one within its range, a T two
 * of −angle, 0, +angle, an X three.
 */
export const setConnector: ActionDefinition<z.infer<typeof connectorParams>> = {
  name: 'setConnector',
  label: 'Connector',
  params: connectorParams,
  isEnabled(state, p, catalog) {
    const { system, railIndex } = findRail(state, p.railId);
    const at = nodeJoints(system, railIndex);
    if (at.length === 0) return refuse('no connector sits at the end of this rail; add a rail or a branch there', { code: 'noConnectorAtEnd' });
    const con = findConnector(catalog, p.connector);
    return (
      connectorFits(
        con,
        at.map((k) => system.joints[k].turn),
        catalog,
      ) ?? true
    );
  },
  perform(state, p, catalog) {
    const { systemIndex: si, system, railIndex } = findRail(state, p.railId);
    findConnector(catalog, p.connector);
    if (nodeJoints(system, railIndex).length === 0) throw new InputError('no connector sits at the end of this rail; add a rail or a branch there', { code: 'noConnectorAtEnd' });
    const joints = system.joints.map((j, k) => (jointParent(j, k) === railIndex ? { ...j, connector: p.connector } : j));
    // The connector's span can change: moved fixing points stay only when they keep the rules.
    return replaceSystem(state, si, keepFixingsIfValid({ ...system, joints }, catalog));
  },
  explain(problem) {
    return branchReason(problem);
  },
};

/** Why a connector cannot hold these branches (their turns), or null when it can. */
export function connectorFits(con: ReturnType<typeof findConnector>, turns: readonly number[], _catalog: Catalog): Refusal | null {
  const ports = connectorPorts(con);
  const named = { name: con.name, connectorId: con.id };
  if (turns.length > ports - 1) return refuse(`the ${con.name} joins ${ports} rail ends; ${turns.length} branches leave this connector`, { code: 'connectorTooFewPorts', params: { ...named, ports, count: turns.length } });
  const bad = turns.find((t) => !allowedTurn(con, t));
  if (bad !== undefined) {
    // One code per wording of the range, so a UI words the whole sentence.
    const range = ports > 2 ? `straight on or ±${con.angle}°` : con.flex ? `within ±${con.flex.maxAngle}° in ${con.flex.step}° steps` : con.angle === 0 ? 'straight on only' : `by ±${con.angle}° only`;
    const code = ports > 2 ? 'connectorTurnsNode' : con.flex ? 'connectorTurnsFlex' : con.angle === 0 ? 'connectorTurnsStraight' : 'connectorTurnsAngle';
    return refuse(`the ${con.name} turns ${range}; a branch here turns ${bad}°`, { code, params: { ...named, angle: con.angle, step: con.flex?.step ?? 0, max: con.flex?.maxAngle ?? con.angle, turn: bad } });
  }
  return null;
}

/** Walls, clashes and feeds in the shopper's words. */
function branchReason(problem: Problem): string | CodedReason {
  if (problem.code === 'outside-room') return { reason: 'the branch would reach outside the room', code: 'branchOutsideRoom' };
  if (problem.code === 'self-overlap') return { reason: 'the branch would run into the system itself', code: 'branchSelfOverlap' };
  if (problem.code === 'system-overlap') return { reason: problem.message.replace(/^system \S+ /, 'the branch '), code: 'branchOverlap', params: { other: problem.params?.other ?? '' } };
  return problem.message;
}
