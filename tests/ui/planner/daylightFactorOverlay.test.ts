/**
 * The plan's daylight-factor overlay as a state (issue 30; docs/daylight.md "The daylight-factor
 * map on the plan"), on a real bake service (headless-gl, 'fast' quality, unfenced slices on a
 * manual queue, as tests/engines/view/bakeService.test.ts drives it): on and attached, the service
 * shows the 'daylight-factor' light, the overlay says "computing" until the engine settles and
 * then holds the grid of the shared work-plane function on the engine's maps; off or detached, the
 * service's light is given back; a moved window lights a new grid; a scene without a sky is "no-sky";
 * no bake feed is "unavailable".
 */
import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import { glazingFrom } from '../../../src/core/daylight/glazing';
import { cieGeneralSky, CIE_CLEAR_SKY_TYPE, groundLuminance } from '../../../src/core/daylight/skies';
import { sunDirection } from '../../../src/core/daylight/solarPosition';
import { createConfiguration } from '../../../src/core/model/configuration/configuration';
import type { Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import type { RoomInput } from '../../../src/core/room/roomInput';
import { createConfiguratorStore } from '../../../src/core/store/createConfiguratorStore';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import type { BakeDaylight } from '../../../src/engines/bake/daylight/bakeDaylight';
import { daylightFactorDaylight, workPlaneDaylight } from '../../../src/engines/bake/daylight/workPlaneDaylightFactor';
import { createBakeService, type VisibilitySource } from '../../../src/engines/view/createBakeService';
import { createHeadlessGL } from '../../../src/hosts/node/createHeadlessGL';
import { createDaylightFactorOverlay, GRID_DEBOUNCE_MS } from '../../../src/ui/planner/daylightFactorOverlay';
import type { BakeFeed } from '../../../src/ui/viewer/startBakeFeed';
import { DAYLIGHT_BOX_WINDOW, daylightBox } from '../../../src/hosts/bench/daylightBox';
import { shapedBakeRoom } from '../../engines/bake/shapedRoomKit';

// The daylight box with its window moved along the south wall.
const room = (offset: number): RoomInput => ({ ...daylightBox(), openings: [{ ...DAYLIGHT_BOX_WINDOW, offset }] });

function daylight(): BakeDaylight {
  const s = sunDirection(40, 200) as Vec3;
  return { sky: cieGeneralSky(CIE_CLEAR_SKY_TYPE, s, 12_000), sun: { direction: s, normalIlluminance: 60_000 }, groundLuminance: groundLuminance(12_000, 60_000 * s[1], 0.2), glazing: new Map([[0, glazingFrom('double')]]) };
}

const scene = (offset: number, withSky = true): BakeScene => ({ room: shapedBakeRoom(room(offset)), luminaires: [], ...(withSky ? { daylight: daylight() } : {}) });

/** Callbacks queued (the service's slices, the overlay's debounce), run in order by drain; a cancelled one is skipped. */
function manualQueue() {
  const pending: { run: () => void; ms: number; cancelled: boolean }[] = [];
  const delays: number[] = [];
  return {
    defer: (run: () => void, ms = 0) => {
      pending.push({ run, ms, cancelled: false });
    },
    delay: (run: () => void, ms: number) => {
      const entry = { run, ms, cancelled: false };
      delays.push(ms);
      pending.push(entry);
      return () => {
        entry.cancelled = true;
      };
    },
    delays,
    drain(limit = 100_000) {
      for (let n = 0; pending.length > 0 && n < limit; n++) {
        const e = pending.shift()!;
        if (!e.cancelled) e.run();
      }
    },
  };
}

function setUp() {
  const gl = createHeadlessGL();
  const q = manualQueue();
  const canvas = () => ({ getContext: () => gl, addEventListener: () => {}, removeEventListener: () => {} });
  const page = { hidden: false, addEventListener: () => {}, removeEventListener: () => {} } as unknown as VisibilitySource;
  const service = createBakeService({ quality: 'fast', visibility: page, input: null, canvas, defer: q.defer, fence: null });
  const feed: BakeFeed = { service, latest: () => null, error: () => null, pending: () => false, subscribe: () => () => undefined, dispose: () => service.dispose() };
  const store = createConfiguratorStore({ catalog: defaultCatalog, initial: createConfiguration() });
  const slices = (next: () => void) => {
    next();
    return () => undefined;
  };
  const overlay = createDaylightFactorOverlay(store, () => Promise.resolve(feed), { schedule: slices, delay: q.delay });
  return {
    service,
    overlay,
    q,
    dispose: () => {
      service.dispose();
      gl.getExtension('STACKGL_destroy_context')?.destroy();
    },
  };
}

/** Lets the feed's promise resolve (the overlay takes the service in a then). */
const settle = () => new Promise((resolve) => setTimeout(resolve, 0));

describe('the plan’s daylight-factor overlay', () => {
  it('asks the service for the daylight factor while on and attached, lights the grid from its maps, and gives the light back', async () => {
    const { service, overlay, q, dispose } = setUp();
    try {
      service.setScene(scene(1.75));
      q.drain();
      expect(service.lightSources).toBe('both');
      expect(overlay.snapshot()).toEqual({ on: false, phase: 'off', grid: null });

      // On but the plan not shown: nothing asked of the service.
      overlay.setOn(true);
      await settle();
      expect(service.lightSources).toBe('both');
      const detach = overlay.attach();
      await settle();
      expect(service.lightSources).toBe('daylight-factor');
      expect(overlay.snapshot().phase).toBe('computing');
      q.drain();
      const { phase, grid } = overlay.snapshot();
      expect(phase).toBe('ready');
      expect(q.delays.every((ms) => ms === GRID_DEBOUNCE_MS)).toBe(true);
      // The grid is the shared work-plane function on the engine's settled 'daylight-factor' maps.
      const engine = service.engine!;
      expect(engine.progress.done).toBe(true);
      expect(grid!.version).toBe(engine.version);
      const lux = workPlaneDaylight(service.scene!, service.objects()!, engine.maps().maps.objects!, daylightFactorDaylight(service.scene!.daylight!));
      expect(grid!.values.length).toBe(lux.length);
      lux.forEach((e, i) => expect(Math.abs(grid!.values[i] - e / 100)).toBeLessThan(1e-6));
      expect(grid!.statistics.mean).toBeGreaterThan(0.5);

      // A window moved: "computing", then a new grid of the new light.
      // (In the app the configuration's change says so at once, the feed then pending; here the service's first slice does.)
      service.setScene(scene(0.5));
      q.drain(1);
      expect(overlay.snapshot().phase).toBe('computing');
      q.drain();
      const moved = overlay.snapshot().grid!;
      expect(overlay.snapshot().phase).toBe('ready');
      expect(moved.version).toBeGreaterThan(grid!.version);
      // The window now sits near x = 0.5 … 2 m (wall 2 runs from (5, 4) to (0, 4)): the west end of the window's side is brighter than before.
      const westNearWindow = (g: typeof moved) => Math.max(...g.values.filter((_, i) => g.points[i][0] < 1.5 && g.points[i][1] > 3));
      const eastNearWindow = (g: typeof moved) => Math.max(...g.values.filter((_, i) => g.points[i][0] > 3.5 && g.points[i][1] > 3));
      expect(westNearWindow(moved) / eastNearWindow(moved)).not.toBeCloseTo(westNearWindow(grid!) / eastNearWindow(grid!), 1);

      // Detached (the plan left for the 3D view): the service's light back; attached again: asked again.
      detach();
      expect(service.lightSources).toBe('both');
      const again = overlay.attach();
      await settle();
      expect(service.lightSources).toBe('daylight-factor');
      // Off: the light back, the layer gone.
      overlay.setOn(false);
      expect(service.lightSources).toBe('both');
      expect(overlay.snapshot()).toEqual({ on: false, phase: 'off', grid: moved });
      again();
    } finally {
      dispose();
    }
  });

  it('says when the scene has no sky, and when there is no bake service', async () => {
    const { service, overlay, q, dispose } = setUp();
    try {
      service.setScene(scene(1.75, false));
      q.drain();
      overlay.setOn(true);
      const detach = overlay.attach();
      await settle();
      q.drain();
      expect(overlay.snapshot().phase).toBe('no-sky');
      expect(overlay.snapshot().grid).toBeNull();
      detach();
    } finally {
      dispose();
    }
    const store = createConfiguratorStore({ catalog: defaultCatalog, initial: createConfiguration() });
    const none = createDaylightFactorOverlay(store, () => null);
    none.setOn(true);
    const detach = none.attach();
    expect(none.snapshot().phase).toBe('unavailable');
    detach();
  });
});
