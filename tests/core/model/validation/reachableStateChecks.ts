/**
 * What the always-valid property (alwaysValid.property.test.ts) checks on the state a random
 * sequence reached, beyond validate(): finite placements, aims within their limits, reflectances
 * the baker accepts, installable rail systems (feeds within their drivers, fixing points within the
 * mounting's rules, checked along the tree independently of fixingRules.ts), looks that name
 * existing modules; and the tallies that show each kind of step and state came up in bulk.
 */
import type { Configuration, LightSystem } from '../../../../src/core/model/configuration/configuration';
import type { LightingScene } from '../../../../src/core/model/lightingScene/lightingScene';
import { billOfMaterials } from '../../../../src/core/model/power/billOfMaterials';
import { MAX_REFLECTANCE, reflectanceRgb } from '../../../../src/core/model/lightingScene/reflectance';
import { toLightingScene } from '../../../../src/core/model/files/toLightingScene';
import { objectMesh } from '../../../../src/core/model/objects/objectGeometry';
import { chainCoordinates } from '../../../../src/core/model/rails/chainCoordinates';
import { feedLoads } from '../../../../src/core/model/power/feedLoads';
import { mountingRule, suspensionCoordinates } from '../../../../src/core/model/rails/suspensionPoints';
import { catalog } from '../helpers';

/**
 * The checks inside the property. Vitest's expect() copies its matcher state on every call, and a
 * sequence makes about a hundred checks after its steps: a plain comparison that throws an Error
 * naming the check and its values (fast-check reports it with the failing sequence) keeps every
 * check at a fraction of the cost (docs/benchmarks.md, "Test suite time").
 */
export function holds(ok: boolean, what: string, ...values: unknown[]): void {
  if (!ok) throw new Error(`${what}: ${values.map((v) => JSON.stringify(v)).join(', ')}`);
}

/** Counters of the steps taken and refused and of what the reached states held, by kind. */
export function newTallies() {
  return {
    counts: { enabled: 0, refused: 0 },
    finishes: { enabled: 0, refused: 0 },
    objects: { enabled: 0, refused: 0 },
    power: { enabled: 0, refused: 0, overloads: 0, surface: 0 },
    free: { moves: 0, refusedMoves: 0, splits: 0, removals: 0, freeRails: 0 },
    shape: { turns: 0, refusedTurns: 0, fixingMoves: 0, refusedFixingMoves: 0, movedSystems: 0, turned: 0 },
    trees: { branches: 0, refusedBranches: 0, connectorChanges: 0, branched: 0, tees: 0, crosses: 0, maxPieces: 0 },
    aims: { enabled: 0, refused: 0, aimed: 0 },
    scenes: { enabled: 0, refused: 0, recalls: 0, looks: 0 },
    placed: 0,
  };
}
export type Tallies = ReturnType<typeof newTallies>;

/** Derived outputs of a reachable state are finite; every aim lies within its type's limits and on its stops (validate() says why otherwise). */
function checkPlacementsAndAims(s: Configuration, scene: LightingScene, t: Tallies): void {
  for (const l of scene.luminaires) holds([...l.position, l.yaw, l.pitch, l.roll].every(Number.isFinite), 'luminaire placement is finite', l.id);
  // every aim of a reachable state lies within its type's limits and on its stops (validate() says why otherwise)
  for (const m of s.systems.flatMap((x) => x.rails.flatMap((r) => r.modules))) {
    if (!m.aim) continue;
    t.aims.aimed++;
    const lim = catalog.moduleTypes.find((t) => t.id === m.type)!.adjustable!;
    holds(m.aim.tilt >= lim.tilt.min, 'tilt ≥ its minimum', m.id, m.aim.tilt, lim.tilt.min);
    holds(m.aim.tilt <= lim.tilt.max, 'tilt ≤ its maximum', m.id, m.aim.tilt, lim.tilt.max);
    holds(m.aim.rotation >= lim.rotation.min, 'rotation ≥ its minimum', m.id, m.aim.rotation, lim.rotation.min);
    holds(m.aim.rotation <= lim.rotation.max, 'rotation ≤ its maximum', m.id, m.aim.rotation, lim.rotation.max);
  }
  for (const r of Object.values(scene.room.reflectance))
    holds(
      reflectanceRgb(r).every((v) => v >= 0 && v <= MAX_REFLECTANCE),
      'reflectance within 0…MAX_REFLECTANCE',
      r,
    );
  holds(Number.isFinite(billOfMaterials(s, catalog).total), 'the bill of materials has a finite total');
}

/**
 * Installable by construction: every feed within its driver, the load all assigned, and the
 * fixing points (derived or moved) within the mounting's rules (first and last within the
 * overhang of the chain ends, no gap above the spacing, one at every connector); moved
 * points are judged to FIXING_EPS (a micrometre), derived ones hold to float noise.
 */
function checkInstallable(sys: LightSystem, t: Tallies): void {
  const loads = feedLoads(sys, catalog);
  for (const l of loads) holds(l.load <= l.capacity + 1e-6, 'a feed within its driver', sys.id, l.index, l.load, l.capacity);
  const watts = sys.rails.flatMap((r) => r.modules).reduce((a, m) => a + catalog.moduleTypes.find((x) => x.id === m.type)!.beams.find((b) => b.id === m.beam)!.watts, 0);
  // toBeCloseTo(watts, 6): within half a microwatt
  const assigned = loads.reduce((a, l) => a + l.load, 0);
  holds(Math.abs(assigned - watts) < 10 ** -6 / 2, 'the feeds carry every module', sys.id, assigned, watts);
  const rule = mountingRule(sys, catalog);
  const chain = chainCoordinates(sys, catalog);
  const pts = suspensionCoordinates(sys, catalog).map((q) => q.s);
  const tol = sys.fixings ? 1e-6 : 1e-9;
  if (sys.fixings) t.shape.movedSystems++;
  if (sys.joints.some((j) => j.turn !== 0 && Math.abs(j.turn) !== 90)) t.shape.turned++;
  // Per rail, along the tree (independent of fixingRules.ts): the supports in order are the
  // node it hangs on, the points on it, and the node at its end; a free end (the chain start,
  // any rail end without a connector) overhangs its outermost support by at most maxOverhang.
  const nodeOf = (p: number) => pts.findIndex((q) => Math.abs(q - chain.nodeAt[p]) < tol);
  for (let p = 0; p < sys.rails.length; p++) if (!Number.isNaN(chain.nodeAt[p])) holds(nodeOf(p) >= 0, 'a fixing point at every connector node', sys.id, p);
  for (let k = 1; k < pts.length; k++) holds(pts[k] - pts[k - 1] > 0, 'fixing points in increasing order', sys.id, pts);
  const covered = new Set<number>();
  sys.rails.forEach((r, i) => {
    const u0 = chain.railStart[i];
    const on = pts.flatMap((q, k) => (q >= u0 - tol && q <= u0 + r.length + tol ? [k] : []));
    on.forEach((k) => covered.add(k));
    const depths = on.map((k) => chain.depthStart[i] + pts[k] - u0);
    const p = chain.parent[i];
    const startSupport = p >= 0 ? [chain.nodeDepth[p]] : [];
    const endSupport = Number.isNaN(chain.nodeAt[i]) ? [] : [chain.nodeDepth[i]];
    const seq = [...startSupport, ...depths, ...endSupport];
    for (let k = 1; k < seq.length; k++) holds(seq[k] - seq[k - 1] <= rule.spacing + tol, 'supports within the spacing', sys.id, i, seq, rule.spacing);
    if (p < 0) holds(seq[0] - chain.depthStart[i] <= rule.maxOverhang + tol, 'chain start within the overhang', sys.id, seq, rule.maxOverhang);
    if (endSupport.length === 0) holds(chain.depthStart[i] + r.length - seq[seq.length - 1] <= rule.maxOverhang + tol, 'free rail end within the overhang', sys.id, i, seq, rule.maxOverhang);
  });
  // Every point is on a rail or at a connector node.
  pts.forEach((q, k) => holds(covered.has(k) || chain.nodeAt.some((at) => Math.abs(at - q) < tol), 'every fixing point on a rail or at a node', sys.id, q));
  if (sys.joints.some((j, k) => (j.parent ?? k) !== k)) t.trees.branched++;
  t.trees.tees += sys.joints.filter((j) => j.connector === 'tee').length;
  t.trees.crosses += sys.joints.filter((j) => j.connector === 'cross').length;
  if (sys.mounting === 'surface') t.power.surface++;
  t.free.freeRails += sys.rails.filter((r) => r.modules.some((m) => m.offset !== undefined)).length;
}

/** Every look of the light scenes names a module that exists (removals pruned them); every object has a finite placement and a mesh whose reflectances the baker accepts. */
function checkLooksAndObjects(s: Configuration, scene: LightingScene, t: Tallies): void {
  const ids = new Set(s.systems.flatMap((x) => x.rails.flatMap((r) => r.modules.map((m) => m.id))));
  for (const q of s.lightScenes ?? []) {
    for (const id of Object.keys(q.looks)) holds(ids.has(id), 'a look names an existing module', q.id, id);
    t.scenes.looks += Object.keys(q.looks).length;
  }
  t.placed += s.objects.length;
  for (const o of scene.objects ?? []) holds([...o.position, o.yaw, o.scale].every(Number.isFinite), 'object placement is finite', o.id);
  for (const o of s.objects)
    holds(
      objectMesh(s, o.id).materials.every((m) => m.reflectance.every((c) => c >= 0 && c < 1)),
      'object reflectances within [0, 1)',
      o.id,
    );
}

/** The checks on the state a sequence reached, in the order the property has always made them. */
export function checkReachableState(s: Configuration, t: Tallies): void {
  const scene = toLightingScene(s, catalog);
  checkPlacementsAndAims(s, scene, t);
  for (const sys of s.systems) checkInstallable(sys, t);
  checkLooksAndObjects(s, scene, t);
}
