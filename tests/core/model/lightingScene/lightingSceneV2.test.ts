/** Lighting scene version 2 (docs/scene-format.md "Version 2"): nearField, version rules, strict fields. */
import { describe, expect, it } from 'vitest';
import { LightingSceneError, parseLightingScene } from '../../../../src/core/model/lightingScene/parseLightingScene';

const scene = (extra: Record<string, unknown> = {}, luminaire: Record<string, unknown> = {}) => ({
  version: 2,
  room: { width: 5, height: 2.8, depth: 4, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } },
  luminaires: [{ photometry: 'a.ies', position: [2.5, 2.7, 2], ...luminaire }],
  ...extra,
});
const refusal = (json: unknown): string => {
  try {
    parseLightingScene(json, 'scene.json');
  } catch (error) {
    expect(error).toBeInstanceOf(LightingSceneError);
    return (error as Error).message;
  }
  throw new Error('accepted');
};

describe('lighting scene version 2', () => {
  it('reads nearField and keeps the version', () => {
    expect(parseLightingScene(scene({ nearField: 'point' }), 's').nearField).toBe('point');
    expect(parseLightingScene(scene({ nearField: 'split' }), 's').nearField).toBe('split');
    const plain = parseLightingScene(scene(), 's');
    expect(plain.version).toBe(2);
    expect(plain.nearField).toBeUndefined(); // default 'split' (DEFAULT_NEAR_FIELD)
  });

  it('still reads version 1 files', () => {
    expect(parseLightingScene(scene({ version: 1 }), 's').version).toBe(1);
  });

  it('accepts empty objects and windows lists', () => {
    expect(() => parseLightingScene(scene({ objects: [], windows: [] }), 's')).not.toThrow();
  });

  it.each([
    [scene({ nearField: 'far' }), 'scene.json: nearField: must be "split" or "point", got "far"'],
    [scene({ version: 1, nearField: 'point' }), 'scene.json: nearField: needs "version": 2 (this file says version 1)'],
    [scene({ version: 1, objects: [] }), 'scene.json: objects: needs "version": 2 (this file says version 1)'],
    [scene({ version: 7 }), 'scene.json: version: made by a newer luxbox (version 7; this one reads versions 1 to 3)'],
    [scene({ objects: [{ mesh: 'table.obj' }] }), 'scene.json: objects[0].position: must be [x, y, z] in metres, got undefined'],
    [scene({ windows: [{ wall: 'south' }] }), 'scene.json: windows[0].u: is missing'],
    [scene({ version: 1, sky: { type: 'uniform' } }), 'scene.json: sky: needs "version": 2 (this file says version 1)'],
    [scene({ nearFeild: 'point' }), "scene.json: nearFeild: unknown field 'nearFeild' (did you mean 'nearField'?)"],
    [scene({}, { dimmming: 0.5 }), "scene.json: luminaires[0].dimmming: unknown field 'dimmming' (did you mean 'dimming'?)"],
    [scene({}, { photometri: 'a.ies' }), "scene.json: luminaires[0].photometri: unknown field 'photometri' (did you mean 'photometry'?)"],
    [scene({ comment: 'x' }), "scene.json: comment: unknown field 'comment'"],
  ])('refuses %j', (json, message) => {
    expect(refusal(json)).toBe(message);
  });

  it('refuses unknown fields in room and reflectance', () => {
    const s = scene();
    (s.room as Record<string, unknown>).heigth = 3;
    expect(refusal(s)).toBe("scene.json: room.heigth: unknown field 'heigth' (did you mean 'height'?)");
    const t = scene();
    (t.room.reflectance as Record<string, unknown>).nort = 0.5;
    expect(refusal(t)).toBe("scene.json: room.reflectance.nort: unknown field 'nort' (did you mean 'north'?)");
  });

  it('refuses deep nesting and huge values in one short line', () => {
    let deep: unknown = 1;
    for (let i = 0; i < 5000; i++) deep = [deep];
    const message = refusal(scene({}, { dimming: deep }));
    expect(message).toMatch(/^scene\.json: luminaires\[0\]\.dimming(\[0\])+…?: nested deeper than 32 levels$/);
    const long = refusal(scene({}, { dimming: 'x'.repeat(100_000) }));
    expect(long.length).toBeLessThanOrEqual(200);
    expect(long).not.toContain('\n');
  });
});
