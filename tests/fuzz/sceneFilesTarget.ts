/**
 * Fuzz target (issue 32): lighting scene files through the loader that also reads what they name —
 * the photometric files and the objects' OBJ meshes (resolveSceneFiles, the synchronous path of
 * `luxbox bake/probe/render`) — relative to the fixture folder, with the CLI's rule that a scene
 * may name files only inside the repository (SceneFileAccess.within): a mutated path never reaches
 * outside it. Accepted: every placed object vertex and every number the baker gets is finite.
 */
import { readFileSync, realpathSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { InputError } from '../../src/core/inputError';
import { placedPositions } from '../../src/core/mesh/placeMesh';
import { LightingSceneError, parseLightingScene } from '../../src/core/model/lightingScene/parseLightingScene';
import type { LightingScene } from '../../src/core/model/lightingScene/lightingScene';
import { parseJsonText, resolveSceneFiles } from '../../src/hosts/node/loadLightingSceneFile';
import { jsonAcceptedProblems } from './checks';
import type { FuzzOutcome, FuzzSeed, FuzzTarget } from './fuzzTarget';
import { sceneProblems } from './sceneTarget';

const ROOT = realpathSync(fileURLToPath(new URL('../..', import.meta.url)));
const FOLDER = join(ROOT, 'tests/fixtures/models');
const SEEDS = ['tests/fixtures/models/furnished-room-obj.json'];
const decoder = new TextDecoder('utf-8');

export const sceneFilesFuzzTarget: FuzzTarget = {
  name: 'scene-files',
  seeds: (): FuzzSeed[] => SEEDS.map((path) => ({ name: path.split('/').pop()!, bytes: new Uint8Array(readFileSync(join(ROOT, path))) })),
  run(input: Uint8Array): FuzzOutcome {
    const text = decoder.decode(input);
    let scene: LightingScene;
    let objects: { position: number[]; yaw: number; scale: number; mesh: Parameters<typeof placedPositions>[0] }[];
    try {
      scene = parseLightingScene(parseJsonText(text, 'scene.json'), 'scene.json');
      const loaded = resolveSceneFiles(scene, FOLDER, 'scene.json', { within: [ROOT] });
      objects = (loaded.bakeScene.objects ?? []) as typeof objects;
    } catch (error) {
      if (error instanceof LightingSceneError || error instanceof InputError) return { kind: 'refused', message: error.message };
      throw error;
    }
    const problems = [...jsonAcceptedProblems(text, scene), ...sceneProblems(scene)];
    objects.forEach((o, k) => {
      const world = placedPositions(o.mesh, { position: o.position as [number, number, number], yaw: o.yaw, scale: o.scale });
      if (!world.every(Number.isFinite)) problems.push(`objects[${k}]: a placed vertex is not finite`);
    });
    return { kind: 'accepted', problems };
  },
};
