/**
 * A system's own rules, whatever its place in the plan: how it hangs, its joints and tree, its rails
 * and modules, its feeds (feedProblems.ts), its moved fixing points — in that order, each stage only
 * where the ones before it let the next make sense. One step per domain (hangingProblems,
 * jointProblems, railProblems with moduleProblems, overloadProblems). The planner's first screen
 * carries them: the split cost 52 B of its gzip on index.html and 50 B on embed.html (issue 28,
 * measured with scripts/firstScreenBudget.mjs against the one-function version).
 */
import { findModuleType, type Catalog } from '../catalogSchema/catalogSchema';
import { keyed, type Keyed } from '../configuration/coding';
import { MOUNTINGS, type LightSystem } from '../configuration/configuration';
import type { Problem } from '../configuration/problem';
import { perCatalog } from '../catalogSchema/perCatalog';
import { fixingProblem } from '../rails/fixingRules';
import { treeProblem } from '../rails/railTree';
import { onGrid } from '../catalogSchema/catalogFields';
import { allowedTurn } from '../catalogSchema/connectorTurns';
import { aimProblem } from '../modules/aim';
import { patchRangeIssue } from '../modules/dmxPatch';
import { moduleFilterProblem } from '../modules/moduleFilter';
import { feedLabel, feedLoads, formatWatts, isOverloaded } from '../power/feedLoads';
import { freeRailProblem, isFreeRail } from '../rails/freePositions';
import { railModuleOffsets } from '../rails/geometry';
import { photometricDrop } from '../rails/suspensionPoints';
import { feedProblems } from './feedProblems';
import { EPS, fmt, type ReportProblem } from './reporting';

/** A system's own rules, with paths relative to the system ('.rails[0].length'): the part of systemProblems that does not depend on where it stands, but for a finite x and z. */
export function systemOwnProblems(s: LightSystem, roomHeight: number, catalog: Catalog): Problem[] {
  return ownProblems(s, '', roomHeight, catalog);
}

/**
 * A system's own problems, worked out once per system object, catalog and room height
 * (perCatalog.ts) with paths relative to the system: validate() after every action, and the clash
 * checks against every other system, ask again for the systems the action left alone.
 */
const ownByHeight = perCatalog((_s: LightSystem) => new Map<number, readonly Problem[]>());

export function ownProblems(s: LightSystem, at: string, roomHeight: number, catalog: Catalog): Problem[] {
  const known = ownByHeight(s, catalog);
  let list = known.get(roomHeight);
  if (!list) known.set(roomHeight, (list = computeOwnProblems(s, roomHeight, catalog)));
  return list.map((q) => ({ ...q, path: `${at}${q.path}` }));
}

/** Reports a problem (ReportProblem) and a sub-rule's problem (fixing points, free positions, the tree, aim, filter, patch) with its own coding. */
interface OwnReport {
  p: ReportProblem;
  sub: (code: string, path: string, found: { message: string } & Keyed) => void;
}

function computeOwnProblems(s: LightSystem, roomHeight: number, catalog: Catalog): Problem[] {
  const out: Problem[] = [];
  // `key`: the sentence's own code where the rule has several (docs/i18n.md); its params then travel non-enumerable.
  const p: ReportProblem = (code, path, message, params, key) => out.push(key ? keyed({ code, path, message }, key, params) : { code, path, message, ...(params ? { params } : {}) });
  const report: OwnReport = { p, sub: (code, path, found) => p(code, path, found.message, found.params, found.key) };
  hangingProblems(s, roomHeight, catalog, p);
  jointProblems(s, catalog, p);
  if (out.length === 0) {
    // The tree (railTree.ts): parents before children, one connector per node, its ports.
    const t = treeProblem(s, catalog);
    if (t) report.sub(t.code, `.joints[${t.joint}].${t.field}`, t);
  }
  s.rails.forEach((r, k) => railProblems(r, `.rails[${k}]`, catalog, report));
  feedProblems(s, catalog, p);
  if (out.length === 0) overloadProblems(s, catalog, p);
  // Moved fixing points (fixingRules.ts), once the chain itself is sound.
  if (out.length === 0 && s.fixings !== undefined) {
    const f = Array.isArray(s.fixings) ? fixingProblem(s, s.fixings, catalog) : keyed({ code: 'fixing-order', index: 0, message: 'fixings must be a list of chain coordinates' }, 'fixingsNotList');
    if (f) report.sub(f.code, `.fixings[${f.index}]`, f);
  }
  return out;
}

/** Position and rotation, suspension range, mounting, and the head room under the modules. */
function hangingProblems(s: LightSystem, roomHeight: number, catalog: Catalog, p: ReportProblem): void {
  if (![s.x, s.z, s.rotation].every(Number.isFinite)) p('position', '', `system ${s.id} has a non-finite position or rotation`, { id: s.id }, 'systemPosition');
  else if (s.rotation < 0 || s.rotation >= 360) p('rotation', '.rotation', `rotation must be in [0, 360) degrees (got ${s.rotation})`, { value: s.rotation }, 'rotationRange');
  const susp = catalog.suspension;
  const inRange = Number.isFinite(s.suspension) && s.suspension >= susp.min - EPS && s.suspension <= susp.max + EPS;
  if (!inRange) p('suspension-range', '.suspension', `suspension must be between ${susp.min} and ${susp.max} m (got ${s.suspension})`, { min: susp.min, max: susp.max, value: s.suspension });
  if (!(MOUNTINGS as readonly string[]).includes(s.mounting)) p('mounting', '.mounting', `mounting must be ${MOUNTINGS.join(' or ')} (got ${String(s.mounting)})`, { value: String(s.mounting) }, 'mountingUnknown');
  else if ((inRange || s.mounting === 'surface') && roomHeight - photometricDrop(s, catalog) < susp.minHeightAboveFloor - EPS) {
    // Head room from where the modules really are: the suspension, or the surface mount's drop below the ceiling.
    const hang = fmt(roomHeight - photometricDrop(s, catalog));
    const surface = s.mounting === 'surface';
    const message = `modules would hang at ${hang} m${surface ? ' on the ceiling' : ''}, below the minimum ${susp.minHeightAboveFloor} m above the floor`;
    // The pendant wording keeps the rule's code as its key (coded before the surface mount's own).
    if (surface) p('suspension-floor', '.mounting', message, { hang: Number(hang), min: susp.minHeightAboveFloor }, 'suspensionFloorSurface');
    else p('suspension-floor', '.suspension', message, { hang: Number(hang), min: susp.minHeightAboveFloor });
  }
}

/** Rails present, one joint fewer than rails, each joint's connector known and its turn allowed. */
function jointProblems(s: LightSystem, catalog: Catalog, p: ReportProblem): void {
  if (s.rails.length === 0) p('no-rails', '.rails', `system ${s.id} has no rails`, { id: s.id }, 'noRails');
  if (s.joints.length !== Math.max(0, s.rails.length - 1))
    p('joint-count', '.joints', `${s.rails.length} rails need ${Math.max(0, s.rails.length - 1)} joints, found ${s.joints.length}`, { rails: s.rails.length, needed: Math.max(0, s.rails.length - 1), found: s.joints.length }, 'jointCount');
  s.joints.forEach((j, i) => {
    const con = catalog.connectors.find((c) => c.id === j.connector);
    if (!con) p('unknown-connector', `.joints[${i}].connector`, `unknown connector '${j.connector}'`, { id: j.connector }, 'unknownConnector');
    else if (!allowedTurn(con, j.turn)) {
      if (con.flex)
        p(
          'bad-turn',
          `.joints[${i}].turn`,
          `connector '${con.id}' turns by a multiple of ${con.flex.step}° within ±${con.flex.maxAngle}°, not ${j.turn}°`,
          { id: con.id, connectorId: con.id, step: con.flex.step, max: con.flex.maxAngle, turn: j.turn },
          'badTurnFlex',
        );
      else p('bad-turn', `.joints[${i}].turn`, `connector '${con.id}' turns by ±${con.angle}°, not ${j.turn}°`, { id: con.id, connectorId: con.id, angle: con.angle, turn: j.turn }, 'badTurn');
    }
  });
}

type Rail = LightSystem['rails'][number];

/** A rail's length (range, grid), its modules, and where they sit (free positions, or the distribution's fit). */
function railProblems(r: Rail, rp: string, catalog: Catalog, report: OwnReport): void {
  const { p, sub } = report;
  const rail = catalog.rail;
  if (!Number.isFinite(r.length) || r.length < rail.minLength - EPS || r.length > rail.maxLength + EPS) {
    p('rail-length-range', `${rp}.length`, `rail length must be between ${rail.minLength} and ${rail.maxLength} m (got ${r.length})`, { min: rail.minLength, max: rail.maxLength, value: r.length });
  } else if (!onGrid(r.length, rail.step)) p('rail-length-grid', `${rp}.length`, `rail length must be a multiple of ${rail.step} m (got ${r.length})`, { step: rail.step, value: r.length });
  let refsOk = true;
  r.modules.forEach((m, n) => {
    if (!moduleProblems(m, `${rp}.modules[${n}]`, catalog, report)) refsOk = false;
  });
  const free =
    refsOk && Number.isFinite(r.length) && isFreeRail(r)
      ? freeRailProblem(
          r,
          r.modules.map((m) => findModuleType(catalog, m.type).length),
        )
      : null;
  if (free) sub(free.code, `${rp}.modules[${free.index}].offset`, free);
  else if (refsOk && Number.isFinite(r.length) && !railModuleOffsets(r, catalog)) {
    p('modules-do-not-fit', `${rp}.modules`, `the modules of rail ${r.id} do not fit its ${fmt(r.length)} m with distribution '${r.distribution}'`, { rail: r.id, length: Number(fmt(r.length)), distribution: r.distribution });
  }
}

/** A module's type, beam, CCT, dimming, filter, aim and DMX patch; false when its type is unknown (nothing else is checked then). */
function moduleProblems(m: Rail['modules'][number], mp: string, catalog: Catalog, report: OwnReport): boolean {
  const { p, sub } = report;
  const type = catalog.moduleTypes.find((t) => t.id === m.type);
  if (!type) {
    p('unknown-module-type', `${mp}.type`, `unknown module type '${m.type}'`, { id: m.type }, 'unknownModuleType');
    return false;
  }
  const named = { name: type.name, typeId: type.id };
  if (!type.beams.some((b) => b.id === m.beam)) p('unknown-beam', `${mp}.beam`, `${type.name} has no beam '${m.beam}'`, { ...named, beam: m.beam }, 'unknownBeam');
  if (!type.ccts.includes(m.cct)) p('cct', `${mp}.cct`, `${type.name} is not available in ${m.cct} K (offered: ${type.ccts.join(', ')} K)`, { ...named, cct: String(m.cct), ccts: type.ccts.join(', ') }, 'cctNotOffered');
  if (!Number.isFinite(m.dimming) || m.dimming < 0 || m.dimming > 1) p('dimming', `${mp}.dimming`, `dimming must be between 0 and 1 (got ${m.dimming})`, { value: m.dimming }, 'dimmingRange');
  const filter = m.filter !== undefined ? moduleFilterProblem(type, m.filter, catalog) : null;
  if (filter) sub(filter.code, `${mp}.filter`, filter);
  const aim = m.aim !== undefined ? aimProblem(m.aim, type) : null;
  if (aim) sub(aim.field === 'aim' ? 'aim-fixed' : 'aim-range', `${mp}.${aim.field}`, aim);
  const patch = m.dmx ? patchRangeIssue(m.dmx, type) : null;
  if (patch) sub('dmx-range', `${mp}.dmx`, patch);
  return true;
}

/** Every feed whose load exceeds its driver. */
function overloadProblems(s: LightSystem, catalog: Catalog, p: ReportProblem): void {
  for (const l of feedLoads(s, catalog)) {
    if (isOverloaded(l))
      p(
        'feed-overload',
        `.feeds[${l.index}]`,
        `${feedLabel(l.index)} carries ${formatWatts(l.load)} W, more than its ${formatWatts(l.capacity)} W driver (${l.driver.name})`,
        { n: l.index + 1, load: Number(formatWatts(l.load)), capacity: Number(formatWatts(l.capacity)), driver: l.driver.name, driverId: l.driver.id },
        'feedCarries',
      );
  }
}
