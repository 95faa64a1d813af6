/**
 * A system's rails as a tree (docs/model.md, "Trees of rails"). Rail 0 is the root; joints[i]
 * hangs rail i+1 on the connector node at the END of rail `parent` (absent: rail i, so a list
 * without parents is the old snake). Rails are listed parents first (parent ≤ i), so one pass
 * in list order visits every parent before its children. A node is one connector: every joint
 * at it names the same connector, and each takes a different port (turn); a connector of P
 * ports takes at most P − 1 branches.
 */
import { keyed } from '../configuration/coding';
import { type Catalog } from '../catalogSchema/catalogSchema';
import { allowedTurn, connectorPorts } from '../catalogSchema/connectorTurns';
import type { Joint, LightSystem } from '../configuration/configuration';

/** The rail whose end holds joints[k] (the parent of rail k+1). */
export function jointParent(joint: Pick<Joint, 'parent'>, k: number): number {
  return joint.parent ?? k;
}

/** Parent rail of every rail: −1 for the root. */
export function railParents(system: Pick<LightSystem, 'rails' | 'joints'>): number[] {
  return system.rails.map((_, i) => (i === 0 ? -1 : jointParent(system.joints[i - 1] ?? {}, i - 1)));
}

/** The joints (indices k, ascending) at the node at the end of rail p: its branches rail k+1. */
export function nodeJoints(system: Pick<LightSystem, 'joints'>, p: number): number[] {
  const out: number[] = [];
  system.joints.forEach((j, k) => {
    if (jointParent(j, k) === p) out.push(k);
  });
  return out;
}

/** The first joint at each rail's end (undefined: a free end), in one pass. */
export function firstNodeJoints(system: Pick<LightSystem, 'rails' | 'joints'>): (number | undefined)[] {
  const out: (number | undefined)[] = system.rails.map(() => undefined);
  system.joints.forEach((j, k) => {
    const p = jointParent(j, k);
    if (p >= 0 && p < out.length && out[p] === undefined) out[p] = k;
  });
  return out;
}

/** Whether rail i's end is free (no connector node there). */
export function isLeafRail(system: Pick<LightSystem, 'joints'>, i: number): boolean {
  return !system.joints.some((j, k) => jointParent(j, k) === i);
}

/** Rail r and every rail below its end, ascending (list order keeps parents first). */
export function subtreeRails(system: Pick<LightSystem, 'rails' | 'joints'>, r: number): number[] {
  const parents = railParents(system);
  const inside = new Set([r]);
  for (let i = r + 1; i < parents.length; i++) if (inside.has(parents[i])) inside.add(i);
  return [...inside].sort((a, b) => a - b);
}

/** True when the system branches (some node holds more than one rail). */
export function isBranched(system: Pick<LightSystem, 'rails' | 'joints'>): boolean {
  const seen = new Set<number>();
  return system.joints.some((j, k) => {
    const p = jointParent(j, k);
    if (seen.has(p)) return true;
    seen.add(p);
    return false;
  });
}

export interface TreeProblem {
  readonly code: 'joint-parent' | 'node-connector' | 'node-ports' | 'node-port-taken';
  /** Index into joints. */
  readonly joint: number;
  readonly field: 'parent' | 'connector' | 'turn';
  readonly message: string;
}

/**
 * The first broken tree rule, or null: each parent an earlier rail; at each node one connector,
 * no more branches than its ports allow, each port (turn) once. Unknown connectors and turns a
 * connector never allows are validate()'s own checks (unknown-connector, bad-turn).
 */
export function treeProblem(system: Pick<LightSystem, 'rails' | 'joints'>, catalog: Catalog): TreeProblem | null {
  for (let k = 0; k < system.joints.length; k++) {
    const p = system.joints[k].parent;
    if (p !== undefined && !(Number.isInteger(p) && p >= 0 && p <= k)) {
      return keyed({ code: 'joint-parent', joint: k, field: 'parent', message: `rail ${k + 2} must hang on an earlier rail (parent 1 to ${k + 1}, got ${String(typeof p === 'number' ? p + 1 : p)})` }, 'jointParent', {
        rail: k + 2,
        max: k + 1,
        value: String(typeof p === 'number' ? p + 1 : p),
      });
    }
  }
  const byNode = new Map<number, number[]>();
  system.joints.forEach((j, k) => {
    const p = jointParent(j, k);
    const list = byNode.get(p);
    if (list) list.push(k);
    else byNode.set(p, [k]);
  });
  for (const [p, ks] of byNode) {
    const first = system.joints[ks[0]];
    for (const k of ks.slice(1)) {
      const j = system.joints[k];
      if (j.connector !== first.connector)
        return keyed({ code: 'node-connector', joint: k, field: 'connector', message: `the connector at the end of rail ${p + 1} is '${first.connector}'; rail ${k + 2} cannot hang on it through '${j.connector}'` }, 'nodeConnector', {
          rail: p + 1,
          connector: first.connector,
          branch: k + 2,
          other: j.connector,
        });
    }
    const con = catalog.connectors.find((c) => c.id === first.connector);
    if (!con) continue;
    const ports = connectorPorts(con);
    if (ks.length > ports - 1)
      return keyed({ code: 'node-ports', joint: ks[ports - 1], field: 'connector', message: `the ${con.name} at the end of rail ${p + 1} joins ${ports} rail ends; it cannot hold ${ks.length} branches` }, 'nodePorts', {
        name: con.name,
        connectorId: con.id,
        rail: p + 1,
        ports,
        count: ks.length,
      });
    const turns = new Set<number>();
    for (const k of ks) {
      const t = system.joints[k].turn;
      if (turns.has(t) && allowedTurn(con, t))
        return keyed({ code: 'node-port-taken', joint: k, field: 'turn', message: `two rails leave the ${con.name} at the end of rail ${p + 1} through one port (${t}°)` }, 'nodeOnePort', {
          name: con.name,
          connectorId: con.id,
          rail: p + 1,
          turn: t,
        });
      turns.add(t);
    }
  }
  return null;
}
