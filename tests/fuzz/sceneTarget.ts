/**
 * Fuzz target: lighting scene files (`luxbox bake/probe/render` input) through
 * the loader's own text reader and parseLightingScene — everything
 * loadLightingSceneFile does before it opens the photometric files (which a
 * mutated path must not make the fuzzer read).
 */
import { readFileSync } from 'node:fs';
import { LightingSceneError, parseLightingScene } from '../../src/core/model/lightingScene/parseLightingScene';
import { SURFACE_NAMES, type LightingScene } from '../../src/core/model/lightingScene/lightingScene';
import { parseJsonText } from '../../src/hosts/node/loadLightingSceneFile';
import { jsonAcceptedProblems } from './checks';
import type { FuzzOutcome, FuzzSeed, FuzzTarget } from './fuzzTarget';

const SEEDS = ['tests/fixtures/scenes/small-room.json', 'tests/fixtures/bench/living-room.json', 'tests/fixtures/bench/corridor.json', 'tests/fixtures/bench/cie-cube.json'];

const decoder = new TextDecoder('utf-8'); // as readFileSync(path, 'utf8'): bad bytes become U+FFFD

/** Physical sanity of an accepted scene, checked independently of the parser. */
export function sceneProblems(s: LightingScene): string[] {
  const out: string[] = [];
  const { width, height, depth } = s.room;
  if (![width, height, depth].every((d) => d >= 0.1 && d <= 500)) out.push('room dimension out of range');
  for (const surface of SURFACE_NAMES) {
    const r = s.room.reflectance[surface];
    if (!(Array.isArray(r) ? r : [r]).every((x) => x >= 0 && x < 1)) out.push(`reflectance ${surface} out of range`);
  }
  s.luminaires.forEach((l, i) => {
    const [x, y, z] = l.position;
    if (!(x >= 0 && x <= width && y >= 0 && y <= height && z >= 0 && z <= depth)) out.push(`luminaires[${i}] outside the room`);
    if (l.dimming !== undefined && !(l.dimming >= 0 && l.dimming <= 1)) out.push(`luminaires[${i}].dimming out of range`);
  });
  if (s.nearField !== undefined && s.version !== 2) out.push('nearField in a version-1 scene');
  return out;
}

export const sceneFuzzTarget: FuzzTarget = {
  name: 'scene',
  seeds: (): FuzzSeed[] => SEEDS.map((path) => ({ name: path.split('/').pop()!, bytes: new Uint8Array(readFileSync(path)) })),
  run(input: Uint8Array): FuzzOutcome {
    const text = decoder.decode(input);
    let scene: LightingScene;
    try {
      scene = parseLightingScene(parseJsonText(text, 'scene.json'), 'scene.json');
    } catch (error) {
      if (error instanceof LightingSceneError) return { kind: 'refused', message: error.message };
      throw error;
    }
    return { kind: 'accepted', problems: [...jsonAcceptedProblems(text, scene), ...sceneProblems(scene)] };
  },
};
