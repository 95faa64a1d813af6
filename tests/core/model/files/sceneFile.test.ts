import { describe, expect, it } from 'vitest';
import { createHistory, pushHistory, redo, undo } from '../../../../src/core/model/configuration/history';
import { deserializeConfiguration, serializeConfiguration } from '../../../../src/core/model/files/sceneFile';
import { SceneFileError } from '../../../../src/core/model/files/sceneFileError';
import { decodeShareString, encodeShareString } from '../../../../src/core/model/files/shareLink';
import { SCENE_FILE_VERSION } from '../../../../src/core/model/files/sceneFileSchema';
import { catalog, run, withPreset } from '../helpers';

const sample = () => run(withPreset('snake', 1, 4), 'placePreset', { presetId: 'single', x: 5, z: 5 });

describe('scene file', () => {
  it('round-trips through JSON and through a share string', () => {
    const s = sample();
    expect(deserializeConfiguration(serializeConfiguration(s, catalog), catalog)).toEqual(s);
    const share = encodeShareString(s, catalog);
    expect(share).toMatch(/^[A-Za-z0-9_-]+$/);
    expect(decodeShareString(share, catalog)).toEqual(s);
  });
  const file = () => JSON.parse(serializeConfiguration(sample(), catalog));
  const reject = (text: string, msg: RegExp) => {
    expect(() => deserializeConfiguration(text, catalog)).toThrow(SceneFileError);
    expect(() => deserializeConfiguration(text, catalog)).toThrow(msg);
  };
  it('rejects corrupt and foreign files with clear messages', () => {
    reject('{"format":', /not valid JSON/);
    reject('[1,2]', /expected a JSON object/);
    reject(JSON.stringify({ version: 1, room: {}, luminaires: [] }), /is a lighting scene/);
    reject(JSON.stringify({ ...file(), format: 'other' }), /format must be 'luxbox-configuration'/);
    reject(JSON.stringify({ ...file(), version: SCENE_FILE_VERSION + 1 }), new RegExp(`newer luxbox \\(version ${SCENE_FILE_VERSION + 1}`));
    reject(JSON.stringify({ ...file(), catalog: 'acme' }), /made for catalog 'acme'/);
    const f = file();
    f.configuration.systems[0].rails[1].length = 'long';
    reject(JSON.stringify(f), /configuration\.systems\[0\]\.rails\[1\]\.length: /);
    const g = file();
    g.configuration.systems[1].x = 7; // the 1.5 m rail would reach x = 8.5 in the 8 m room
    reject(JSON.stringify(g), /configuration\.systems\[1\]: system s\d+ reaches outside/);
    const h = file();
    h.configuration.systems[0].rails[0].modules[0].cct = 6500;
    reject(JSON.stringify(h), /modules\[0\]\.cct: Spot is not available in 6500 K/);
  });
  it('rejects damaged share strings', () => {
    const share = encodeShareString(sample(), catalog);
    expect(() => decodeShareString('', catalog)).toThrow(/empty/);
    expect(() => decodeShareString(share.slice(0, 40) + '!', catalog)).toThrow(/outside base64url/);
    expect(() => decodeShareString(share.slice(0, 101), catalog)).toThrow(SceneFileError);
    expect(() => decodeShareString(share.slice(0, share.length - 8), catalog)).toThrow(/share link/);
    expect(() => decodeShareString('_w', catalog)).toThrow(/not UTF-8/);
  });
});

describe('history', () => {
  it('undo/redo round-trips and a new action clears redo', () => {
    const a = withPreset('single', 1, 1);
    const b = run(a, 'moveSystem', { systemId: a.systems[0].id, x: 2, z: 2 });
    const c = run(b, 'rotateSystem', { systemId: a.systems[0].id, by: 90 });
    let h = pushHistory(pushHistory(createHistory(a), b), c);
    h = undo(undo(h));
    expect(h.present).toBe(a);
    expect(undo(h)).toBe(h);
    h = redo(h);
    expect(h.present).toBe(b);
    h = pushHistory(h, c);
    expect(h.future).toEqual([]);
    expect(redo(h)).toBe(h);
    let big = createHistory(0);
    for (let i = 1; i <= 5; i++) big = pushHistory(big, i, 3);
    expect(big.past).toEqual([2, 3, 4]);
  });
});
