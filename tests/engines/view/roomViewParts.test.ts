/** The pure parts of the room view: surface quads, the track's pieces, the shader's level array, presentMaps. */
import { describe, expect, it } from 'vitest';
import { IDENTITY3 } from '../../../src/engines/view/cat16';
import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../../src/core/model/lightingScene/lightingScene';
import { surfaceLayouts, texelCentre } from '../../../src/engines/bake/surfaceLayout';
import { emptyLitMaps } from '../../../src/engines/relight/relightMaps';
import { autoExposure } from '../../../src/engines/view/autoExposure';
import { luxLevels, MAX_LEVELS, shaderLevels } from '../../../src/engines/view/falseColorScale';
import { RAIL_HEIGHT } from '../../../src/engines/view/fixtures';
import { trackPieces } from '../../../src/engines/view/luminaires/trackParts';
import { luxScaleTop } from '../../../src/engines/view/luxScaleTop';
import { ev100FromExposure } from '../../../src/engines/view/photographicExposure';
import { presentMaps } from '../../../src/engines/view/presentMaps';
import type { RoomView } from '../../../src/engines/view/roomView';
import { surfaceQuad } from '../../../src/engines/view/surfaceQuad';

const room = { width: 4, height: 2.5, depth: 3 };

describe('surfaceQuad', () => {
  it("covers each surface with uv following the baker's texel grid, both triangles facing into the room", () => {
    for (const l of surfaceLayouts(room, 0.25, 64)) {
      const q = surfaceQuad(l);
      const corner = (k: number) => q.positions.slice(3 * k, 3 * k + 3);
      // Bilinear position at a texel centre's uv equals the baker's texel centre.
      const [i, j] = [l.width - 1, 0];
      const [u, v] = [(i + 0.5) / l.width, (j + 0.5) / l.height];
      const at = [0, 1, 2].map((a) => (1 - u) * (1 - v) * corner(0)[a] + u * (1 - v) * corner(1)[a] + u * v * corner(2)[a] + (1 - u) * v * corner(3)[a]);
      texelCentre(l, i, j).forEach((x, a) => expect(at[a]).toBeCloseTo(x, 12));
      expect(q.uvs).toEqual([0, 0, 1, 0, 1, 1, 0, 1]);
      for (let t = 0; t < 2; t++) {
        const [a, b, c] = q.index.slice(3 * t, 3 * t + 3).map(corner);
        const e1 = b.map((x, k) => x - a[k]);
        const e2 = c.map((x, k) => x - a[k]);
        const n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
        expect(n[0] * l.normal[0] + n[1] * l.normal[1] + n[2] * l.normal[2], `${l.name} triangle ${t}`).toBeGreaterThan(0);
      }
    }
  });
});

describe('trackPieces', () => {
  it('a rail is a U-channel of the catalog width and RAIL_HEIGHT along its run; a cable a wire from ceiling to rail top with canopy and gripper; none of zero length', () => {
    const pieces = trackPieces({
      rails: [{ start: [1, 2.2, 1], end: [1, 2.2, 3] }],
      railWidth: 0.05,
      connectors: [],
      modules: [],
      cables: [
        { top: [1, 2.5, 1], bottom: [1, 2.22, 1] },
        { top: [1, 2.5, 3], bottom: [1, 2.5, 3] },
      ],
    });
    expect(pieces.map((p) => p.role)).toEqual(['housing', 'housing', 'housing', 'cable', 'housing', 'cable']);
    const box = (k: number) => {
      pieces[k].geometry.computeBoundingBox();
      return pieces[k].geometry.boundingBox!;
    };
    const rail = box(0).union(box(1)).union(box(2));
    // Turned onto world +z: 2 m along z, 50 mm across x, RAIL_HEIGHT tall round y = 2.2.
    expect(rail.max.z - rail.min.z).toBeCloseTo(2, 6);
    expect(rail.max.x - rail.min.x).toBeCloseTo(0.05, 6);
    expect(rail.max.y - rail.min.y).toBeCloseTo(RAIL_HEIGHT, 6);
    expect((rail.max.y + rail.min.y) / 2).toBeCloseTo(2.2, 6);
    const wire = box(3);
    expect(wire.max.y - wire.min.y).toBeCloseTo(0.28, 6);
    expect(wire.max.z - wire.min.z).toBeCloseTo(0.002, 6);
  });
});

describe('shaderLevels', () => {
  it('the first MAX_LEVELS positive levels and their count; the rest of the array 1', () => {
    expect(shaderLevels([10, 0, 20, -5, 50])).toEqual({ count: 3, values: [10, 20, 50, ...new Array(MAX_LEVELS - 3).fill(1)] });
    const many = Array.from({ length: MAX_LEVELS + 4 }, (_, i) => i + 1);
    expect(shaderLevels(many)).toEqual({ count: MAX_LEVELS, values: many.slice(0, MAX_LEVELS) });
    expect(shaderLevels([]).count).toBe(0);
  });
});

describe('presentMaps', () => {
  it('maps, auto exposure × 2^EV, and the mode with levels up to the scale top, in that order', () => {
    const lit = emptyLitMaps(surfaceLayouts(room, 0.5, 16));
    SURFACE_NAMES.forEach((name, k) => lit.maps[name].total.fill(50 * (k + 1)));
    const reflectance = Object.fromEntries(SURFACE_NAMES.map((n) => [n, [0.5, 0.5, 0.5]])) as Record<SurfaceName, Rgb>;
    const calls: unknown[][] = [];
    const view = {
      setMaps: (...a: unknown[]) => calls.push(['maps', ...a]),
      setExposure: (...a: unknown[]) => calls.push(['exposure', ...a]),
      setAdaptation: (...a: unknown[]) => calls.push(['adaptation', ...a]),
      setMode: (...a: unknown[]) => calls.push(['mode', ...a]),
      setObjectLight: (...a: unknown[]) => calls.push(['objects', ...a]),
    } as unknown as RoomView;
    const shown = presentMaps(view, lit, reflectance, { exposureEv: -1, mode: 'lux' });
    const auto = autoExposure(lit, reflectance);
    const levels = luxLevels(luxScaleTop(lit));
    // No white lamp given: nothing to adapt to, the identity.
    expect(shown).toEqual({ autoExposure: auto, target: { auto, white: null }, exposure: auto / 2, ev100: ev100FromExposure(auto / 2), adaptation: { matrix: IDENTITY3, d: 0, white: null }, levels });
    expect(calls).toEqual([
      ['maps', lit, reflectance],
      ['objects', null],
      ['exposure', auto / 2],
      ['adaptation', IDENTITY3],
      ['mode', 'lux', levels],
    ]);
  });
});
