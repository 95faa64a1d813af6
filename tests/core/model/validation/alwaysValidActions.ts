/**
 * The random steps of the always-valid property (alwaysValid.property.test.ts): a step is six
 * numbers, which toAction reads as one of the model's actions with params chosen from the current
 * state (rails, modules, patches, finishes, objects, power, trees, aims, light scenes).
 */
import fc from 'fast-check';
import type { Configuration } from '../../../../src/core/model/configuration/configuration';
import { DISTRIBUTIONS } from '../../../../src/core/model/catalogSchema/railSystemSchema';
import { SURFACE_TARGETS } from '../../../../src/core/model/lightingScene/reflectance';
import { FURNITURE_LIBRARY } from '../../../../src/core/model/objects/furniture/furnitureLibrary';
import { boxPart, composeParts, frustumPart } from '../../../../src/core/model/objects/furniture/meshParts';
import { OBJECT_FINISHES } from '../../../../src/core/model/objects/furniture/objectFinishes';
import { WALL_NAMES } from '../../../../src/core/model/configuration/configuration';
import type { TriangleMesh } from '../../../../src/core/mesh/triangleMesh';
import { catalog } from '../helpers';
import { headingVector, railPlacements } from '../../../../src/core/model/rails/geometry';
import { chainCoordinates } from '../../../../src/core/model/rails/chainCoordinates';
import { suspensionCoordinates } from '../../../../src/core/model/rails/suspensionPoints';

const grey = (): [number, number, number] => [0.4, 0.4, 0.4];
/** Meshes an import could hand over: an L-shaped counter, a tall thin lamp, one reaching below its origin, a malformed one. */
const IMPORTS: { name: string; mesh: TriangleMesh }[] = [
  { name: 'counter.obj', mesh: composeParts([boxPart('worktop', [0, 0, 0], [2, 0.9, 0.6]), boxPart('worktop', [0, 0, 0.6], [0.6, 0.9, 1.6])], grey) },
  { name: 'lamp.glb', mesh: composeParts([frustumPart('shade', 0, 0, 1.4, 1.7, 0.25, 0.12), frustumPart('stand', 0, 0, 0, 1.4, 0.03)], grey) },
  { name: 'sunk.obj', mesh: composeParts([boxPart('body', [-0.3, -0.05, -0.3], [0.3, 0.4, 0.3])], grey) },
  { name: 'broken.obj', mesh: { ...composeParts([boxPart('body', [0, 0, 0], [1, 1, 1])], grey), indices: new Uint32Array([0, 1, 42]), materialOfTriangle: new Uint16Array(1) } },
];
const MATERIALS = ['top', 'legs', 'frame', 'cushions', 'body', 'worktop', 'canvas', 'nope'];

export interface Step {
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
export const unit = fc.noBias(fc.integer({ min: 0, max: 999_999 })).map((n) => n / 1_000_000);
export const step = fc.record({ kind: fc.nat(55), i: fc.nat(50), j: fc.nat(50), a: unit, b: unit, c: unit });

const pick = <T>(xs: readonly T[], i: number, fallback: T): T => (xs.length ? xs[i % xs.length] : fallback);

/** Interprets a random step as an action with params against the current state (ids chosen from it). */
export function toAction(s: Configuration, st: Step): [string, unknown] {
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
