/** The pure parts of the room view: surface quads, hardware boxes, the shader's level array, presentMaps. */
import { describe, expect, it } from 'vitest';
import { IDENTITY3 } from '../../../src/engines/view/cat16';
import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../../src/core/model/lightingScene';
import { surfaceLayouts, texelCentre } from '../../../src/engines/bake/surfaceLayout';
import { emptyLitMaps } from '../../../src/engines/relight/relightMaps';
import { autoExposure } from '../../../src/engines/view/autoExposure';
import { luxLevels, MAX_LEVELS, shaderLevels } from '../../../src/engines/view/falseColorScale';
import { MODULE_HEIGHT, RAIL_HEIGHT } from '../../../src/engines/view/fixtures';
import { hardwareBoxes } from '../../../src/engines/view/hardwareBoxes';
import { luxScaleTop } from '../../../src/engines/view/luxScaleTop';
import { ev100FromExposure } from '../../../src/engines/view/photographicExposure';
import { presentMaps } from '../../../src/engines/view/presentMaps';
import type { RoomView } from '../../../src/engines/view/roomView';
import { surfaceQuad } from '../../../src/engines/view/surfaceQuad';

const room = { width: 4, height: 2.5, depth: 3 };

describe('surfaceQuad', () => {
  it('covers each surface with uv following the baker\'s texel grid, both triangles facing into the room', () => {
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

describe('hardwareBoxes', () => {
  it('rails along their run, modules on their photometric centre (turned by heading), cables ceiling to rail, none of zero length', () => {
    const boxes = hardwareBoxes({
      rails: [{ start: [1, 2.2, 1], end: [1, 2.2, 3] }],
      modules: [
        { id: 'm1', centre: [1, 2.1, 1.5], heading: 90, length: 0.3, on: true },
        { id: 'm2', centre: [1, 2.1, 2.5], heading: 0, length: 0.02, on: false },
      ],
      cables: [
        { top: [1, 2.5, 1], bottom: [1, 2.22, 1] },
        { top: [1, 2.5, 3], bottom: [1, 2.5, 3] },
      ],
    });
    expect(boxes.map((b) => b.part)).toEqual(['rail', 'moduleOn', 'moduleOff', 'cable']);
    const [rail, m1, m2, cable] = boxes;
    expect(rail.size[0]).toBeCloseTo(2, 12);
    expect(rail.size.slice(1)).toEqual([RAIL_HEIGHT, 0.05]);
    expect(rail.position).toEqual([1, 2.2, 2]);
    expect(rail.yaw).toBeCloseTo(-Math.PI / 2, 12); // local x turned onto world +z
    expect(m1).toMatchObject({ name: 'module:m1', yaw: Math.PI / 2 });
    expect(m1.size[0]).toBeCloseTo(0.294, 12);
    expect(m1.position[1]).toBeCloseTo(2.1 + MODULE_HEIGHT / 2, 12);
    expect(m2.size[0]).toBe(0.03); // never thinner than 3 cm
    expect(cable.size[1]).toBeCloseTo(0.28, 12);
    expect(cable.position[1]).toBeCloseTo(2.36, 12);
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
