/**
 * The planner bundle's bake host (docs/viewer.md, "Always ready: the bake service"): one per
 * store, started in idle time (never where WebGL2 is missing: here, Node has no document), its
 * status readable through view3d()'s registry before the service runs, released on dispose.
 */
import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import { createConfiguration } from '../../../src/core/model/configuration/configuration';
import { createConfiguratorStore } from '../../../src/core/store/createConfiguratorStore';
import { bakeHostFor, bakeHostOf, createBakeHost } from '../../../src/ui/viewer/bakeHost';
import { initialQuality } from '../../../src/ui/viewer/qualityPreference';
import { getViewerStatus, IDLE_BAKE } from '../../../src/ui/viewer/viewerStatus';

const noPhotometry = () => Promise.reject(new Error('not used'));
const store = () => createConfiguratorStore({ catalog: defaultCatalog, initial: createConfiguration() });

describe('bake host', () => {
  it('registers per store; the status shows the pinned level before the service runs; dispose unregisters', () => {
    const a = store();
    const b = store();
    expect(bakeHostOf(a)).toBeNull();
    const host = createBakeHost(a, noPhotometry, { quality: 'best' });
    expect(bakeHostOf(a)).toBe(host);
    expect(bakeHostOf(b)).toBeNull();
    expect(bakeHostFor(a, noPhotometry)).toBe(host);
    expect(host.quality).toBe('best');
    expect(host.current()).toBeNull();
    expect(getViewerStatus(a).bake).toEqual({ ...IDLE_BAKE, quality: 'best' });
    // The user's choice applies (not remembered: nothing to store here).
    host.setQuality('fast');
    expect(host.quality).toBe('fast');
    expect(getViewerStatus(a).bake.quality).toBe('fast');
    host.dispose();
    expect(bakeHostOf(a)).toBeNull();
    expect(getViewerStatus(a).bake).toEqual(IDLE_BAKE);
  });

  it('the idle start can be cancelled, and without WebGL2 the idle start loads nothing', () => {
    const s = store();
    const pending: (() => void)[] = [];
    let cancelled = 0;
    const idle = (f: () => void) => {
      pending.push(f);
      return () => cancelled++;
    };
    const host = createBakeHost(s, noPhotometry, { idle });
    const cancel = host.startWhenIdle();
    expect(pending).toHaveLength(1);
    cancel();
    expect(cancelled).toBe(1);
    host.startWhenIdle();
    pending[1]();
    // webglSupportProblem() has no document in Node: no chunk, no service.
    expect(host.current()).toBeNull();
    expect(getViewerStatus(s).bake.running).toBe(false);
    host.dispose();
    expect(host.startWhenIdle()).toBeTypeOf('function');
    expect(pending).toHaveLength(2);
  });

  it('the starting level: the pin, else the remembered choice (only when remembering), else the device calibration', () => {
    expect(initialQuality('fast', true)).toBe('fast');
    expect(initialQuality(null, false)).toBe('device');
    // No localStorage in Node: nothing remembered.
    expect(initialQuality(undefined, true)).toBe('device');
    expect(createBakeHost(store(), noPhotometry).quality).toBe('balanced'); // shown until the calibration has run
  });
});
