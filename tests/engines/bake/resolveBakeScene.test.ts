import { describe, expect, it } from 'vitest';
import type { LightingScene, SurfaceName } from '../../../src/core/model/lightingScene/lightingScene';
import { PhotometryReadError } from '../../../src/core/photometry/PhotometryReadError';
import type { Photometry } from '../../../src/core/photometry/types';
import { LuminairePhotometryError, resolveBakeScene, resolveBakeSceneSync } from '../../../src/engines/bake/resolveBakeScene';

const reflectance = { floor: 0.2, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } as Record<SurfaceName, number>;

/** Stands in for a parsed file: resolveBakeScene only passes photometry through. */
const fake = (name: string) => ({ luminaire: name }) as unknown as Photometry;

function scene(paths: string[], extra: Partial<LightingScene> = {}): LightingScene {
  return {
    version: 1,
    room: { width: 4, height: 2.5, depth: 3, reflectance },
    luminaires: paths.map((photometry, i) => ({ photometry, position: [i, 2, 1], yaw: 10 * i, pitch: 0, roll: 0 })),
    ...extra,
  };
}

describe('resolveBakeScene', () => {
  it('fills dimming and colour defaults, keeps given values and the near-field model', async () => {
    const s = scene(['a.ies', 'b.ies'], { version: 2, nearField: 'point' });
    s.luminaires[1] = { ...s.luminaires[1], dimming: 0.25, color: [1, 0.5, 0.2], id: 'm7' };
    const out = await resolveBakeScene(s, async (p) => fake(p));
    expect(out.room).toBe(s.room);
    expect(out.nearField).toBe('point');
    expect(out.luminaires).toEqual([
      { photometry: fake('a.ies'), position: [0, 2, 1], yaw: 0, pitch: 0, roll: 0, dimming: 1, color: [1, 1, 1] },
      { photometry: fake('b.ies'), position: [1, 2, 1], yaw: 10, pitch: 0, roll: 0, dimming: 0.25, color: [1, 0.5, 0.2] },
    ]);
    expect('nearField' in (await resolveBakeScene(scene(['a.ies']), async (p) => fake(p)))).toBe(false);
  });

  it('loads each distinct path once, in first-use order, and shares the parsed object', async () => {
    const asked: string[] = [];
    const out = await resolveBakeScene(scene(['a.ies', 'b.ies', 'a.ies', 'a.ies', 'b.ies']), async (p) => {
      asked.push(p);
      return fake(p);
    });
    expect(asked).toEqual(['a.ies', 'b.ies']);
    expect(out.luminaires[3].photometry).toBe(out.luminaires[0].photometry);
    expect(out.luminaires[4].photometry).toBe(out.luminaires[1].photometry);
  });

  it('a synchronous loader gives the scene at once (resolveBakeSceneSync)', () => {
    const out = resolveBakeSceneSync(scene(['a.ies']), (p) => fake(p));
    expect(out.luminaires).toHaveLength(1);
  });

  it('a scene without luminaires still gives a promise (an empty shop room opens in 3D)', async () => {
    const result = resolveBakeScene(scene([]), async (p) => fake(p));
    expect(result).toBeInstanceOf(Promise);
    expect((await result).luminaires).toEqual([]);
  });

  it('a failure names the first luminaire using the file and the file, and keeps the cause', async () => {
    const cause = new PhotometryReadError('ies/gone.ies', 'HTTP 404');
    const load = async (p: string) => {
      if (p === 'ies/gone.ies') throw cause;
      return fake(p);
    };
    const error = await resolveBakeScene(scene(['ies/ok.ies', 'ies/gone.ies', 'ies/gone.ies']), load).catch((e: unknown) => e);
    expect(error).toBeInstanceOf(LuminairePhotometryError);
    expect(error).toMatchObject({ luminaire: 1, path: 'ies/gone.ies', cause, message: 'luminaires[1].photometry: ies/gone.ies: HTTP 404' });
    // A cause that does not name the file gets it added.
    expect(() =>
      resolveBakeSceneSync(scene(['x.ies']), () => {
        throw new Error('boom');
      }),
    ).toThrow('luminaires[0].photometry: x.ies: boom');
  });
});
