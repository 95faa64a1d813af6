/**
 * The always-valid property (configurator paper §3.2): from any valid state, an enabled
 * action leads to a valid state, and a refused action, performed anyway,
 * either throws or leads to a state validate() rejects. Random sequences over
 * every action — rails (removed at any index: splits; flexible connectors turned; fixing points moved),
 * modules (moved to free positions; aimed, in and out of their limits), patches,
 * finishes and objects (furniture, imported meshes) mixed —
 * seeded so failures reproduce.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { bindAction } from '../../../../src/core/model/actions/actionDefinitions';
import { billOfMaterials } from '../../../../src/core/model/power/billOfMaterials';
import { createConfiguration, type Configuration } from '../../../../src/core/model/configuration/configuration';
import { DISTRIBUTIONS } from '../../../../src/core/model/catalogSchema/railSystemSchema';
import { MAX_REFLECTANCE, SURFACE_TARGETS, reflectanceRgb } from '../../../../src/core/model/lightingScene/reflectance';
import { toLightingScene } from '../../../../src/core/model/files/toLightingScene';
import { validate } from '../../../../src/core/model/validation/validate';
import { FURNITURE_LIBRARY } from '../../../../src/core/model/objects/furniture/furnitureLibrary';
import { boxPart, composeParts, frustumPart } from '../../../../src/core/model/objects/furniture/meshParts';
import { OBJECT_FINISHES } from '../../../../src/core/model/objects/furniture/objectFinishes';
import { WALL_NAMES } from '../../../../src/core/model/configuration/configuration';
import { objectMesh } from '../../../../src/core/model/objects/objectGeometry';
import type { TriangleMesh } from '../../../../src/core/mesh/triangleMesh';
import { catalog } from '../helpers';
import { headingVector, railPlacements } from '../../../../src/core/model/rails/geometry';
import { chainCoordinates } from '../../../../src/core/model/rails/chainCoordinates';
import { feedLoads } from '../../../../src/core/model/power/feedLoads';
import { mountingRule, suspensionCoordinates } from '../../../../src/core/model/rails/suspensionPoints';

const grey = (): [number, number, number] => [0.4, 0.4, 0.4];
/** Meshes an import could hand over: an L-shaped counter, a tall thin lamp, one reaching below its origin, a malformed one. */
const IMPORTS: { name: string; mesh: TriangleMesh }[] = [
  { name: 'counter.obj', mesh: composeParts([boxPart('worktop', [0, 0, 0], [2, 0.9, 0.6]), boxPart('worktop', [0, 0, 0.6], [0.6, 0.9, 1.6])], grey) },
  { name: 'lamp.glb', mesh: composeParts([frustumPart('shade', 0, 0, 1.4, 1.7, 0.25, 0.12), frustumPart('stand', 0, 0, 0, 1.4, 0.03)], grey) },
  { name: 'sunk.obj', mesh: composeParts([boxPart('body', [-0.3, -0.05, -0.3], [0.3, 0.4, 0.3])], grey) },
  { name: 'broken.obj', mesh: { ...composeParts([boxPart('body', [0, 0, 0], [1, 1, 1])], grey), indices: new Uint32Array([0, 1, 42]), materialOfTriangle: new Uint16Array(1) } },
];
const MATERIALS = ['top', 'legs', 'frame', 'cushions', 'body', 'worktop', 'canvas', 'nope'];

interface Step {
  kind: number;
  i: number;
  j: number;
  a: number;
  b: number;
  c: number;
}

// Uniform in [0, 1) in steps of 1e-6. fc.double is biased towards 0 and the ends (good for finding
// numeric edge cases, bad here): most draws were exactly 0, so every `a < 0.3`-style choice took one
// branch and positions sat at the room's corner. Unbiased (2026-11-24), 5 000 sequences enable 34 417
// steps instead of 23 151, split rails 648 times instead of 84 and fill a driver 1 911 times instead of 473.
const unit = fc.noBias(fc.integer({ min: 0, max: 999_999 })).map((n) => n / 1_000_000);
const step = fc.record({ kind: fc.nat(55), i: fc.nat(50), j: fc.nat(50), a: unit, b: unit, c: unit });

const pick = <T>(xs: readonly T[], i: number, fallback: T): T => (xs.length ? xs[i % xs.length] : fallback);

/**
 * The checks inside the property. Vitest's expect() copies its matcher state on every call, and a
 * sequence makes about a hundred checks after its steps: a plain comparison that throws an Error
 * naming the check and its values (fast-check reports it with the failing sequence) keeps every
 * check at a fraction of the cost (docs/benchmarks.md, "Test suite time").
 */
function holds(ok: boolean, what: string, ...values: unknown[]): void {
  if (!ok) throw new Error(`${what}: ${values.map((v) => JSON.stringify(v)).join(', ')}`);
}

/** Interprets a random step as an action with params against the current state (ids chosen from it). */
function toAction(s: Configuration, st: Step): [string, unknown] {
  const systems = s.systems.map((x) => x.id);
  const rails = s.systems.flatMap((x) => x.rails.map((r) => r.id));
  const modules = s.systems.flatMap((x) => x.rails.flatMap((r) => r.modules.map((m) => m.id)));
  const types = catalog.moduleTypes.map((t) => t.id);
  const { width: W, depth: D } = s.room;
  const sys = pick(systems, st.i, 'none');
  const rail = pick(rails, st.i, 'none');
  const mod = pick(modules, st.i, 'none');
  const obj = pick(
    s.objects.map((o) => o.id),
    st.i,
    'none',
  );
  // An empty room mostly gets a preset, so sequences spend their steps on systems.
  if (systems.length === 0 && st.c < 0.8) return ['placePreset', { presetId: pick(catalog.presets, st.j, catalog.presets[0]).id }];
  // Object edits on a room without objects mostly furnish it first.
  const kind = st.kind >= 27 && st.kind <= 31 && s.objects.length === 0 && st.c < 0.8 ? 32 : st.kind;
  const feeds = s.systems.flatMap((x) => x.feeds.map((f) => f.id));
  const feed = pick(feeds, st.j, 'none');
  // Positions on both sides of what the chain has: ends, existing connectors, one past the last.
  // Branch ends too (a leaf, a rail with a connector, one past the last rail).
  const at = st.a < 0.3 ? 'start' : st.a < 0.5 ? 'end' : st.a < 0.8 ? { joint: st.j % 5 } : { end: st.j % 5 };
  const driver = pick(
    catalog.drivers.map((d) => d.id),
    st.i,
    'none',
  );
  const smallDrivers = [...catalog.drivers]
    .sort((x, y) => x.capacity - y.capacity)
    .slice(0, 3)
    .map((d) => d.id);
  switch (kind) {
    case 0:
      return ['setRoom', { width: 0.5 + st.a * 11, depth: 0.5 + st.b * 11, height: 2 + st.c * 2.5 }];
    case 1:
    case 2:
    case 3:
      return st.c < 0.5
        ? ['placePreset', { presetId: pick(catalog.presets, st.j, catalog.presets[0]).id }]
        : ['placePreset', { presetId: pick(catalog.presets, st.j, catalog.presets[0]).id, x: st.a * W, z: st.b * D, rotation: 90 * (st.i % 4) }];
    case 4:
      return ['deleteSystem', { systemId: st.j % 5 === 0 ? sys : 'none' }];
    case 5:
      return ['moveSystem', { systemId: sys, x: -0.5 + st.a * (W + 1), z: -0.5 + st.b * (D + 1) }];
    case 6:
      return ['rotateSystem', { systemId: sys, by: st.c < 0.5 ? 90 * (st.j % 4) : -180 + 360 * st.a }];
    case 7:
      return ['setSuspension', { systemId: sys, suspension: st.a * 2.5 }];
    case 8:
    case 9:
      return ['setRailLength', { railId: rail, length: 0.3 + st.a * 3 }];
    case 10:
      return ['setDistribution', { railId: rail, distribution: DISTRIBUTIONS[st.j % 4] }];
    case 11:
      return ['addRail', { systemId: sys, connector: pick(catalog.connectors, st.j, catalog.connectors[0]).id, turn: [0, 90, -90, 45, -30, 95, 12][st.i % 7], length: 0.4 + st.a * 3 }];
    case 12:
      return ['removeRail', { railId: rail }];
    case 13:
    case 14:
    case 15:
      return ['addModule', { railId: rail, type: pick(types, st.j, 'spot'), ...(st.c < 0.3 ? { index: st.i % 6 } : {}) }];
    case 16:
      return ['removeModule', { moduleId: mod }];
    case 17:
      return ['setModuleType', { moduleId: mod, type: pick(types, st.j, 'spot') }];
    case 18:
      return ['setModuleCct', { moduleId: mod, cct: [2700, 3000, 4000, 5000][st.j % 4] }];
    case 19:
      return [
        'setModuleBeam',
        {
          moduleId: mod,
          beam: pick(
            catalog.moduleTypes.flatMap((t) => t.beams.map((b) => b.id)),
            st.j,
            'x',
          ),
        },
      ];
    case 20:
      return ['setModuleDimming', { moduleId: mod, dimming: -0.2 + 1.4 * st.a }];
    case 21:
      // Grey or RGB finishes from the integer fields (the unit doubles cluster at their ends);
      // some step past the 0.95 cap or below 0.
      return ['setReflectance', { surface: SURFACE_TARGETS[st.j % SURFACE_TARGETS.length], value: st.c < 0.5 ? 0.02 * st.i - 0.04 : [(st.i % 20) / 20, 0.02 * st.j, st.i % 3 === 0 ? 0.97 : 0.3] }];
    case 22:
      // Addresses near the end of the universe and next to other modules' channels; some unpatch.
      return ['setModulePatch', { moduleId: mod, patch: st.c < 0.1 ? null : { universe: st.j % 3, address: st.c < 0.3 ? 505 + (st.i % 10) : 1 + (st.i % 12), resolution: st.a < 0.5 ? 8 : 16, cct: st.b < 0.5 } }];
    case 23:
      return st.c < 0.15 ? ['clearPatch', {}] : ['autoPatch', { universe: 1 + (st.j % 3), address: 1 + Math.floor(st.a * 511), resolution: st.b < 0.5 ? 8 : 16, cct: st.i % 2 === 0 }];
    case 24:
    case 25:
    case 32: {
      // Library items where asked (some half through a wall: addObject finds the nearest free spot), or where the model puts them.
      const item = pick(FURNITURE_LIBRARY, st.j, FURNITURE_LIBRARY[0]);
      const wall = item.mount === 'wall' ? st.i % 10 !== 0 : st.i % 10 === 0;
      const placement = wall ? { on: 'wall', wall: WALL_NAMES[st.j % 4], u: -0.5 + st.a * (Math.max(W, D) + 1), y: st.b * 3.5 } : { on: 'floor', x: -0.5 + st.a * (W + 1), z: -0.5 + st.b * (D + 1) };
      return ['addObject', { source: { kind: 'library', item: item.id }, ...(st.c < 0.2 ? {} : { placement }), ...(st.c > 0.7 ? { yaw: 360 * st.a - 90, scale: 0.3 + 2.4 * st.b } : {}) }];
    }
    case 26: {
      const meshIds = Object.keys(s.importedMeshes);
      if (meshIds.length > 0 && st.c < 0.4) return ['addObject', { source: { kind: 'imported', mesh: st.i % 7 === 0 ? 'i0' : pick(meshIds, st.i, 'i0') }, placement: { on: 'floor', x: st.a * W, z: st.b * D } }];
      const imp = IMPORTS[st.j % IMPORTS.length];
      return ['addObject', { source: { kind: 'import', name: imp.name, mesh: imp.mesh, units: 'cm' }, placement: { on: 'floor', x: st.a * W, z: st.b * D }, yaw: 90 * (st.i % 4) }];
    }
    case 27:
      return ['moveObject', { objectId: obj, placement: st.c < 0.75 ? { on: 'floor', x: -0.5 + st.a * (W + 1), z: -0.5 + st.b * (D + 1) } : { on: 'wall', wall: WALL_NAMES[st.j % 4], u: st.a * Math.max(W, D), y: st.b * 3 } }];
    case 28:
      return ['rotateObject', st.c < 0.5 ? { objectId: obj, by: 15 * (st.j % 24) - 90 } : { objectId: obj, yaw: 400 * st.a - 20 }];
    case 29:
      return ['resizeObject', { objectId: obj, scale: 0.1 + 4.5 * st.a }];
    case 30:
      return [
        'refinishObject',
        { objectId: obj, material: MATERIALS[st.j % MATERIALS.length], finish: st.c < 0.1 ? null : st.c < 0.6 ? (st.i % 9 === 0 ? 'gold' : pick(OBJECT_FINISHES, st.i, OBJECT_FINISHES[0]).id) : [st.a, st.b, (st.i % 20) / 19] },
      ];
    case 31:
      return ['removeObject', { objectId: st.j % 3 === 0 ? obj : 'none' }];
    case 33:
      return ['addFeed', { systemId: sys, at, ...(st.b < 0.5 ? { driver } : {}) }];
    case 34:
      return ['moveFeed', { feedId: feed, at }];
    case 35:
      return ['removeFeed', { feedId: feed }];
    case 36:
      // Half the time one of the three smallest drivers: presets ship with headroom, so a driver that
      // one more module fills (and one too small for the load) must be chosen to reach those refusals.
      // Chosen by the integer fields (with the biased unit above, a `c < 0.05` choice of 'none' once
      // took 717 of 734 draws at 5 000 sequences, and no driver was ever set).
      return ['setFeedDriver', { feedId: feed, driver: st.i % 20 === 0 ? 'none' : st.i % 2 === 1 ? pick(smallDrivers, st.j, 'none') : driver }];
    case 37:
      return ['setMounting', { systemId: sys, mounting: st.b < 0.5 ? 'surface' : 'suspended' }];
    case 38:
    case 39:
    case 40: {
      // Free positions: anywhere from half a metre before the rail's start to half a metre past its end
      // (from the integer fields mostly: the unit doubles cluster at their ends, i.e. out of range).
      const railOf = s.systems.flatMap((x) => x.rails).find((r) => r.modules.some((m) => m.id === mod));
      const u = st.i % 4 === 0 ? st.a : ((7 * st.j + st.i) % 41) / 40;
      return ['moveModule', { moduleId: mod, offset: -0.5 + u * ((railOf?.length ?? 1) + 1) }];
    }
    case 41: {
      // Middle rails of chains of three or more (splits), else any rail.
      const middle = s.systems.flatMap((x) => x.rails.slice(1, -1).map((r) => r.id));
      return ['removeRail', { railId: pick(middle.length ? middle : rails, st.j, 'none') }];
    }
    case 42:
    case 45:
    case 46: {
      // Flexible connectors mostly (fixed ones are refused), on any system that has one: turns near the
      // current one (mostly kept) or across and beyond ±90°, off the 5° grid too (mostly refused).
      const flexOf = (x: Configuration['systems'][number]) => x.joints.flatMap((j, k) => (catalog.connectors.find((c) => c.id === j.connector)?.flex ? [k] : []));
      const withFlex = s.systems.filter((x) => flexOf(x).length > 0);
      const flex = catalog.connectors.find((c) => c.flex);
      // No chain has one: mostly grow one first (a short rail through the flexible connector).
      if (withFlex.length === 0 && flex && st.b < 0.6) return ['addRail', { systemId: sys, connector: flex.id, turn: [0, 45, -45][st.i % 3], length: 0.5 + 0.1 * (st.j % 4) }];
      const target = withFlex.length > 0 && st.b < 0.9 ? pick(withFlex, st.i, withFlex[0]) : null;
      if (!target) return ['setJointTurn', { systemId: sys, joint: st.j % 3, degrees: 5 * (st.i % 45) - 112 }];
      const joint = pick(flexOf(target), st.j, 0);
      const now = target.joints[joint].turn;
      return ['setJointTurn', { systemId: target.id, joint, degrees: st.c < 0.6 ? now - 20 + (st.i % 41) + (st.j % 3) : -120 + 240 * st.a }];
    }
    case 43:
    case 44: {
      // Any fixing point (one past the last too), anywhere from half a metre before the chain to half a metre past it.
      const sysObj = s.systems.find((x) => x.id === sys);
      const count = sysObj ? suspensionCoordinates(sysObj, catalog).length : 1;
      const length = sysObj ? chainCoordinates(sysObj, catalog).length : 1;
      const u = st.i % 4 === 0 ? st.a : ((7 * st.j + st.i) % 41) / 40;
      const near = sysObj ? suspensionCoordinates(sysObj, catalog)[st.j % count].s : 0;
      // Small steps near a point (mostly kept) or anywhere on the chain (mostly refused).
      return ['moveFixingPoint', { systemId: sys, index: st.j % (count + 1), s: st.c < 0.6 ? near - 0.5 + u : -0.5 + u * (length + 1) }];
    }
    case 47: {
      // Aims of any module (fixed types refused), mostly out of range: rotations across ±2 turns and the 355–360° gap, tilts −30…150°.
      const rotation = st.c < 0.3 ? 355 + (st.i % 10) * 0.5 : -720 + 1440 * st.a;
      return ['setAim', { moduleId: mod, aim: { rotation, tilt: st.b < 0.5 ? -30 + 4 * (st.j % 46) : -30 + 180 * st.b } }];
    }
    case 48:
      // Points anywhere in and around the room, below, level with and above the modules (aimAt clamps).
      return ['aimAt', { moduleId: mod, point: [-1 + st.a * (W + 2), st.c * 4.5, -1 + st.b * (D + 2)] }];
    case 49:
    case 50:
    case 53:
    case 54: {
      // Branches: at any rail's end, through a T or X mostly (some corners, straights, flexible ones,
      // or none: the node's own), at every port and at turns no port has; lengths up to 2.5 m.
      // At a rail that already carries a connector, mostly its own (another one is refused).
      const connectors = ['tee', 'cross', 'tee', 'cross', 'corner90', 'straight', 'flex'];
      const hasNode = s.systems.some((x) => x.joints.some((j, k) => x.rails[j.parent ?? k].id === rail));
      // (From the integer fields: the unit doubles cluster at their ends.)
      const connector = (hasNode && st.j % 10 !== 0) || (!hasNode && st.j % 20 === 0) ? {} : { connector: connectors[st.j % connectors.length] };
      // Mostly toward the room's centre (so branches fit and trees grow), else any port or none.
      const owner = s.systems.find((x) => x.rails.some((r) => r.id === rail));
      const placed = owner ? railPlacements(owner, catalog).find((r) => r.railId === rail) : undefined;
      const inward = placed
        ? [0, 90, -90].map((t) => ({ t, d: headingVector(placed.heading + t) })).sort((p, q) => q.d[0] * (W / 2 - placed.end[0]) + q.d[1] * (D / 2 - placed.end[1]) - (p.d[0] * (W / 2 - placed.end[0]) + p.d[1] * (D / 2 - placed.end[1])))[
            (st.i % 5) % 2
          ].t
        : 0;
      const turn = st.i % 4 === 3 ? [0, 90, -90, 45][st.j % 4] : inward;
      return ['addBranch', { railId: rail, ...connector, turn, length: 0.5 + 0.1 * ((st.i * 7 + st.j) % (st.b < 0.5 ? 6 : 16)) }];
    }
    case 51: {
      // Connector changes at rails that carry one (mostly), to every kind.
      const withNode = s.systems.flatMap((x) => x.joints.map((j, k) => x.rails[j.parent ?? k].id));
      return ['setConnector', { railId: st.b < 0.8 ? pick(withNode, st.i, rail) : rail, connector: pick(catalog.connectors, st.j, catalog.connectors[0]).id }];
    }
    case 52: {
      // Inner rails of trees: rails that carry a connector node (splits into two, three or four pieces).
      const inner = s.systems.flatMap((x) => x.joints.map((j, k) => x.rails[j.parent ?? k].id));
      return ['removeRail', { railId: pick(inner.length ? inner : rails, st.j, 'none') }];
    }
    case 55: {
      // Switching modules on and off, a fifth of these steps.
      if (st.i % 5 === 4) return ['setModuleOn', { moduleId: mod, on: st.a < 0.5 }];
      // Light scenes (docs/light-scenes.md): names from a small pool (clashes, blanks, case twins), fades around 0–30 s.
      const scenes = (s.lightScenes ?? []).map((q) => q.id);
      const scene = pick(scenes, st.j, 'none');
      const names = ['Day', 'Evening', ' evening ', '', 'Night', 'x'.repeat(201)];
      const name = names[st.i % names.length];
      const op = st.j % 6;
      if (scenes.length === 0 || (op === 0 && st.i % 3 !== 0)) return ['recordScene', { name, fade: st.b < 0.5 ? undefined : -5 + 40 * st.b }];
      // With scenes recorded, a third of these steps recall one (after other edits, so the looks differ).
      if (st.i % 3 === 0) return ['recallScene', { sceneId: scene }];
      if (op === 1) return ['renameScene', { sceneId: scene, name }];
      if (op === 2) return ['setSceneFade', { sceneId: scene, fade: -5 + 40 * st.a }];
      if (op === 3) return ['reorderScene', { sceneId: scene, index: (st.j % (scenes.length + 2)) - 1 }];
      if (op === 4) return ['deleteScene', { sceneId: scene }];
      return ['recallScene', { sceneId: scene }];
    }
    default:
      return ['setRailLength', { railId: rail, length: 0.5 + 0.1 * (st.j % 26) }];
  }
}

/**
 * Sequences per run. Issue 11 asks for 10 000 in CI: scripts/test.sh (the README's test command,
 * so CI) sets ALWAYS_VALID_RUNS=10000; a plain `vitest run` while developing takes 5 000. Since
 * the model caches its derived data (perCatalog.ts) and the checks below skip expect(), a sequence
 * costs about 3 ms of CPU (10 000: 32 s of CPU, 62 s on the shared 2-core machine with about seven
 * agents on it), where it took 34 ms under load before (341 s; docs/benchmarks.md, "Test suite time").
 */
const RUNS = Number(process.env.ALWAYS_VALID_RUNS ?? 5000);

describe('always-valid property', () => {
  it(
    'enabled actions keep validate() empty; refused ones would break it',
    () => {
      const counts = { enabled: 0, refused: 0 };
      const finishes = { enabled: 0, refused: 0 };
      const objects = { enabled: 0, refused: 0 };
      const power = { enabled: 0, refused: 0, overloads: 0, surface: 0 };
      const free = { moves: 0, refusedMoves: 0, splits: 0, removals: 0, freeRails: 0 };
      const shape = { turns: 0, refusedTurns: 0, fixingMoves: 0, refusedFixingMoves: 0, movedSystems: 0, turned: 0 };
      const trees = { branches: 0, refusedBranches: 0, connectorChanges: 0, branched: 0, tees: 0, crosses: 0, maxPieces: 0 };
      const aims = { enabled: 0, refused: 0, aimed: 0 };
      const scenes = { enabled: 0, refused: 0, recalls: 0, looks: 0 };
      let placed = 0;
      fc.assert(
        fc.property(unit, unit, unit, fc.array(step, { minLength: 5, maxLength: 30 }), (a, b, c, steps) => {
          let s = createConfiguration({ width: 2 + a * 8, depth: 2 + b * 8, height: 2.4 + c * 2 });
          holds(validate(s, catalog).length === 0, 'a new room is valid');
          for (const st of steps) {
            const [name, params] = toAction(s, st);
            const action = bindAction(name, params, catalog);
            const e = action.isEnabled(s);
            if (name === 'setReflectance') finishes[e === true ? 'enabled' : 'refused']++;
            if (/Object$/.test(name)) objects[e === true ? 'enabled' : 'refused']++;
            if (/Feed|Mounting/.test(name)) power[e === true ? 'enabled' : 'refused']++;
            if (e !== true && /driver is full|would carry|cannot carry/.test(e.reason)) power.overloads++;
            if (name === 'moveModule') free[e === true ? 'moves' : 'refusedMoves']++;
            if (name === 'removeRail' && e === true) free.removals++;
            if (name === 'setJointTurn') shape[e === true ? 'turns' : 'refusedTurns']++;
            if (name === 'moveFixingPoint') shape[e === true ? 'fixingMoves' : 'refusedFixingMoves']++;
            if (name === 'setAim' || name === 'aimAt') aims[e === true ? 'enabled' : 'refused']++;
            if (name === 'addBranch') trees[e === true ? 'branches' : 'refusedBranches']++;
            if (/Scene$/.test(name)) scenes[e === true ? 'enabled' : 'refused']++;
            if (name === 'recallScene' && e === true) scenes.recalls++;
            if (name === 'setConnector' && e === true) trees.connectorChanges++;
            if (e === true) {
              counts.enabled++;
              const systemsBefore = s.systems.length;
              s = action.perform(s);
              if (name === 'removeRail' && s.systems.length > systemsBefore) free.splits++;
              if (name === 'removeRail') trees.maxPieces = Math.max(trees.maxPieces, s.systems.length - systemsBefore + 1);
              const problems = validate(s, catalog);
              if (problems.length) throw new Error(`${name} ${JSON.stringify(params)} was enabled but left: ${problems[0].path}: ${problems[0].message}`);
            } else {
              counts.refused++;
              holds(e.reason.length > 0, `${name} is refused with a reason`);
              let broken: Configuration;
              try {
                broken = action.perform(s);
              } catch {
                continue;
              }
              if (validate(broken, catalog).length === 0) throw new Error(`${name} ${JSON.stringify(params)} was refused (${e.reason}) but would have been valid`);
            }
          }
          // derived outputs of any reachable state are finite
          const scene = toLightingScene(s, catalog);
          for (const l of scene.luminaires) holds([...l.position, l.yaw, l.pitch, l.roll].every(Number.isFinite), 'luminaire placement is finite', l.id);
          // every aim of a reachable state lies within its type's limits and on its stops (validate() says why otherwise)
          for (const m of s.systems.flatMap((x) => x.rails.flatMap((r) => r.modules))) {
            if (!m.aim) continue;
            aims.aimed++;
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
          // Installable by construction: every feed within its driver, the load all assigned, and the
          // fixing points (derived or moved) within the mounting's rules (first and last within the
          // overhang of the chain ends, no gap above the spacing, one at every connector); moved
          // points are judged to FIXING_EPS (a micrometre), derived ones hold to float noise.
          for (const sys of s.systems) {
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
            if (sys.fixings) shape.movedSystems++;
            if (sys.joints.some((j) => j.turn !== 0 && Math.abs(j.turn) !== 90)) shape.turned++;
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
            if (sys.joints.some((j, k) => (j.parent ?? k) !== k)) trees.branched++;
            trees.tees += sys.joints.filter((j) => j.connector === 'tee').length;
            trees.crosses += sys.joints.filter((j) => j.connector === 'cross').length;
            if (sys.mounting === 'surface') power.surface++;
            free.freeRails += sys.rails.filter((r) => r.modules.some((m) => m.offset !== undefined)).length;
          }
          // every look of a reachable state's light scenes names a module that exists (removals pruned them)
          const ids = new Set(s.systems.flatMap((x) => x.rails.flatMap((r) => r.modules.map((m) => m.id))));
          for (const q of s.lightScenes ?? []) {
            for (const id of Object.keys(q.looks)) holds(ids.has(id), 'a look names an existing module', q.id, id);
            scenes.looks += Object.keys(q.looks).length;
          }
          // every object of a reachable state has a finite placement and a mesh whose reflectances the baker accepts
          placed += s.objects.length;
          for (const o of scene.objects ?? []) holds([...o.position, o.yaw, o.scale].every(Number.isFinite), 'object placement is finite', o.id);
          for (const o of s.objects)
            holds(
              objectMesh(s, o.id).materials.every((m) => m.reflectance.every((c) => c >= 0 && c < 1)),
              'object reflectances within [0, 1)',
              o.id,
            );
        }),
        { seed: 20240917, numRuns: RUNS },
      );
      console.log(`always-valid: ${RUNS} sequences, ${JSON.stringify({ counts, finishes, objects, power, placed, free, shape, aims, trees, scenes })}`);
      // both branches were exercised in bulk (at 2 000 sequences: 9 278 enabled, 15 157 refused steps;
      // 371 / 31 finishes, 2 561 / 1 172 object actions, 2 017 objects placed; bounds scale with RUNS)
      expect(counts.enabled).toBeGreaterThan(3 * RUNS);
      expect(counts.refused).toBeGreaterThan(3 * RUNS);
      expect(finishes.enabled).toBeGreaterThan(0.12 * RUNS);
      // scene actions ran both ways, scenes were recalled, and looks survived module removals
      // (at 5 000 sequences: 417 enabled, 201 refused, 9 recalls, 1 308 looks checked; a recall needs a
      // second scene step in the same sequence, rare at one kind in 56)
      expect(scenes.enabled).toBeGreaterThan(0.06 * RUNS);
      expect(scenes.refused).toBeGreaterThan(0.02 * RUNS);
      expect(scenes.recalls).toBeGreaterThan(0.001 * RUNS);
      expect(scenes.looks).toBeGreaterThan(0.1 * RUNS);
      expect(finishes.refused).toBeGreaterThan(0.007 * RUNS);
      expect(objects.enabled).toBeGreaterThan(0.8 * RUNS);
      expect(objects.refused).toBeGreaterThan(0.33 * RUNS);
      expect(placed).toBeGreaterThan(0.68 * RUNS);
      // the power and mounting actions, and refusals for an overloaded driver, in bulk
      expect(power.enabled).toBeGreaterThan(RUNS / 4);
      // (2 806 at 5 000 and 5 644 at 10 000 sequences)
      expect(power.refused).toBeGreaterThan(0.3 * RUNS);
      // (1 911 at 5 000 and 3 770 at 10 000 sequences: setFeedDriver picks one of the three smallest
      // drivers half the time, which one more module fills or which is too small for the load. The
      // Single rail preset ships with a 240 W driver, so without that only 97 at 5 000 filled one)
      expect(power.overloads).toBeGreaterThan(RUNS / 15);
      // (495 at 5 000 and 956 at 10 000 sequences)
      expect(power.surface).toBeGreaterThan(RUNS / 15);
      // free positions and rail removals at any index (splits included), in bulk
      // (at 5 000 sequences: 739 / 2 419 moves, 598 free rails at the ends, 213 removals, 72 splits)
      expect(free.moves).toBeGreaterThan(RUNS / 12);
      expect(free.refusedMoves).toBeGreaterThan(RUNS / 4);
      expect(free.freeRails).toBeGreaterThan(RUNS / 15);
      expect(free.removals).toBeGreaterThan(RUNS / 40);
      expect(free.splits).toBeGreaterThan(RUNS / 200);
      // flexible connector turns and moved fixing points, kept and refused, in bulk
      // (at 2 000 sequences: 20 / 26 turns, 101 / 657 fixing moves, 84 systems ending with moved points, 41 with a flexible turn)
      expect(shape.turns).toBeGreaterThan(RUNS / 200);
      expect(shape.refusedTurns).toBeGreaterThan(RUNS / 200);
      expect(shape.fixingMoves).toBeGreaterThan(RUNS / 40);
      expect(shape.refusedFixingMoves).toBeGreaterThan(RUNS / 20);
      expect(shape.movedSystems).toBeGreaterThan(RUNS / 60);
      expect(shape.turned).toBeGreaterThan(RUNS / 100);
      // aims set and refused (fixed types) in bulk, and aimed modules in the final states
      expect(aims.enabled).toBeGreaterThan(RUNS / 20);
      expect(aims.refused).toBeGreaterThan(RUNS / 40);
      expect(aims.aimed).toBeGreaterThan(RUNS / 40);
      // trees (issue 11): branches through T and X connectors grown and refused, connector changes, branched systems
      // reached, inner rails removed (at 5 000 sequences: 1 687 / 1 638 branches, 168 changes, 53 branched end states,
      // 445 T and 478 X joints; the six tree kinds thinned the others: finishes 671, refused object actions 1 889,
      // 3 875 objects placed, 514 free moves, 185 fixing moves, 128 systems with moved points; at 10 000: 3 340 / 3 278
      // branches, 332 changes, 102 branched end states, 343 fixing moves)
      expect(trees.branches).toBeGreaterThan(RUNS / 5);
      expect(trees.refusedBranches).toBeGreaterThan(RUNS / 5);
      expect(trees.connectorChanges).toBeGreaterThan(RUNS / 50);
      expect(trees.branched).toBeGreaterThan(RUNS / 400);
      expect(trees.tees).toBeGreaterThan(RUNS / 20);
      expect(trees.crosses).toBeGreaterThan(RUNS / 20);
      // (five more action kinds thinned the others: object actions 0.8·RUNS and 0.4·RUNS, refused finishes 0.007·RUNS;
      // at 5 000 sequences: 66 / 50 turns, 242 / 1 664 fixing moves, 205 systems with moved points, 97 turned)
    },
    Math.max(120_000, 60 * RUNS),
  ); // 60 ms a sequence: ten times the load-time cost of today (about 6 ms), above the 34 ms before the caches
});
