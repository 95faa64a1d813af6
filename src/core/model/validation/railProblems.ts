/** A system's chain: rails and joints (connectors, turns), rail lengths, and whether each rail's modules fit it. */
import { findModuleType, type Catalog } from '../catalogSchema/catalogSchema';
import { allowedTurn } from '../catalogSchema/connectorTurns';
import { onGrid } from '../catalogSchema/catalogFields';
import type { LightSystem } from '../configuration/configuration';
import { freeRailProblem, isFreeRail } from '../rails/freePositions';
import { railModuleOffsets } from '../rails/geometry';
import { moduleProblems } from './moduleProblems';
import { EPS, fmt, type ReportProblem, type ReportSubProblem } from './reporting';

/** The rail count's joints, each a known connector turned as it allows. */
export function jointProblems(s: LightSystem, catalog: Catalog, p: ReportProblem): void {
  if (s.rails.length === 0) p('no-rails', '.rails', `system ${s.id} has no rails`, { id: s.id }, 'noRails');
  if (s.joints.length !== Math.max(0, s.rails.length - 1)) p('joint-count', '.joints', `${s.rails.length} rails need ${Math.max(0, s.rails.length - 1)} joints, found ${s.joints.length}`, { rails: s.rails.length, needed: Math.max(0, s.rails.length - 1), found: s.joints.length }, 'jointCount');
  s.joints.forEach((j, i) => {
    const con = catalog.connectors.find((c) => c.id === j.connector);
    if (!con) p('unknown-connector', `.joints[${i}].connector`, `unknown connector '${j.connector}'`, { id: j.connector }, 'unknownConnector');
    else if (!allowedTurn(con, j.turn)) {
      if (con.flex) p('bad-turn', `.joints[${i}].turn`, `connector '${con.id}' turns by a multiple of ${con.flex.step}° within ±${con.flex.maxAngle}°, not ${j.turn}°`, { id: con.id, connectorId: con.id, step: con.flex.step, max: con.flex.maxAngle, turn: j.turn }, 'badTurnFlex');
      else p('bad-turn', `.joints[${i}].turn`, `connector '${con.id}' turns by ±${con.angle}°, not ${j.turn}°`, { id: con.id, connectorId: con.id, angle: con.angle, turn: j.turn }, 'badTurn');
    }
  });
}

/** Each rail: its length (range, grid), its modules' own rules, and whether they fit it (free positions or the distribution). */
export function railProblems(s: LightSystem, catalog: Catalog, p: ReportProblem, sub: ReportSubProblem): void {
  const rail = catalog.rail;
  s.rails.forEach((r, k) => {
    const rp = `.rails[${k}]`;
    if (!Number.isFinite(r.length) || r.length < rail.minLength - EPS || r.length > rail.maxLength + EPS) {
      p('rail-length-range', `${rp}.length`, `rail length must be between ${rail.minLength} and ${rail.maxLength} m (got ${r.length})`, { min: rail.minLength, max: rail.maxLength, value: r.length });
    } else if (!onGrid(r.length, rail.step)) p('rail-length-grid', `${rp}.length`, `rail length must be a multiple of ${rail.step} m (got ${r.length})`, { step: rail.step, value: r.length });
    const refsOk = moduleProblems(r, rp, catalog, p, sub);
    const free = refsOk && Number.isFinite(r.length) && isFreeRail(r) ? freeRailProblem(r, r.modules.map((m) => findModuleType(catalog, m.type).length)) : null;
    if (free) sub(free.code, `${rp}.modules[${free.index}].offset`, free);
    else if (refsOk && Number.isFinite(r.length) && !railModuleOffsets(r, catalog)) {
      p('modules-do-not-fit', `${rp}.modules`, `the modules of rail ${r.id} do not fit its ${fmt(r.length)} m with distribution '${r.distribution}'`, { rail: r.id, length: Number(fmt(r.length)), distribution: r.distribution });
    }
  });
}
