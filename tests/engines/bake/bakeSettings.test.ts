/**
 * Bake settings are resolved once and passed on (issue #28): resolveBakeSettings fills defaults and
 * checks ranges; what it returned comes back as it is (frozen, so it cannot have changed since the
 * check), and the baker keeps that very object (its report carries it), so a CLI bake that checks
 * its flags before reading the scene file does not check them again in the scene baker and in
 * `start`.
 */
import { describe, expect, it } from 'vitest';
import { DEFAULT_BAKE_SETTINGS, resolveBakeSettings } from '../../../src/engines/bake/bakeSettings';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { isotropic, uniformRoom } from './bakeTestKit';
import { withHeadlessGL } from './withHeadlessGL';

describe('resolveBakeSettings', () => {
  it('fills the defaults and checks each field', () => {
    const s = resolveBakeSettings({ samples: 8, seed: undefined });
    expect(s).toEqual({ ...DEFAULT_BAKE_SETTINGS, samples: 8 });
    expect(() => resolveBakeSettings({ samples: 0 })).toThrow(/samples 0/);
  });

  it('gives resolved settings back as they are, frozen; a changed copy is checked again', () => {
    const s = resolveBakeSettings({ texelSize: 0.1 });
    expect(resolveBakeSettings(s)).toBe(s);
    expect(Object.isFrozen(s)).toBe(true);
    expect(() => {
      (s as { samples: number }).samples = -1;
    }).toThrow(TypeError);
    expect(() => resolveBakeSettings({ ...s, samples: -1 })).toThrow(/samples -1/);
  });

  it('the baker bakes with the resolved object it was given, not a second resolution of it', () => {
    const baker = createBaker(withHeadlessGL());
    const settings = resolveBakeSettings({ texelSize: 0.5, samples: 4, bounces: 1 });
    const { report } = baker.bake({ room: uniformRoom(2, 2, 2, 0.5), luminaires: [{ photometry: isotropic(100), position: [1, 1, 1], yaw: 0, pitch: 0, roll: 0 }] }, settings);
    expect(report.settings).toBe(settings);
    baker.dispose();
  });
});
