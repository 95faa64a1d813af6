/** What a connector allows: the turns, its ports, whether it bridges with two arms (docs/catalog-format.md, "Connectors"). */
import { onGrid } from './catalogFields';
import type { ConnectorSpec } from './railSystemSchema';

/**
 * Whether a connector may turn by `turn` degrees: a fixed one by exactly ±angle (0 for straight),
 * a flexible one by a multiple of its step within ±maxAngle.
 */
export function allowedTurn(con: Pick<ConnectorSpec, 'angle' | 'flex' | 'ports'>, turn: number): boolean {
  if (!Number.isFinite(turn)) return false;
  if (connectorPorts(con) > 2) return turn === 0 || Math.abs(turn) === con.angle;
  if (!con.flex) return Math.abs(turn) === con.angle;
  return Math.abs(turn) <= con.flex.maxAngle + 1e-9 && onGrid(turn, con.flex.step);
}

/** Rail ends a connector joins: 2 unless the catalog says 3 (T) or 4 (X); a node takes ports − 1 branches. */
export function connectorPorts(con: Pick<ConnectorSpec, 'ports'>): number {
  return con.ports ?? 2;
}

/** The turns a connector allows, in words ('must be ±90', 'must be a multiple of 5 within ±90'). */
export function turnRange(con: Pick<ConnectorSpec, 'angle' | 'flex' | 'ports'>): string {
  if (connectorPorts(con) > 2) return `must be 0 or ±${con.angle}`;
  return con.flex ? `must be a multiple of ${con.flex.step}° within ±${con.flex.maxAngle}°` : `must be ±${con.angle}`;
}

/**
 * True when a connector bridges its rails with two arms through a hinge (corner) point: a corner
 * or a flexible connector, whatever its turn (a flexible one at 0° is still two arms long).
 */
export function twoArmed(con: Pick<ConnectorSpec, 'angle' | 'flex'>): boolean {
  return con.angle !== 0 || con.flex !== undefined;
}
