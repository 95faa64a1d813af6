/**
 * Validity of a configuration, defined on the state alone (independent of the
 * actions that produced it). The always-valid guarantee is: validate() of any
 * state reachable through enabled actions is empty; the property test in
 * tests/core/model checks it.
 */
import { aimProblem } from '../modules/aim';
import { keyed, type Keyed } from '../configuration/coding';
import { feedAtParam } from '../power/feedLoads';
import { allowedTurn, findModuleType, onGrid, type Catalog } from '../catalogSchema/catalogSchema';
import { fixingProblem } from '../rails/fixingRules';
import { moduleFilterProblem } from '../modules/moduleFilter';
import { freeRailProblem, isFreeRail } from '../rails/freePositions';
import { MOUNTINGS, ROOM_LIMITS, withinRoomLimits, type Configuration, type LightSystem } from '../configuration/configuration';
import { describeFeedAt, feedLabel, feedLoads, formatWatts, isOverloaded } from '../power/feedLoads';
import { photometricDrop } from '../rails/suspensionPoints';
import { SURFACE_NAMES } from '../lightingScene/lightingScene';
import { firstPatchOverlap, formatPatchRange, patchRangeIssue } from '../modules/dmxPatch';
import { allObjectProblems } from '../objects/objectProblems';
import { lightSceneProblems } from '../cues/lightScenes';
import { reflectanceProblem } from '../lightingScene/reflectance';
import { rectCorners, rectsOverlap, systemElementTree, railModuleOffsets, type PlanRect, type SystemElementTree } from '../rails/geometry';
import { firstNodeJoints, jointParent, treeProblem } from '../rails/railTree';
import { perCatalog } from '../catalogSchema/perCatalog';
import type { Problem } from '../configuration/problem';

/** Float noise allowed at walls and grids (a nanometre). */
const EPS = 1e-9;

export interface ValidateOptions {
  /**
   * Stop at the first stage that finds a problem (room, ids, each system's own
   * rules, room bounds, self-crossing, overlaps between systems) and, in the
   * pair stages, at the first clash: what readers of untrusted files need (they
   * report one problem), so a cheap problem is never hidden behind pair checks.
   */
  firstOnly?: boolean;
  /** Counts the exact (separating-axis) rectangle tests, for tests of the broad phase. */
  stats?: { pairTests: number };
}

/**
 * All problems of a configuration, in a stable order: room, ids, then per
 * system its own rules or else its geometry (outside, self-overlap, clashes
 * with other systems). Pair checks use a uniform grid over the plan, so a hall
 * with hundreds of rails costs O(n) exact rectangle tests, not O(n²).
 */
export function validate(config: Configuration, catalog: Catalog, options: ValidateOptions = {}): Problem[] {
  const first = options.firstOnly === true;
  const stats = options.stats ?? { pairTests: 0 };
  const problems: Problem[] = roomProblems(config);
  if (first && problems.length > 0) return problems;
  problems.push(...idProblems(config));
  if (first && problems.length > 0) return problems;
  problems.push(...patchProblems(config));
  if (first && problems.length > 0) return problems;
  problems.push(...lightSceneProblems(config));
  if (first && problems.length > 0) return problems;
  const n = config.systems.length;
  const own = config.systems.map((s, i) => ownProblems(s, `systems[${i}]`, config.room.height, catalog));
  if (first) {
    const bad = own.find((p) => p.length > 0);
    if (bad) return [...problems, ...bad];
  }
  // Geometry only for systems whose own rules hold (it needs sound references and numbers).
  const trees: (SystemElementTree | null)[] = config.systems.map((s, i) => (own[i].length === 0 ? systemElementTree(s, catalog) : null));
  const elements = trees.map((t) => t?.elements ?? null);
  const outside = config.systems.map((s, i) => {
    const el = elements[i];
    return el !== null && outsideRoom(el, config.room.width, config.room.depth) ? outsideProblem(s, i, config.room) : null;
  });
  if (first) {
    const out = outside.find((p) => p !== null);
    if (out) return [...problems, out];
  }
  // One grid over every element of every sound system: self-crossings (same
  // system, elements that do not touch by design: SystemElementTree.near) and clashes between systems.
  const rects: PlanRect[] = [];
  const owner: number[] = [];
  const chainIndex: number[] = [];
  elements.forEach((el, i) => el?.forEach((group, a) => group.forEach((r) => (rects.push(r), owner.push(i), chainIndex.push(a)))));
  const selfCrossing = new Set<number>();
  const clashes = Array.from({ length: n }, () => new Set<number>());
  forEachOverlap(rects, stats, (p, q) => {
    const [i, j] = [owner[p], owner[q]];
    if (i === j) {
      if (trees[i]!.near[chainIndex[p]].has(chainIndex[q]) || selfCrossing.has(i)) return 'skip';
      selfCrossing.add(i);
    } else {
      if (clashes[i].has(j)) return 'skip';
      clashes[i].add(j);
      clashes[j].add(i);
    }
    return first ? 'stop' : 'continue';
  }, (p, q) => {
    // Cheap pre-filter: pairs whose answer is already known need no exact test.
    const [i, j] = [owner[p], owner[q]];
    return i === j ? !trees[i]!.near[chainIndex[p]].has(chainIndex[q]) && !selfCrossing.has(i) : !clashes[i].has(j);
  });
  config.systems.forEach((s, i) => {
    if (own[i].length > 0) return problems.push(...own[i]);
    const at = `systems[${i}]`;
    if (outside[i]) problems.push(outside[i]);
    if (selfCrossing.has(i)) problems.push({ code: 'self-overlap', path: at, message: `system ${s.id} runs into itself`, params: { id: s.id } });
    [...clashes[i]].sort((a, b) => a - b).forEach((j) => problems.push({ code: 'system-overlap', path: at, message: `system ${s.id} overlaps system ${config.systems[j].id}`, params: { id: s.id, other: config.systems[j].id } }));
  });
  if (first && problems.length > 0) return problems;
  // Objects last: they never clash with systems or each other (overlapping furniture is the user's business).
  problems.push(...allObjectProblems(config, first));
  return problems;
}

function outsideRoom(elements: PlanRect[][], width: number, depth: number): boolean {
  // "Not inside" rather than "outside": a NaN corner fails every comparison and must count as outside (issue 32).
  return elements.flat().flatMap(rectCorners).some(([x, z]) => !(x >= -EPS && x <= width + EPS && z >= -EPS && z <= depth + EPS));
}

function outsideProblem(s: LightSystem, index: number, room: Configuration['room']): Problem {
  return { code: 'outside-room', path: `systems[${index}]`, message: `system ${s.id} reaches outside the ${room.width} × ${room.depth} m room`, params: { id: s.id, width: room.width, depth: room.depth } };
}

interface Box {
  minX: number;
  minZ: number;
  maxX: number;
  maxZ: number;
}

function boxOf(r: PlanRect): Box {
  const c = rectCorners(r);
  const xs = c.map((p) => p[0]);
  const zs = c.map((p) => p[1]);
  return { minX: Math.min(...xs), minZ: Math.min(...zs), maxX: Math.max(...xs), maxZ: Math.max(...zs) };
}

/** Grid cell edge, metres: about a rail's length, so an element covers a few cells. */
const CELL = 1;
/** Elements spanning more cells than this per axis (a hostile catalog's 1 km rail) are tested against all. */
const MAX_CELLS_PER_AXIS = 64;

/**
 * Calls `found(p, q)` for every pair of rectangles that overlap (rectsOverlap),
 * each pair once, after `wanted(p, q)` says the pair still matters. Broad phase:
 * a uniform grid of CELL-metre cells; a pair is examined only in the first
 * cell both boxes share. Boxes that merely touch are never candidates, which is
 * exact: touching or separated boxes mean separated or touching rectangles,
 * and rectsOverlap calls touching rectangles disjoint.
 */
export function forEachOverlap(
  rects: readonly PlanRect[],
  stats: { pairTests: number },
  found: (p: number, q: number) => 'continue' | 'skip' | 'stop',
  wanted: (p: number, q: number) => boolean = () => true,
): void {
  const boxes = rects.map(boxOf);
  const cells = new Map<string, number[]>();
  const oversize: number[] = [];
  const range = (b: Box) => [Math.floor(b.minX / CELL), Math.floor(b.maxX / CELL), Math.floor(b.minZ / CELL), Math.floor(b.maxZ / CELL)];
  boxes.forEach((b, p) => {
    const [x0, x1, z0, z1] = range(b);
    if (!(x1 - x0 <= MAX_CELLS_PER_AXIS && z1 - z0 <= MAX_CELLS_PER_AXIS)) return oversize.push(p);
    for (let x = x0; x <= x1; x++) {
      for (let z = z0; z <= z1; z++) {
        const key = `${x},${z}`;
        const list = cells.get(key);
        if (list) list.push(p);
        else cells.set(key, [p]);
      }
    }
  });
  const test = (p: number, q: number): boolean => {
    const a = boxes[p];
    const b = boxes[q];
    if (a.minX >= b.maxX || b.minX >= a.maxX || a.minZ >= b.maxZ || b.minZ >= a.maxZ) return true;
    const [lo, hi] = p < q ? [p, q] : [q, p];
    if (!wanted(lo, hi)) return true;
    stats.pairTests++;
    return !rectsOverlap(rects[lo], rects[hi]) || found(lo, hi) !== 'stop';
  };
  for (const [key, list] of cells) {
    const [cx, cz] = key.split(',').map(Number);
    for (let u = 0; u < list.length; u++) {
      for (let v = u + 1; v < list.length; v++) {
        const [a, b] = [boxes[list[u]], boxes[list[v]]];
        // Examine the pair only in the first cell both boxes cover.
        if (Math.max(Math.floor(a.minX / CELL), Math.floor(b.minX / CELL)) !== cx || Math.max(Math.floor(a.minZ / CELL), Math.floor(b.minZ / CELL)) !== cz) continue;
        if (!test(list[u], list[v])) return;
      }
    }
  }
  const isOversize = new Set(oversize);
  for (const p of oversize) {
    for (let q = 0; q < rects.length; q++) {
      if (q === p || (isOversize.has(q) && q < p)) continue;
      if (!test(p, q)) return;
    }
  }
}

export function roomProblems(config: Configuration): Problem[] {
  const out: Problem[] = [];
  for (const key of ['width', 'depth', 'height'] as const) {
    const v = config.room[key];
    if (!withinRoomLimits(key, v)) {
      const { min, max } = ROOM_LIMITS[key];
      out.push(keyed({ code: 'room-dimension', path: `room.${key}`, message: `room ${key} must be between ${min} and ${max} m (got ${v})`, params: { dimension: key, min, max, value: v } }, ROOM_KEYS[key]));
    }
  }
  const reflectance = (config.room.reflectance ?? {}) as Record<string, unknown>;
  for (const surface of SURFACE_NAMES) {
    const problem = reflectanceProblem(reflectance[surface]);
    if (problem) out.push(subProblem('reflectance', `room.reflectance.${surface}`, problem));
  }
  return out;
}

export function idProblems(config: Configuration): Problem[] {
  const out: Problem[] = [];
  const seen = new Set<string>();
  const check = (id: string, path: string) => {
    if (seen.has(id)) out.push(keyed({ code: 'duplicate-id', path, message: `id '${id}' is used twice` }, 'duplicateId', { id }));
    seen.add(id);
    const m = /^[a-z](\d+)$/.exec(id);
    if (m && Number(m[1]) >= config.nextId) out.push(keyed({ code: 'id-counter', path, message: `id '${id}' is not below nextId ${config.nextId}` }, 'idCounter', { id, next: config.nextId }));
  };
  config.objects.forEach((o, i) => check(o.id, `objects[${i}].id`));
  (config.lightScenes ?? []).forEach((s, i) => check(s.id, `lightScenes[${i}].id`));
  Object.keys(config.importedMeshes).forEach((id) => check(id, `importedMeshes.${id}`));
  config.systems.forEach((s, i) => {
    check(s.id, `systems[${i}].id`);
    s.feeds.forEach((f, k) => check(f.id, `systems[${i}].feeds[${k}].id`));
    s.rails.forEach((r, k) => {
      check(r.id, `systems[${i}].rails[${k}].id`);
      r.modules.forEach((m, n) => check(m.id, `systems[${i}].rails[${k}].modules[${n}].id`));
    });
  });
  return out;
}

/**
 * Channels shared by two patched modules (one problem: the first overlap, on the
 * later module in module order). Each patch's own ranges are a module rule
 * (ownProblems); this is the one rule across systems besides clashes.
 */
export function patchProblems(config: Configuration): Problem[] {
  const hit = firstPatchOverlap(config);
  if (!hit) return [];
  const { at, other } = hit;
  return [keyed({ code: 'dmx-overlap', path: `${at.path}.dmx`, message: `DMX ${formatPatchRange(at.patch)} of module ${at.module.id} overlaps module ${other.module.id} (${formatPatchRange(other.patch)})` }, 'dmxOverlap', { range: formatPatchRange(at.patch), id: at.module.id, other: other.module.id, otherRange: formatPatchRange(other.patch) })];
}

/**
 * Problems of one system: its own rules, its fit in the room and clashes with
 * the other systems. The action binding (validateResult.ts) and the preset
 * placement search check only the systems a change touched with it.
 */
export function systemProblems(config: Configuration, index: number, catalog: Catalog): Problem[] {
  const s = config.systems[index];
  const at = `systems[${index}]`;
  const out = ownProblems(s, at, config.room.height, catalog);
  if (out.length > 0) return out; // geometry needs sound references and numbers
  const tree = systemElementTree(s, catalog);
  const elements = tree.elements;
  if (outsideRoom(elements, config.room.width, config.room.depth)) out.push(outsideProblem(s, index, config.room));
  if (crossesItself(tree)) out.push({ code: 'self-overlap', path: at, message: `system ${s.id} runs into itself`, params: { id: s.id } });
  const mine = footprintOf(s, catalog);
  config.systems.forEach((other, j) => {
    if (j !== index && clashes(mine, other, config.room.height, catalog)) {
      out.push({ code: 'system-overlap', path: at, message: `system ${s.id} overlaps system ${other.id}`, params: { id: s.id, other: other.id } });
    }
  });
  return out;
}

/** A system's own rules, with paths relative to the system ('.rails[0].length'): the part of systemProblems that does not depend on where it stands, but for a finite x and z. */
export function systemOwnProblems(s: LightSystem, roomHeight: number, catalog: Catalog): Problem[] {
  return ownProblems(s, '', roomHeight, catalog);
}

/**
 * Whether systemProblems(config, index, catalog) would be empty, for a system whose own rules
 * (systemOwnProblems) the caller already knows to hold and whose x and z are finite: the preset
 * placement search tries up to 1 600 spots of one system, and stops at the first problem, the
 * cheap ones first (room bounds, clashes by bounding boxes, then self-crossing).
 */
export function systemFitsAt(config: Configuration, index: number, catalog: Catalog): boolean {
  const s = config.systems[index];
  const tree = systemElementTree(s, catalog);
  if (outsideRoom(tree.elements, config.room.width, config.room.depth)) return false;
  const mine = footprintOf(s, catalog);
  if (config.systems.some((other, j) => j !== index && clashes(mine, other, config.room.height, catalog))) return false;
  return !crossesItself(tree);
}

/** Neighbours in the tree touch by design; anything further apart must not overlap. */
function crossesItself(tree: SystemElementTree): boolean {
  const rects = tree.elements.flat();
  const chainIndex = tree.elements.flatMap((group, a) => group.map(() => a));
  let crosses = false;
  forEachOverlap(rects, { pairTests: 0 }, () => ((crosses = true), 'stop'), (p, q) => !tree.near[chainIndex[p]].has(chainIndex[q]));
  return crosses;
}

interface Footprint {
  readonly rects: readonly PlanRect[];
  readonly boxes: readonly Box[];
  /** The union of the boxes. */
  readonly box: Box;
}

/** A sound system's rectangles and their boxes, once per system object (perCatalog.ts). */
const footprintOf = perCatalog((s: LightSystem, catalog: Catalog): Footprint => {
  const rects = systemElementTree(s, catalog).elements.flat();
  const boxes = rects.map(boxOf);
  const box = boxes.reduce((u, b) => ({ minX: Math.min(u.minX, b.minX), minZ: Math.min(u.minZ, b.minZ), maxX: Math.max(u.maxX, b.maxX), maxZ: Math.max(u.maxZ, b.maxZ) }), { minX: Infinity, minZ: Infinity, maxX: -Infinity, maxZ: -Infinity });
  return { rects, boxes, box };
});

const boxesMeet = (a: Box, b: Box) => a.minX < b.maxX && b.minX < a.maxX && a.minZ < b.maxZ && b.minZ < a.maxZ;

/** Whether a sound system's footprint overlaps `other`'s (none when other breaks its own rules: it has no geometry to clash with). */
function clashes(mine: Footprint, other: LightSystem, roomHeight: number, catalog: Catalog): boolean {
  if (ownProblems(other, '', roomHeight, catalog).length > 0) return false;
  const theirs = footprintOf(other, catalog);
  if (!boxesMeet(mine.box, theirs.box)) return false;
  // Only their rectangles whose boxes meet my whole footprint's box, then pair by pair: boxes first, then the exact test.
  const near = theirs.rects.flatMap((rb, q) => (boxesMeet(theirs.boxes[q], mine.box) ? [q] : []));
  return mine.rects.some((ra, p) => near.some((q) => boxesMeet(mine.boxes[p], theirs.boxes[q]) && rectsOverlap(ra, theirs.rects[q])));
}

/**
 * A system's own problems, worked out once per system object, catalog and room height
 * (perCatalog.ts) with paths relative to the system: validate() after every action, and the clash
 * checks against every other system, ask again for the systems the action left alone.
 */
const ownByHeight = perCatalog((_s: LightSystem) => new Map<number, readonly Problem[]>());

function ownProblems(s: LightSystem, at: string, roomHeight: number, catalog: Catalog): Problem[] {
  const known = ownByHeight(s, catalog);
  let list = known.get(roomHeight);
  if (!list) known.set(roomHeight, (list = computeOwnProblems(s, roomHeight, catalog)));
  return list.map((q) => ({ ...q, path: `${at}${q.path}` }));
}

function computeOwnProblems(s: LightSystem, roomHeight: number, catalog: Catalog): Problem[] {
  const at = '';
  const out: Problem[] = [];
  // `key`: the sentence's own code where the rule has several (docs/i18n.md); its params then travel non-enumerable.
  const p = (code: string, path: string, message: string, params?: Record<string, string | number>, key?: string) =>
    out.push(key ? keyed({ code, path: `${at}${path}`, message }, key, params) : { code, path: `${at}${path}`, message, ...(params ? { params } : {}) });
  // A sub-rule's problem (fixing points, free positions, the tree, aim, filter, patch) with its own coding.
  const sub = (code: string, path: string, found: { message: string } & Keyed) => p(code, path, found.message, found.params, found.key);
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
  if (out.length === 0) {
    // The tree (railTree.ts): parents before children, one connector per node, its ports.
    const t = treeProblem(s, catalog);
    if (t) sub(t.code, `.joints[${t.joint}].${t.field}`, t);
  }
  const rail = catalog.rail;
  s.rails.forEach((r, k) => {
    const rp = `.rails[${k}]`;
    if (!Number.isFinite(r.length) || r.length < rail.minLength - EPS || r.length > rail.maxLength + EPS) {
      p('rail-length-range', `${rp}.length`, `rail length must be between ${rail.minLength} and ${rail.maxLength} m (got ${r.length})`, { min: rail.minLength, max: rail.maxLength, value: r.length });
    } else if (!onGrid(r.length, rail.step)) p('rail-length-grid', `${rp}.length`, `rail length must be a multiple of ${rail.step} m (got ${r.length})`, { step: rail.step, value: r.length });
    let refsOk = true;
    r.modules.forEach((m, n) => {
      const mp = `${rp}.modules[${n}]`;
      const type = catalog.moduleTypes.find((t) => t.id === m.type);
      if (!type) {
        refsOk = false;
        p('unknown-module-type', `${mp}.type`, `unknown module type '${m.type}'`, { id: m.type }, 'unknownModuleType');
        return;
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
    });
    const free = refsOk && Number.isFinite(r.length) && isFreeRail(r) ? freeRailProblem(r, r.modules.map((m) => findModuleType(catalog, m.type).length)) : null;
    if (free) sub(free.code, `${rp}.modules[${free.index}].offset`, free);
    else if (refsOk && Number.isFinite(r.length) && !railModuleOffsets(r, catalog)) {
      p('modules-do-not-fit', `${rp}.modules`, `the modules of rail ${r.id} do not fit its ${fmt(r.length)} m with distribution '${r.distribution}'`, { rail: r.id, length: Number(fmt(r.length)), distribution: r.distribution });
    }
  });
  feedProblems(s, catalog, p);
  if (out.length === 0) {
    for (const l of feedLoads(s, catalog)) {
      if (isOverloaded(l)) p('feed-overload', `.feeds[${l.index}]`, `${feedLabel(l.index)} carries ${formatWatts(l.load)} W, more than its ${formatWatts(l.capacity)} W driver (${l.driver.name})`, { n: l.index + 1, load: Number(formatWatts(l.load)), capacity: Number(formatWatts(l.capacity)), driver: l.driver.name, driverId: l.driver.id }, 'feedCarries');
    }
  }
  // Moved fixing points (fixingRules.ts), once the chain itself is sound.
  if (out.length === 0 && s.fixings !== undefined) {
    const f = Array.isArray(s.fixings) ? fixingProblem(s, s.fixings, catalog) : keyed({ code: 'fixing-order', index: 0, message: 'fixings must be a list of chain coordinates' }, 'fixingsNotList');
    if (f) sub(f.code, `.fixings[${f.index}]`, f);
  }
  return out;
}

/** A system's feeds: at least one, known drivers, positions the catalog allows on this chain, no two at one spot. */
function feedProblems(s: LightSystem, catalog: Catalog, p: (code: string, path: string, message: string, params?: Record<string, string | number>, key?: string) => void): void {
  if (s.feeds.length === 0) p('no-feed', '.feeds', `system ${s.id} has no power feed`, { id: s.id }, 'noFeed');
  // First feed at each position, keyed 'start' / 'end' / 'joint:k': one pass, even for a hostile file's thousands of feeds.
  const firstJoint = firstNodeJoints(s);
  const first = new Map<string, number>();
  s.feeds.forEach((f, k) => {
    const fp = `.feeds[${k}]`;
    if (!catalog.drivers.some((d) => d.id === f.driver)) p('unknown-driver', `${fp}.driver`, `unknown driver '${f.driver}'`, { id: f.driver }, 'unknownDriver');
    const at = f.at;
    if (typeof at === 'object' && 'joint' in at) {
      if (!catalog.feed.positions.includes('joints')) p('feed-position', `${fp}.at`, `${catalog.name} feeds only at the chain ends, not at connectors`, { catalog: catalog.name }, 'feedOnlyAtEnds');
      else if (!Number.isInteger(at.joint) || at.joint < 0 || at.joint >= s.joints.length) p('feed-position', `${fp}.at`, `${feedLabel(k)} is at connector ${at.joint + 1}, but the chain has ${s.joints.length} connector${s.joints.length === 1 ? '' : 's'}`, { n: k + 1, joint: at.joint + 1, count: s.joints.length }, 'feedAtMissingConnector');
    } else if (typeof at === 'object' && 'end' in at) {
      if (!Number.isInteger(at.end) || at.end < 0 || at.end >= s.rails.length) p('feed-position', `${fp}.at`, `${feedLabel(k)} is at the end of rail ${at.end + 1}, but the system has ${s.rails.length} rail${s.rails.length === 1 ? '' : 's'}`, { n: k + 1, rail: at.end + 1, count: s.rails.length }, 'feedAtMissingRail');
      else if (firstJoint[at.end] !== undefined) p('feed-position', `${fp}.at`, `${feedLabel(k)} is at the end of rail ${at.end + 1}, but a connector sits there (feed at the connector instead)`, { n: k + 1, rail: at.end + 1 }, 'feedAtRailEndConnector');
    } else if (at !== 'start' && at !== 'end') p('feed-position', `${fp}.at`, `a feed sits at 'start', 'end', { joint: k } or { end: i } (got ${String(at)})`, { value: String(at) }, 'feedPositionUnknown');
    // One key per physical position: the joints of one node share it, and 'end' is the last rail's end.
    const key = typeof at !== 'object' ? (at === 'end' ? `end:${s.rails.length - 1}` : String(at)) : 'joint' in at ? `node:${s.joints[at.joint] ? jointParent(s.joints[at.joint], at.joint) : `?${at.joint}`}` : `end:${at.end}`;
    const twin = first.get(key);
    if (twin === undefined) first.set(key, k);
    else p('feed-duplicate', `${fp}.at`, `${feedLabel(twin)} and ${feedLabel(k)} both sit at ${describeFeedAt(f.at)}`, { n: twin + 1, other: k + 1, feedAt: feedAtParam(f.at) }, 'feedsBothAt');
  });
}

function fmt(x: number): string {
  return String(Math.round(x * 1000) / 1000);
}

/** The sentence key of each room dimension's range problem. */
const ROOM_KEYS = { width: 'roomWidthRange', depth: 'roomDepthRange', height: 'roomHeightRange' } as const;

/** A problem whose sentence a sub-rule wrote, with that rule's coding (reflectance.ts …). */
function subProblem(code: string, path: string, found: string | ({ message: string } & Keyed)): Problem {
  if (typeof found === 'string') return { code, path, message: found };
  return found.key ? keyed({ code, path, message: found.message }, found.key, found.params) : { code, path, message: found.message };
}
