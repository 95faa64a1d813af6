import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { beforeAll, describe, expect, it, vi } from 'vitest';

// The browser build resolves `zod` to the classic-API shim on zod/mini (vite.config.ts,
// src/core/zodClassicOnMini.ts); Node and the other tests use zod classic. A schema method the
// shim lacks type-checks and passes those tests, and throws only in the browser (version 3's
// `extend` stopped every background bake until the fresh-clone e2e caught it). Here the file
// readers run on the shim, as they ship, over the same frozen files as frozenFormats.test.ts.
vi.mock('zod', async () => await import('../../../../src/core/zodClassicOnMini'));

const { defaultCatalog } = await import('../../../../src/core/catalog/defaultCatalog');
const { parseLightingScene } = await import('../../../../src/core/model/lightingScene/parseLightingScene');
const { deserializeConfiguration, serializeConfiguration } = await import('../../../../src/core/model/files/sceneFile');
const { decodeShareString } = await import('../../../../src/core/model/files/shareLink');
const { loadColourFilterSpectra } = await import('../../../../src/core/colour/colourFilterSpectra');

const DIR = join(__dirname, '../../../fixtures/formats');
const text = (name: string) => readFileSync(join(DIR, name), 'utf8');
const files = readdirSync(DIR);
const named = (prefix: string, suffix: string) => files.filter((f) => f.startsWith(prefix) && f.endsWith(suffix));

beforeAll(loadColourFilterSpectra);

describe('frozen formats read with the browser build’s zod (the shim on zod/mini)', () => {
  it('runs on the shim, not on zod classic', async () => {
    const { z } = await import('zod');
    // Classic's strings have .email(); the shim leaves out every method luxbox does not use.
    expect((z.string() as unknown as Record<string, unknown>).email).toBeUndefined();
  });
  for (const f of named('lighting-scene-v', '.json')) {
    it(`${f} parses to its expected form`, () => {
      expect(JSON.parse(JSON.stringify(parseLightingScene(JSON.parse(text(f)), f)))).toEqual(JSON.parse(text(`expected/${f}`)));
    });
  }
  for (const f of named('configuration-v', '.luxbox.json')) {
    it(`${f} opens as its expected current form`, () => {
      expect(serializeConfiguration(deserializeConfiguration(text(f), defaultCatalog, f), defaultCatalog) + '\n').toBe(text(`expected/${f}`));
    });
  }
  for (const f of named('share-link-v', '.txt')) {
    it(`${f} opens as its expected configuration`, () => {
      const expected = text(`expected/${f.replace(/\.txt$/, '.luxbox.json')}`);
      expect(serializeConfiguration(decodeShareString(text(f).trim(), defaultCatalog), defaultCatalog) + '\n').toBe(expected);
    });
  }
});
