import { describe, expect, it, vi } from 'vitest';

// The daylight fields read with the browser build's zod (the shim on zod/mini), as
// frozenFormatsOnMini.test.ts reads the frozen files: a schema method the shim lacks throws only there.
vi.mock('zod', async () => await import('../../../../src/core/zodClassicOnMini'));

const { parseLightingScene } = await import('../../../../src/core/model/lightingScene/parseLightingScene');

const room = { width: 5, height: 2.8, depth: 4, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } };

describe('daylight on the zod shim', () => {
  it('reads version-2 windows and a clear sky with the sun, version-3 glazing, and refuses as on classic zod', async () => {
    const { z } = await import('zod');
    expect((z.string() as unknown as Record<string, unknown>).email).toBeUndefined();
    const two = parseLightingScene(
      { version: 2, room, luminaires: [], windows: [{ wall: 'south', u: 1, v: 0.9, width: 1.5, height: 1.4, transmittance: 0.7 }], sky: { type: 'cie-clear', sun: { city: 'Zurich', date: '2026-06-21', time: '10:00' } } },
      's',
    );
    expect(two.daylight?.transmittance).toEqual({ 0: 0.7 });
    expect(two.daylight?.sky?.sun?.city).toBe('Zurich');
    const three = parseLightingScene(
      {
        version: 3,
        room: {
          outline: [
            [0, 0],
            [5, 0],
            [5, 4],
            [0, 4],
          ],
          height: 2.8,
          openings: [{ wall: 2, offset: 1, width: 1, sill: 1, height: 1, kind: 'window', transmittance: 'triple' }],
          reflectance: { floor: 0.2, ceiling: 0.8, walls: 0.5 },
        },
        luminaires: [],
        sky: { type: 'cie-overcast' },
      },
      's',
    );
    expect(three.daylight?.transmittance).toEqual({ 0: 'triple' });
    expect(() => parseLightingScene({ version: 2, room, luminaires: [], sky: { type: 'cie-clear' } }, 'scene.json')).toThrow("scene.json: sky.sun: is missing: a clear sky needs the sun's place, date and time");
  });
});
