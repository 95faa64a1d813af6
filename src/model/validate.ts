/**
 * Validity of a configuration, defined on the state alone (independent of the
 * actions that produced it). The always-valid guarantee is: validate() of any
 * state reachable through enabled actions is empty; the property test in
 * tests/model checks it.
 */
import { onGrid, type Catalog } from './catalogSchema';
import { ROOM_LIMITS, type Configuration, type LightSystem } from './configuration';
import { SURFACE_NAMES } from './lightingScene';
import { reflectanceProblem } from './reflectance';
import { rectCorners, rectsOverlap, systemElements, railModuleOffsets } from './geometry';

export interface Problem {
  /** Stable machine-readable code, e.g. 'outside-room'. */
  readonly code: string;
  /** One sentence for people. */
  readonly message: string;
  /** Where: e.g. 'systems[1].rails[0].modules[2].cct'. */
  readonly path: string;
}

/** Float noise allowed at walls and grids (a nanometre). */
const EPS = 1e-9;

export function validate(config: Configuration, catalog: Catalog): Problem[] {
  const problems: Problem[] = [...roomProblems(config), ...idProblems(config)];
  config.systems.forEach((_, i) => problems.push(...systemProblems(config, i, catalog)));
  return problems;
}

export function roomProblems(config: Configuration): Problem[] {
  const out: Problem[] = [];
  for (const key of ['width', 'depth', 'height'] as const) {
    const v = config.room[key];
    const { min, max } = ROOM_LIMITS[key];
    if (!Number.isFinite(v) || v < min || v > max) {
      out.push({ code: 'room-dimension', path: `room.${key}`, message: `room ${key} must be between ${min} and ${max} m (got ${v})` });
    }
  }
  const reflectance = (config.room.reflectance ?? {}) as Record<string, unknown>;
  for (const surface of SURFACE_NAMES) {
    const problem = reflectanceProblem(reflectance[surface]);
    if (problem) out.push({ code: 'reflectance', path: `room.reflectance.${surface}`, message: problem });
  }
  return out;
}

function idProblems(config: Configuration): Problem[] {
  const out: Problem[] = [];
  const seen = new Set<string>();
  const check = (id: string, path: string) => {
    if (seen.has(id)) out.push({ code: 'duplicate-id', path, message: `id '${id}' is used twice` });
    seen.add(id);
    const m = /^[a-z](\d+)$/.exec(id);
    if (m && Number(m[1]) >= config.nextId) out.push({ code: 'id-counter', path, message: `id '${id}' is not below nextId ${config.nextId}` });
  };
  config.systems.forEach((s, i) => {
    check(s.id, `systems[${i}].id`);
    s.rails.forEach((r, k) => {
      check(r.id, `systems[${i}].rails[${k}].id`);
      r.modules.forEach((m, n) => check(m.id, `systems[${i}].rails[${k}].modules[${n}].id`));
    });
  });
  return out;
}

/**
 * Problems of one system: its own rules, its fit in the room and clashes with
 * the other systems. Actions use this on their candidate state to give reasons.
 */
export function systemProblems(config: Configuration, index: number, catalog: Catalog): Problem[] {
  const s = config.systems[index];
  const at = `systems[${index}]`;
  const out = ownProblems(s, at, config.room.height, catalog);
  if (out.length > 0) return out; // geometry needs sound references and numbers
  const { width, depth } = config.room;
  const elements = systemElements(s, catalog);
  const outside = elements.flat().flatMap(rectCorners).some(([x, z]) => x < -EPS || x > width + EPS || z < -EPS || z > depth + EPS);
  if (outside) out.push({ code: 'outside-room', path: at, message: `system ${s.id} reaches outside the ${width} × ${depth} m room` });
  for (let a = 0; a < elements.length; a++) {
    // Neighbours in the chain touch by design; anything further apart must not overlap.
    for (let b = a + 3; b < elements.length; b++) {
      if (elements[a].some((ra) => elements[b].some((rb) => rectsOverlap(ra, rb)))) {
        out.push({ code: 'self-overlap', path: at, message: `system ${s.id} runs into itself` });
        a = elements.length;
        break;
      }
    }
  }
  const mine = elements.flat();
  config.systems.forEach((other, j) => {
    if (j === index || ownProblems(other, '', config.room.height, catalog).length > 0) return;
    const theirs = systemElements(other, catalog).flat();
    if (mine.some((ra) => theirs.some((rb) => rectsOverlap(ra, rb)))) {
      out.push({ code: 'system-overlap', path: at, message: `system ${s.id} overlaps system ${other.id}` });
    }
  });
  return out;
}

function ownProblems(s: LightSystem, at: string, roomHeight: number, catalog: Catalog): Problem[] {
  const out: Problem[] = [];
  const p = (code: string, path: string, message: string) => out.push({ code, path: `${at}${path}`, message });
  if (![s.x, s.z, s.rotation].every(Number.isFinite)) p('position', '', `system ${s.id} has a non-finite position or rotation`);
  else if (s.rotation < 0 || s.rotation >= 360) p('rotation', '.rotation', `rotation must be in [0, 360) degrees (got ${s.rotation})`);
  const susp = catalog.suspension;
  if (!Number.isFinite(s.suspension) || s.suspension < susp.min - EPS || s.suspension > susp.max + EPS) {
    p('suspension-range', '.suspension', `suspension must be between ${susp.min} and ${susp.max} m (got ${s.suspension})`);
  } else if (roomHeight - s.suspension < susp.minHeightAboveFloor - EPS) {
    p('suspension-floor', '.suspension', `modules would hang at ${fmt(roomHeight - s.suspension)} m, below the minimum ${susp.minHeightAboveFloor} m above the floor`);
  }
  if (s.rails.length === 0) p('no-rails', '.rails', `system ${s.id} has no rails`);
  if (s.joints.length !== Math.max(0, s.rails.length - 1)) p('joint-count', '.joints', `${s.rails.length} rails need ${Math.max(0, s.rails.length - 1)} joints, found ${s.joints.length}`);
  s.joints.forEach((j, i) => {
    const con = catalog.connectors.find((c) => c.id === j.connector);
    if (!con) p('unknown-connector', `.joints[${i}].connector`, `unknown connector '${j.connector}'`);
    else if (Math.abs(j.turn) !== con.angle) p('bad-turn', `.joints[${i}].turn`, `connector '${con.id}' turns by ±${con.angle}°, not ${j.turn}°`);
  });
  const rail = catalog.rail;
  s.rails.forEach((r, k) => {
    const rp = `.rails[${k}]`;
    if (!Number.isFinite(r.length) || r.length < rail.minLength - EPS || r.length > rail.maxLength + EPS) {
      p('rail-length-range', `${rp}.length`, `rail length must be between ${rail.minLength} and ${rail.maxLength} m (got ${r.length})`);
    } else if (!onGrid(r.length, rail.step)) p('rail-length-grid', `${rp}.length`, `rail length must be a multiple of ${rail.step} m (got ${r.length})`);
    let refsOk = true;
    r.modules.forEach((m, n) => {
      const mp = `${rp}.modules[${n}]`;
      const type = catalog.moduleTypes.find((t) => t.id === m.type);
      if (!type) {
        refsOk = false;
        p('unknown-module-type', `${mp}.type`, `unknown module type '${m.type}'`);
        return;
      }
      if (!type.beams.some((b) => b.id === m.beam)) p('unknown-beam', `${mp}.beam`, `${type.name} has no beam '${m.beam}'`);
      if (!type.ccts.includes(m.cct)) p('cct', `${mp}.cct`, `${type.name} is not available in ${m.cct} K (offered: ${type.ccts.join(', ')} K)`);
      if (!Number.isFinite(m.dimming) || m.dimming < 0 || m.dimming > 1) p('dimming', `${mp}.dimming`, `dimming must be within 0..1 (got ${m.dimming})`);
    });
    if (refsOk && Number.isFinite(r.length) && !railModuleOffsets(r, catalog)) {
      p('modules-do-not-fit', `${rp}.modules`, `the modules of rail ${r.id} do not fit its ${fmt(r.length)} m with distribution '${r.distribution}'`);
    }
  });
  return out;
}

function fmt(x: number): string {
  return String(Math.round(x * 1000) / 1000);
}
