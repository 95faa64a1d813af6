/**
 * Issue 32, "Numbers": NaN, ±Infinity and ±1e308 in every numeric field of the lighting scene and
 * configuration formats. The fields are not listed by hand: they are every number leaf of sample
 * files (walked), and a coverage check proves the samples reach every number the zod schemas
 * declare. Each bad value must be refused with a message naming the field (or the object that
 * holds it, for checks that need the placed mesh), or accepted with only finite numbers
 * downstream: the lighting scene, every placed vertex and every luminaire rotation.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { z } from 'zod/mini';
import { livingRoom } from '../../../../src/core/catalog/furnishedPresets';
import { attemptAction } from '../../../../src/core/model/actions/actionDefinitions';
import { composeParts, boxPart } from '../../../../src/core/model/objects/furniture/meshParts';
import type { Configuration } from '../../../../src/core/model/configuration/configuration';
import { lightingSceneSchema, lightingSceneSchemaV3, parseLightingScene } from '../../../../src/core/model/lightingScene/parseLightingScene';
import { configurationFromData, serializeConfiguration } from '../../../../src/core/model/files/sceneFile';
import { sceneFileSchema } from '../../../../src/core/model/files/sceneFileSchema';
import { toLightingScene } from '../../../../src/core/model/files/toLightingScene';
import { objectMesh } from '../../../../src/core/model/objects/objectGeometry';
import type { LightingScene } from '../../../../src/core/model/lightingScene/lightingScene';
import { firstNonFiniteVertex, placedPositions } from '../../../../src/core/mesh/placeMesh';
import { positionBounds } from '../../../../src/core/mesh/triangleMesh';
import type { TriangleMesh } from '../../../../src/core/mesh/triangleMesh';
import { resolveBakeScene } from '../../../../src/engines/bake/resolveBakeScene';
import { luminaireRotation } from '../../../../src/engines/bake/luminaireRotation';
import type { Photometry } from '../../../../src/core/photometry/types';
import { nonFinitePaths } from '../../../fuzz/checks';
import { catalog } from '../helpers';

const BAD_VALUES = [Number.NaN, Infinity, -Infinity, 1e308, -1e308];

type Path = (string | number)[];

/** Every path to a number in a JSON value. */
function numberPaths(value: unknown, at: Path = []): Path[] {
  if (typeof value === 'number') return [at];
  if (typeof value !== 'object' || value === null) return [];
  return Object.entries(value).flatMap(([k, v]) => numberPaths(v, [...at, Array.isArray(value) ? Number(k) : k]));
}

/** The path as messages write it: `luminaires[0].position[1]`. */
const show = (path: Path): string => path.map((k, i) => (typeof k === 'number' ? `[${k}]` : i === 0 ? k : `.${k}`)).join('');
/** The path with array indices dropped and object keys kept: `luminaires.position` (what a schema declares). */
const shape = (path: Path): string => path.filter((k) => typeof k === 'string').join('.');

function withValue(doc: unknown, path: Path, value: number): unknown {
  const copy = structuredClone(doc) as Record<string | number, unknown>;
  let node = copy;
  for (const k of path.slice(0, -1)) node = node[k] as Record<string | number, unknown>;
  node[path[path.length - 1]] = value;
  return copy;
}

/**
 * The shapes (keys, indices dropped) of every number a zod schema declares, record keys as `*`.
 * Walks the same zod 4 definitions as untrustedJson's schemaFieldNames.
 */
function schemaNumberShapes(schema: z.ZodMiniType): Set<string> {
  const out = new Set<string>();
  const visit = (s: unknown, at: string[], depth: number): void => {
    const def = (s as { _zod?: { def?: Record<string, unknown> } })?._zod?.def;
    if (!def || depth > 40) return;
    if (def.type === 'number') out.add(at.join('.'));
    if (def.type === 'object') for (const [k, v] of Object.entries(def.shape as Record<string, unknown>)) visit(v, [...at, k], depth + 1);
    if (def.type === 'record') visit(def.valueType, [...at, '*'], depth + 1);
    for (const key of ['innerType', 'element', 'in', 'out', 'schema', 'rest']) if (def[key]) visit(def[key], at, depth + 1);
    for (const key of ['options', 'items']) if (Array.isArray(def[key])) (def[key] as unknown[]).forEach((o) => visit(o, at, depth + 1));
  };
  visit(schema, [], 0);
  return out;
}

const cube: TriangleMesh = composeParts([boxPart('body', [-0.2, 0, -0.2], [0.2, 0.4, 0.2])], () => [0.5, 0.5, 0.5]);
const photometry = {} as Photometry; // resolveBakeScene only hands it on

/** Problems with an accepted lighting scene downstream: non-finite numbers, placed vertices, rotations. */
async function sceneDownstream(scene: LightingScene): Promise<string[]> {
  const out = nonFinitePaths(scene).map((p) => `non-finite ${p}`);
  let bake;
  try {
    bake = await resolveBakeScene(
      scene,
      () => photometry,
      () => cube,
    );
  } catch (e) {
    // The room check of placed meshes refuses, naming the object.
    return [...out, ...(/^objects\[\d+\]: /.test((e as Error).message) ? [] : [`refused without naming the object: ${(e as Error).message}`])];
  }
  for (const o of bake.objects ?? []) if (!placedPositions(o.mesh, o).every(Number.isFinite)) out.push(`object ${o.id}: non-finite placed vertex`);
  for (const l of bake.luminaires) if (!luminaireRotation(l.yaw, l.pitch, l.roll).every(Number.isFinite)) out.push('non-finite luminaire rotation');
  return out;
}

describe('angles and bounds at the ends of the double range', () => {
  it('a yaw of 5.7e307 turns the mesh by yaw mod 360 (yaw·π used to overflow to NaN vertices)', () => {
    const yaw = 5.7e307;
    const placed = placedPositions(cube, { position: [1, 0, 1], yaw, scale: 1 });
    expect(firstNonFiniteVertex(placed)).toBe(-1);
    expect([...placed]).toEqual([...placedPositions(cube, { position: [1, 0, 1], yaw: yaw % 360, scale: 1 })]);
    expect(luminaireRotation(yaw, -1e308, 1.7e308).every(Number.isFinite)).toBe(true);
  });

  it('actions refuse an object placed at the ends of the double range (never placed with non-finite vertices)', () => {
    const state = livingRoom(catalog);
    for (const placement of [
      { on: 'floor', x: 1e308, z: 1 },
      { on: 'floor', x: 1, z: -1e308 },
      { on: 'wall', wall: 'north', u: 1e308, y: 1 },
    ]) {
      const outcome = attemptAction(state, 'addObject', { source: { kind: 'library', item: 'dining-table' }, placement }, catalog);
      expect(outcome.ok).toBe(false);
    }
    for (const params of [{ scale: 1e308 }, { yaw: Number.NaN }, { yaw: Infinity }]) {
      expect(attemptAction(state, 'addObject', { source: { kind: 'library', item: 'dining-table' }, placement: { on: 'floor', x: 2, z: 2 }, ...params }, catalog).ok).toBe(false);
    }
    // A huge yaw is turned into [0, 360) by the action: accepted, with finite vertices.
    const turned = attemptAction(state, 'addObject', { source: { kind: 'library', item: 'dining-table' }, placement: { on: 'floor', x: 2, z: 2 }, yaw: 1e308 }, catalog);
    if (!turned.ok) throw new Error(turned.reason);
    const added = turned.next.objects[turned.next.objects.length - 1];
    expect(added.yaw).toBe(1e308 % 360);
    const sceneObject = toLightingScene(turned.next, catalog).objects!.find((o) => o.id === added.id)!;
    expect(firstNonFiniteVertex(placedPositions(objectMesh(turned.next, added.id), sceneObject))).toBe(-1);
  });

  it('NaN is kept by positionBounds, so no bounds check can pass it', () => {
    const b = positionBounds([0, 0, 0, NaN, 1, 1, 2, 2, 2]);
    expect(b.min[0]).toBeNaN();
    expect(b.max[0]).toBeNaN();
    expect(b.min.slice(1)).toEqual([0, 0]);
    expect(firstNonFiniteVertex([0, 0, 0, 1, Infinity, 1])).toBe(1);
  });
});

describe('non-finite and huge numbers in every numeric field', () => {
  const sceneSamples = ['tests/fixtures/scenes/small-room.json', 'tests/fixtures/models/furnished-room.json', 'tests/fixtures/bench/living-room.json', 'tests/fixtures/scenes/attic-l-room.json'];

  it('lighting scenes: each refused naming the field, or finite downstream', async () => {
    // Yaw, pitch and roll are optional: give every luminaire and object all of them so they are walked.
    const docs = sceneSamples.map((f) => {
      const doc = JSON.parse(readFileSync(f, 'utf8')) as { luminaires: Record<string, unknown>[]; objects?: Record<string, unknown>[] };
      for (const l of doc.luminaires) Object.assign(l, { yaw: 10, pitch: 5, roll: 3, dimming: 1, color: [1, 1, 1] }, l);
      for (const o of doc.objects ?? []) Object.assign(o, { yaw: 0, scale: 1 }, o);
      return doc;
    });
    const covered = new Set(docs.flatMap((d) => numberPaths(d).map(shape)));
    expect([...schemaNumberShapes(lightingSceneSchema), ...schemaNumberShapes(lightingSceneSchemaV3)].filter((s) => !covered.has(s))).toEqual([]);
    const failures: string[] = [];
    let cases = 0;
    for (const doc of docs) {
      for (const path of numberPaths(doc)) {
        for (const bad of BAD_VALUES) {
          cases++;
          let scene: LightingScene;
          try {
            scene = parseLightingScene(withValue(doc, path, bad), 'scene.json');
          } catch (e) {
            const message = (e as Error).message;
            if (!namesField(message, path)) failures.push(`${show(path)} = ${bad}: refused without naming the field: ${message}`);
            continue;
          }
          for (const p of await sceneDownstream(scene)) failures.push(`${show(path)} = ${bad}: ${p}`);
        }
      }
    }
    expect(failures.slice(0, 10)).toEqual([]);
    expect(cases).toBeGreaterThan(200);
  });

  it('configurations: each refused naming the field, or finite downstream', () => {
    const doc = JSON.parse(serializeConfiguration(richConfiguration(), catalog));
    const covered = new Set(numberPaths(doc).map(shape));
    const declared = schemaNumberShapes(sceneFileSchema);
    expect([...declared].filter((s) => !covered.has(s) && ![...covered].some((c) => matchesRecord(s, c)))).toEqual([]);
    const failures: string[] = [];
    let cases = 0;
    for (const path of numberPaths(doc)) {
      for (const bad of BAD_VALUES) {
        cases++;
        let config: Configuration;
        try {
          config = configurationFromData(withValue(doc, path, bad), catalog, 'scene.luxbox.json');
        } catch (e) {
          const message = (e as Error).message;
          if (!namesField(message, path)) failures.push(`${show(path)} = ${bad}: refused without naming the field: ${message}`);
          continue;
        }
        const scene = toLightingScene(config, catalog);
        const problems = nonFinitePaths(scene).map((p) => `non-finite ${p}`);
        for (const o of config.objects) {
          const sceneObject = scene.objects?.find((s) => s.id === o.id);
          if (sceneObject && !placedPositions(objectMesh(config, o.id), sceneObject).every(Number.isFinite)) problems.push(`object ${o.id}: non-finite placed vertex`);
        }
        failures.push(...problems.map((p) => `${show(path)} = ${bad}: ${p}`));
      }
    }
    expect(failures.slice(0, 10)).toEqual([]);
    expect(cases).toBeGreaterThan(200);
  });
});

/**
 * A message names the field: its path, or the entry one level up that holds it (the tuple `color`
 * for `color[0]`; validate()'s rule for a whole placement `placement` for `placement.x`).
 */
function namesField(message: string, path: Path, levels = 1): boolean {
  for (let n = path.length; n >= Math.max(1, path.length - levels); n--) if (message.includes(show(path.slice(0, n)))) return true;
  return false;
}

/** `a.*.b` (a record in the schema) matches `a.key.b` (a sample). */
function matchesRecord(declared: string, covered: string): boolean {
  const d = declared.split('.');
  const c = covered.split('.');
  return d.length === c.length && d.every((k, i) => k === '*' || k === c[i]);
}

/** The living room with every optional numeric field in use: a DMX patch, a moved module, an aim, a light scene, a feed at a joint, moved fixing points, a coloured finish, an imported mesh. */
function richConfiguration(): Configuration {
  let state = livingRoom(catalog);
  const system = state.systems[0];
  const modules = system.rails.flatMap((r) => r.modules);
  const tries: [string, Record<string, unknown>][] = [
    ['autoPatch', { universe: 1, address: 1, resolution: 8, cct: true }],
    ['moveModule', { moduleId: modules[0].id, offset: 0.05 }],
    ...modules.map((m): [string, Record<string, unknown>] => ['setAim', { moduleId: m.id, aim: { rotation: 30, tilt: 20 } }]),
    ['recordScene', { name: 'Evening', fade: 2 }],
    ['addFeed', { systemId: system.id, at: { joint: 0 }, driver: 'hlg-320h-48' }],
    ['setFeedDriver', { feedId: system.feeds[0].id, driver: 'hlg-320h-48' }],
    ['refinishObject', { objectId: state.objects[0].id, material: objectMesh(state, state.objects[0].id).materials[0].name, finish: [0.4, 0.3, 0.2] }],
    ['addObject', { source: { kind: 'import', name: 'crate.obj', mesh: cube, units: 'm' }, placement: { on: 'floor', x: 1, z: 1 }, yaw: 15 }],
    ['setConnector', { railId: system.rails[0].id, connector: 'tee' }],
    ['addBranch', { railId: system.rails[0].id, turn: 0, length: 0.5 }],
    ['addBranch', { railId: system.rails[0].id, turn: -90, length: 0.5 }],
    ['addBranch', { railId: system.rails[system.rails.length - 1].id, connector: 'tee', turn: -90, length: 0.5 }],
    ['addFeed', { systemId: system.id, at: { end: 2 }, driver: 'hlg-320h-48' }],
    ...[0.3, 0.5, 0.2, 0.1].map((s): [string, Record<string, unknown>] => ['moveFixingPoint', { systemId: system.id, index: 0, s }]),
  ];
  for (const [name, params] of tries) {
    const outcome = attemptAction(state, name, params, catalog);
    // Some tries are refused in this room (a fixed module cannot be aimed); the coverage check above says whether enough passed.
    if (outcome.ok) state = outcome.next;
  }
  // A room shape (version 9) with every numeric field: the room's rectangle with a corner on its north wall, a slope, a door, per-wall finishes.
  const { width: W, depth: D, height: H } = state.room;
  const shape = {
    outline: [
      [0, 0],
      [W / 2, 0],
      [W, 0],
      [W, D],
      [0, D],
    ] as const,
    slopes: [{ wall: 3, kneeHeight: H, pitch: 30, reflectance: [0.7, 0.7, 0.6] as [number, number, number] }],
    openings: [{ wall: 2, offset: 0.2, width: 0.9, sill: 0, height: 2, kind: 'door' as const }],
    wallReflectance: [0.5, 0.5, [0.6, 0.5, 0.4] as [number, number, number], 0.5, 0.5],
  };
  return { ...state, room: { ...state.room, shape } };
}
