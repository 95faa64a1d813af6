/**
 * Adjusting a chain's shape in place: the turn of a flexible-angle connector (setJointTurn) and
 * the position of a fixing point (moveFixingPoint), docs/model.md "Flexible connectors" and
 * "Moving fixing points". Range, walls, clashes and the fixing rules are validate()'s, checked
 * on the result where the action is bound; these definitions snap the input and word refusals.
 */
import { z } from 'zod/mini';
import { InputError } from '../../inputError';
import { refuse, type ActionDefinition, type CodedReason } from './action';
import { quoting } from '../configuration/coding';
import { findConnector, type Catalog } from '../catalogSchema/catalogSchema';
import { type ConnectorSpec } from '../catalogSchema/railSystemSchema';
import type { Configuration, LightSystem } from '../configuration/configuration';
import { suspensionCoordinates } from '../rails/suspensionPoints';
import { replaceSystem, systemIndex } from './lookup';

/** Grid a moved fixing point snaps to along the chain, metres (a centimetre: what a fitter marks). */
export const FIXING_STEP = 0.01;

/** Nearest multiple of the connector's step, without −0. */
export function snapTurn(degrees: number, con: ConnectorSpec): number {
  const step = con.flex?.step ?? 1;
  const t = Math.round(Math.round(degrees / step) * step * 1e6) / 1e6;
  return t === 0 ? 0 : t;
}

/** Nearest centimetre, rounded to a micrometre so 1.3 stays 1.3. */
export function snapFixing(s: number): number {
  return Math.round(Math.round(s / FIXING_STEP) * FIXING_STEP * 1e6) / 1e6;
}

function jointOf(state: Configuration, systemId: string, joint: number, catalog: Catalog): { si: number; system: LightSystem; con: ConnectorSpec } {
  const si = systemIndex(state, systemId);
  const system = state.systems[si];
  const j = system.joints[joint];
  if (!j) throw new InputError(`system ${systemId} has no connector ${joint + 1}`, { code: 'noSuchConnector', params: { id: systemId, n: joint + 1 } });
  return { si, system, con: findConnector(catalog, j.connector) };
}

const turnParams = z.object({ systemId: z.string(), joint: z.number().check(z.int(), z.gte(0)), degrees: z.number() });

/** Sets the turn of a flexible connector (joints[joint]), snapped to its step. */
export const setJointTurn: ActionDefinition<z.infer<typeof turnParams>> = {
  name: 'setJointTurn',
  label: 'Connector angle',
  params: turnParams,
  isEnabled(state, p, catalog) {
    const { con } = jointOf(state, p.systemId, p.joint, catalog);
    return con.flex ? true : refuse(`the ${con.name} has a fixed angle; only a flexible connector can be turned`, { code: 'connectorFixedAngle', params: { name: con.name, connectorId: con.id } });
  },
  perform(state, p, catalog) {
    const { si, system, con } = jointOf(state, p.systemId, p.joint, catalog);
    const turn = snapTurn(p.degrees, con);
    // The chain's coordinates do not depend on a flexible connector's turn (it always bridges two arms), so moved fixing points stay valid.
    return replaceSystem(state, si, { ...system, joints: system.joints.map((j, k) => (k === p.joint ? { ...j, turn } : j)) });
  },
  explain(problem, state, p, catalog): string | CodedReason {
    const { con } = jointOf(state, p.systemId, p.joint, catalog);
    const turn = snapTurn(p.degrees, con);
    if (problem.code === 'bad-turn')
      return { reason: `the ${con.name} turns at most ±${con.flex?.maxAngle ?? con.angle}°`, code: 'connectorTurnsAtMost', params: { name: con.name, connectorId: con.id, max: con.flex?.maxAngle ?? con.angle } };
    if (problem.code === 'outside-room') return { reason: `at ${turn}° the chain would reach outside the room`, code: 'turnOutsideRoom', params: { turn } };
    if (problem.code === 'self-overlap') return { reason: `at ${turn}° the chain would run into itself`, code: 'turnSelfOverlap', params: { turn } };
    if (problem.code === 'system-overlap') return { reason: `at ${turn}° ${problem.message.replace(/^system \S+ /, 'the chain ')}`, code: 'turnOverlap', params: { turn, other: problem.params?.other ?? '' } };
    return problem.message;
  },
};

const fixingParams = z.object({ systemId: z.string(), index: z.number().check(z.int(), z.gte(0)), s: z.number() });

/**
 * Moves fixing point `index` (suspension or clip, in chain order) to chain coordinate `s`,
 * snapped to FIXING_STEP. The system then stores all its points (`fixings`); a point on a
 * connector does not move (a connector is always a support).
 */
export const moveFixingPoint: ActionDefinition<z.infer<typeof fixingParams>> = {
  name: 'moveFixingPoint',
  label: 'Move fixing point',
  params: fixingParams,
  perform(state, p, catalog) {
    const si = systemIndex(state, p.systemId);
    const system = state.systems[si];
    const current = suspensionCoordinates(system, catalog);
    const point = current[p.index];
    if (!point) throw new InputError(`system ${p.systemId} has ${current.length} fixing points, not ${p.index + 1}`, { code: 'noSuchFixingPoint', params: { id: p.systemId, count: current.length, n: p.index + 1 } });
    if (point.joint !== null) throw new InputError(`this point holds connector ${point.joint + 1}; a connector is always a support`, { code: 'fixingHoldsConnector', params: { n: point.joint + 1 } });
    const fixings = current.map((x, i) => (i === p.index ? snapFixing(p.s) : x.s));
    return replaceSystem(state, si, { ...system, fixings });
  },
  explain(problem, _state, p) {
    if (problem.code.startsWith('fixing-')) return quoting(`cannot move the point to ${snapFixing(p.s)} m: ${problem.message}`, 'fixingCannotMove', problem, { s: snapFixing(p.s) });
    return problem.message;
  },
};
