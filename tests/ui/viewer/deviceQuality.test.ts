/**
 * The stored device calibration (src/ui/viewer/deviceQuality.ts): used only when it is this
 * renderer's and complete; an entry an older luxbox wrote (fields missing) is refused, so the page
 * calibrates again instead of falling back to 'balanced' on every load.
 */
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { CALIBRATION_STORAGE_KEY, readCachedCalibration } from '../../../src/ui/viewer/deviceQuality';

const complete = {
  msPerTexelSample: 2e-5,
  msPerTexelSource: 1e-5,
  msPerTexelBasis: 1e-4,
  directCompileMs: 40,
  compileMs: 300,
  renderer: 'ANGLE (Test GPU)',
  work: { texels: 19200, pointSources: 10, samples: 8, bounces: 1 },
};

const store = new Map<string, string>();
beforeEach(() => {
  store.clear();
  (globalThis as { localStorage?: Pick<Storage, 'getItem' | 'setItem'> }).localStorage = {
    getItem: (k) => store.get(k) ?? null,
    setItem: (k, v) => void store.set(k, v),
  };
});
afterEach(() => {
  delete (globalThis as { localStorage?: unknown }).localStorage;
});

describe('stored device calibration', () => {
  it('is used for its own renderer when complete', () => {
    store.set(CALIBRATION_STORAGE_KEY, JSON.stringify(complete));
    expect(readCachedCalibration('ANGLE (Test GPU)')).toEqual(complete);
    expect(readCachedCalibration('ANGLE (Other GPU)')).toBeNull();
  });

  it('an outdated entry (no per-basis or compile cost) or garbage is refused: calibrate again', () => {
    const { msPerTexelBasis: _b, directCompileMs: _c, ...old } = complete;
    store.set(CALIBRATION_STORAGE_KEY, JSON.stringify(old));
    expect(readCachedCalibration('ANGLE (Test GPU)')).toBeNull();
    store.set(CALIBRATION_STORAGE_KEY, '{not json');
    expect(readCachedCalibration('ANGLE (Test GPU)')).toBeNull();
    store.set(CALIBRATION_STORAGE_KEY, JSON.stringify({ ...complete, msPerTexelSample: -1 }));
    expect(readCachedCalibration('ANGLE (Test GPU)')).toBeNull();
  });
});
