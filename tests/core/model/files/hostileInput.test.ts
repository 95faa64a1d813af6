/** Issue 18: hostile and odd input to the configurator's formats — one short line, never a crash, never a dropped field. */
import { describe, expect, it } from 'vitest';
import { CatalogError, parseCatalog } from '../../../../src/core/model/catalogSchema/catalogSchema';
import { configurationFromData, deserializeConfiguration, serializeConfiguration } from '../../../../src/core/model/files/sceneFile';
import { SceneFileError } from '../../../../src/core/model/files/sceneFileError';
import { decodeShareString, encodeShareString } from '../../../../src/core/model/files/shareLink';
import { SCENE_FILE_VERSION } from '../../../../src/core/model/files/sceneFileSchema';
import { duplicateKey, excerpt, jsonShapeProblem, oneLine } from '../../../../src/core/untrustedJson';
import { suggestField } from '../../../../src/core/zodIssues';
import catalogData from '../../../../src/core/catalog/default-catalog.json';
import { catalog, withPreset } from '../helpers';

const config = withPreset('snake', 1, 4);
const file = () => JSON.parse(serializeConfiguration(config, catalog));
const refusal = (text: string): string => {
  try {
    deserializeConfiguration(text, catalog, 'a.json');
  } catch (error) {
    expect(error).toBeInstanceOf(SceneFileError);
    const message = (error as Error).message;
    expect(message).not.toMatch(/[\r\n]/);
    expect(message.length).toBeLessThanOrEqual(200);
    return message;
  }
  throw new Error('accepted');
};
const base64url = (text: string) => Buffer.from(text, 'utf8').toString('base64url');

describe('configuration files', () => {
  it('refuses unknown fields, naming field and path with a suggestion', () => {
    const f = file();
    f.configuration.systems[0].rails[0].modules[0].dimmming = 0.5;
    expect(refusal(JSON.stringify(f))).toBe("a.json: configuration.systems[0].rails[0].modules[0].dimmming: unknown field 'dimmming' (did you mean 'dimming'?)");
    const g = file();
    g.comment = 'hello';
    expect(refusal(JSON.stringify(g))).toBe("a.json: comment: unknown field 'comment'");
  });

  it('refuses duplicated keys with line and column', () => {
    const text = serializeConfiguration(config, catalog).replace('"nextId"', '"nextId": 99,\n    "nextId"');
    expect(refusal(text)).toMatch(/^a\.json: line \d+, column 5: field 'nextId' appears twice in one object$/);
  });

  it('refuses deep nesting, huge arrays and huge files before validation', () => {
    const f = file();
    f.configuration.systems[0].joints = Array.from({ length: 490_271 }, () => ({ connector: 'x', turn: 0 }));
    expect(refusal(JSON.stringify(f).slice(0, 999_000))).toMatch(/not valid JSON/); // cut to fit 1 MB
    expect(() => configurationFromData(f, catalog, 'setConfig')).toThrow('setConfig: configuration.systems[0].joints: array of 490271 entries (at most 20000)');
    const deep = `{"format":"luxbox-configuration","version":1,"catalog":"x","configuration":${'['.repeat(5000)}${']'.repeat(5000)}}`;
    expect(refusal(deep)).toMatch(/^a\.json: configuration(\[0\])+…?: nested deeper than 32 levels$/);
    expect(refusal(' '.repeat(1_000_001))).toBe('a.json is too large to be a luxbox configuration (1.0 MB; at most 1 MB)');
  });

  it('says a newer version was made by a newer luxbox', () => {
    expect(refusal(JSON.stringify({ ...file(), version: SCENE_FILE_VERSION + 1, configuration: { hologram: true } }))).toBe(
      `a.json was made by a newer luxbox (version ${SCENE_FILE_VERSION + 1}; this one reads up to ${SCENE_FILE_VERSION})`,
    );
  });

  it('keeps syntax errors to one short line (no excerpt of the text)', () => {
    const message = refusal(`{"format":\n"${'x'.repeat(5000)}\n`);
    expect(message).toMatch(/^a\.json is not valid JSON \(/);
    expect(refusal(`x${'y'.repeat(5000)}`)).toBe("a.json is not valid JSON (Unexpected token 'x')");
  });
});

describe('share links', () => {
  it('are compact JSON, and indented links from before still decode', () => {
    const share = encodeShareString(config, catalog);
    expect(Buffer.from(share, 'base64url').toString('utf8')).toBe(serializeConfiguration(config, catalog, 0));
    const old = base64url(serializeConfiguration(config, catalog, 2));
    expect(share.length).toBeLessThan(old.length * 0.6);
    expect(decodeShareString(old, catalog)).toEqual(config);
    expect(decodeShareString(share, catalog)).toEqual(config);
  });

  it('refuse unknown fields', () => {
    const f = file();
    f.configuration.room.colour = 'red';
    expect(() => decodeShareString(base64url(JSON.stringify(f)), catalog)).toThrow("share link: configuration.room.colour: unknown field 'colour'");
  });
});

describe('catalog files', () => {
  it('refuse unknown fields and newer versions', () => {
    const c = structuredClone(catalogData) as Record<string, unknown> & { rail: Record<string, unknown> };
    c.rail.widht = 0.05;
    expect(() => parseCatalog(c, 'cat.json')).toThrow(CatalogError);
    expect(() => parseCatalog(c, 'cat.json')).toThrow("cat.json: rail.widht: unknown field 'widht' (did you mean 'width'?)");
    expect(() => parseCatalog({ ...catalogData, formatVersion: 4 }, 'cat.json')).toThrow('cat.json: formatVersion: made by a newer luxbox (version 4; this one reads up to 1)');
  });
});

describe('untrusted JSON helpers', () => {
  it('excerpt and oneLine bound what is quoted back', () => {
    expect(excerpt(Array.from({ length: 100_000 }, () => 1))).toBe(`[${'1,'.repeat(19)}1…`);
    expect(excerpt(NaN)).toBe('NaN');
    expect(excerpt('x'.repeat(1000)).length).toBeLessThanOrEqual(41);
    let deep: unknown = 1;
    for (let i = 0; i < 100_000; i++) deep = [deep];
    expect(excerpt(deep)).toBe(`${'['.repeat(40)}…`);
    expect(oneLine('a\nb\r\nc', 200)).toBe('a b c');
    expect(oneLine('x'.repeat(300)).length).toBe(200);
  });

  it('jsonShapeProblem walks 100 000 levels without recursion', () => {
    let deep: unknown = 1;
    for (let i = 0; i < 100_000; i++) deep = { a: deep };
    expect(jsonShapeProblem(deep)).toBe('a.a.a.a.a.a.a.a.a.a.a.a: nested deeper than 32 levels');
    expect(jsonShapeProblem({ list: [[1, 2], { b: [] }] })).toBeNull();
  });

  it('duplicateKey finds repeats per object, not across objects or in strings', () => {
    expect(duplicateKey('{"a":1,"b":{"a":2},"c":"\\"a\\":"}')).toBeNull();
    expect(duplicateKey('{"a":1,"b":[{"a":1,"a":2}]}')?.key).toBe('a');
    expect(duplicateKey('{"a":1,"\\u0061":2}')?.key).toBe('a');
  });

  it('suggests near misses only', () => {
    expect(suggestField('nearFeild', ['nearField', 'room'])).toBe('nearField');
    expect(suggestField('banana', ['nearField', 'room'])).toBeUndefined();
  });
});
