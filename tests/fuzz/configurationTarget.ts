/**
 * Fuzz target: the configurator's scene files ("Open file…", the saved
 * autosave, setConfig text) through deserializeConfiguration, which
 * readSceneFile calls after its 1 MB size check. Seeds: the viewer's saved
 * fixture and the demo configuration as the app saves it.
 */
import { readFileSync } from 'node:fs';
import { demoConfiguration } from '../../src/core/catalog/demoConfiguration';
import { defaultCatalog } from '../../src/core/catalog/defaultCatalog';
import type { Configuration } from '../../src/core/model/configuration/configuration';
import { deserializeConfiguration, serializeConfiguration, toSceneFile } from '../../src/core/model/files/sceneFile';
import { SceneFileError } from '../../src/core/model/files/sceneFileError';
import { validate } from '../../src/core/model/validation/validate';
import { jsonAcceptedProblems } from './checks';
import type { FuzzOutcome, FuzzSeed, FuzzTarget } from './fuzzTarget';

const decoder = new TextDecoder('utf-8'); // as File.text(): bad bytes become U+FFFD
const encoder = new TextEncoder();

export function configurationSeeds(): FuzzSeed[] {
  return [
    { name: 'corner-l.luxbox.json', bytes: new Uint8Array(readFileSync('tests/fixtures/configurations/corner-l.luxbox.json')) },
    { name: 'demo (serializeConfiguration)', bytes: encoder.encode(serializeConfiguration(demoConfiguration(defaultCatalog), defaultCatalog)) },
  ];
}

/** What is wrong with an accepted configuration (read from `text`). */
export function configurationProblems(text: string, config: Configuration): string[] {
  const problems = jsonAcceptedProblems(text, toSceneFile(config, defaultCatalog));
  problems.push(
    ...validate(config, defaultCatalog)
      .slice(0, 3)
      .map((p) => `invalid: ${p.path}: ${p.message}`),
  );
  return problems;
}

export const configurationFuzzTarget: FuzzTarget = {
  name: 'configuration',
  seeds: configurationSeeds,
  run(input: Uint8Array): FuzzOutcome {
    const text = decoder.decode(input);
    let config: Configuration;
    try {
      config = deserializeConfiguration(text, defaultCatalog, '“scene.luxbox.json”');
    } catch (error) {
      if (error instanceof SceneFileError) return { kind: 'refused', message: error.message };
      throw error;
    }
    return { kind: 'accepted', problems: configurationProblems(text, config) };
  },
};
