import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../../src/core/catalog/defaultCatalog';
import { parseCatalog } from '../../../../src/core/model/catalogSchema/catalogSchema';
import { parseLightingScene, LIGHTING_SCENE_VERSION } from '../../../../src/core/model/lightingScene/parseLightingScene';
import { deserializeConfiguration, serializeConfiguration } from '../../../../src/core/model/files/sceneFile';
import { decodeShareString } from '../../../../src/core/model/files/shareLink';
import { SCENE_FILE_VERSION } from '../../../../src/core/model/files/sceneFileSchema';
import { loadColourFilterSpectra } from '../../../../src/core/colour/colourFilterSpectra';

// Frozen formats (issue 33): a real file of every version of every format, each written by the
// luxbox of its day (tests/fixtures/formats/README.md says which commit and how), opened by
// today's code and compared with the expected current form in expected/. A version bump without a
// frozen file of the new version fails here, so every migration step always has a real input.

const DIR = join(__dirname, '../../../fixtures/formats');
const text = (name: string) => readFileSync(join(DIR, name), 'utf8');
const files = readdirSync(DIR);
const versionsOf = (prefix: string, suffix: string) => files.flatMap((f) => (f.startsWith(prefix) && f.endsWith(suffix) ? [Number(f.slice(prefix.length, -suffix.length))] : [])).sort((a, b) => a - b);
const oneToCurrent = (n: number) => Array.from({ length: n }, (_, i) => i + 1);

beforeAll(loadColourFilterSpectra);

describe('configuration files (luxbox-configuration)', () => {
  it('has a frozen file of every version, 1 to the current one', () => {
    expect(versionsOf('configuration-v', '.luxbox.json')).toEqual(oneToCurrent(SCENE_FILE_VERSION));
  });
  for (const v of versionsOf('configuration-v', '.luxbox.json')) {
    it(`version ${v} opens and reads as its expected current form`, () => {
      const source = text(`configuration-v${v}.luxbox.json`);
      expect(JSON.parse(source).version).toBe(v);
      const config = deserializeConfiguration(source, defaultCatalog, `configuration-v${v}.luxbox.json`);
      expect(serializeConfiguration(config, defaultCatalog) + '\n').toBe(text(`expected/configuration-v${v}.luxbox.json`));
    });
  }
  it('the current version reads and writes back byte for byte', () => {
    const source = text(`configuration-v${SCENE_FILE_VERSION}.luxbox.json`);
    expect(serializeConfiguration(deserializeConfiguration(source, defaultCatalog), defaultCatalog) + '\n').toBe(source);
  });
});

describe('share links', () => {
  it('has a frozen link of every configuration version', () => {
    expect(versionsOf('share-link-v', '.txt')).toEqual(oneToCurrent(SCENE_FILE_VERSION));
  });
  for (const v of versionsOf('share-link-v', '.txt')) {
    it(`a version ${v} link opens as its expected configuration`, () => {
      const config = decodeShareString(text(`share-link-v${v}.txt`).trim(), defaultCatalog);
      expect(serializeConfiguration(config, defaultCatalog) + '\n').toBe(text(`expected/share-link-v${v}.luxbox.json`));
    });
  }
});

describe('lighting scenes (the CLI contract)', () => {
  it('has a frozen scene of every version', () => {
    expect(versionsOf('lighting-scene-v', '.json')).toEqual(oneToCurrent(LIGHTING_SCENE_VERSION));
  });
  for (const v of versionsOf('lighting-scene-v', '.json')) {
    it(`version ${v} parses to its expected form`, () => {
      const scene = parseLightingScene(JSON.parse(text(`lighting-scene-v${v}.json`)), `lighting-scene-v${v}.json`);
      expect(JSON.parse(JSON.stringify(scene))).toEqual(JSON.parse(text(`expected/lighting-scene-v${v}.json`)));
    });
  }
});

describe('catalogs', () => {
  // The catalog format changed within format 1 before luxbox had users (2026-11-23: the power feed
  // became a feed kit with drivers of rated capacity); a catalog of that first day is refused with
  // the field named, not read with made-up driver capacities (CHANGELOG.md, 0.1.0).
  it('the first-day catalog (format 1, 2026-11-23) is refused naming the field that changed', () => {
    expect(() => parseCatalog(JSON.parse(text('catalog-v1-2026-11-23.json')), 'catalog-v1-2026-11-23.json')).toThrow("catalog-v1-2026-11-23.json: powerFeed: unknown field 'powerFeed'");
  });
});
