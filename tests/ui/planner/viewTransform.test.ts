import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { MAX_SCALE, MIN_SCALE, centerOn, constrainPan, fitRoom, panBy, screenToWorld, wheelZoomFactor, worldToScreen, zoomAt } from '../../../src/ui/planner/viewTransform';

const viewArb = fc.record({
  scale: fc.double({ min: MIN_SCALE, max: MAX_SCALE, noNaN: true }),
  offsetX: fc.double({ min: -1e4, max: 1e4, noNaN: true }),
  offsetY: fc.double({ min: -1e4, max: 1e4, noNaN: true }),
});
const pointArb = fc.record({ x: fc.double({ min: -100, max: 100, noNaN: true }), z: fc.double({ min: -100, max: 100, noNaN: true }) });

describe('viewTransform', () => {
  it('screenToWorld inverts worldToScreen (1e-9 m)', () => {
    fc.assert(
      fc.property(viewArb, pointArb, (view, p) => {
        const back = screenToWorld(view, worldToScreen(view, p));
        expect(back.x).toBeCloseTo(p.x, 9);
        expect(back.z).toBeCloseTo(p.z, 9);
      }),
      { seed: 42, numRuns: 500 },
    );
  });

  it('maps plan y to world z, downwards on screen', () => {
    const view = { scale: 100, offsetX: 10, offsetY: 20 };
    expect(worldToScreen(view, { x: 1, z: 2 })).toEqual({ sx: 110, sy: 220 });
  });

  it('zoomAt keeps the anchored world point fixed on screen (1e-6 px)', () => {
    fc.assert(
      fc.property(viewArb, fc.double({ min: 0.01, max: 100, noNaN: true }), fc.double({ min: 0, max: 2000, noNaN: true }), fc.double({ min: 0, max: 2000, noNaN: true }), (view, factor, sx, sy) => {
        const anchor = { sx, sy };
        const before = screenToWorld(view, anchor);
        const zoomed = zoomAt(view, anchor, factor);
        const after = worldToScreen(zoomed, before);
        expect(Math.abs(after.sx - sx)).toBeLessThan(1e-6 * Math.max(1, Math.abs(sx)) * 10);
        expect(Math.abs(after.sy - sy)).toBeLessThan(1e-6 * Math.max(1, Math.abs(sy)) * 10);
        expect(zoomed.scale).toBeGreaterThanOrEqual(MIN_SCALE);
        expect(zoomed.scale).toBeLessThanOrEqual(MAX_SCALE);
      }),
      { seed: 7, numRuns: 500 },
    );
  });

  it('fitRoom centres the room with the margin on the tighter axis', () => {
    const v = fitRoom({ width: 5, depth: 4 }, { width: 1000, height: 600 }, 50);
    // Height is tighter: (600 - 100) / 4 = 125 px/m; room is 625 px wide, centred.
    expect(v.scale).toBeCloseTo(125, 12);
    expect(worldToScreen(v, { x: 0, z: 0 })).toEqual({ sx: 187.5, sy: 50 });
    expect(worldToScreen(v, { x: 5, z: 4 })).toEqual({ sx: 812.5, sy: 550 });
  });

  it('wheel zoom in then out by the same delta returns to the same scale', () => {
    const v = { scale: 100, offsetX: 0, offsetY: 0 };
    const a = { sx: 300, sy: 200 };
    const back = zoomAt(zoomAt(v, a, wheelZoomFactor(-120)), a, wheelZoomFactor(120));
    expect(back.scale).toBeCloseTo(100, 10);
    expect(back.offsetX).toBeCloseTo(0, 9);
    expect(wheelZoomFactor(-120)).toBeGreaterThan(1);
  });

  it('centerOn and panBy', () => {
    const v = centerOn({ x: 2, z: 1 }, 200, { width: 400, height: 300 });
    expect(worldToScreen(v, { x: 2, z: 1 })).toEqual({ sx: 200, sy: 150 });
    expect(panBy(v, 5, -3)).toEqual({ scale: 200, offsetX: v.offsetX + 5, offsetY: v.offsetY - 3 });
  });

  it('constrainPan keeps part of the room reachable', () => {
    const far = constrainPan({ scale: 100, offsetX: 5000, offsetY: -5000 }, { width: 5, depth: 4 }, { width: 800, height: 600 }, 64);
    expect(far.offsetX).toBe(800 - 64);
    expect(far.offsetY).toBe(64 - 400);
  });
});
