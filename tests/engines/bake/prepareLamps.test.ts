/** Lamp preparation without GL (prepareLamps.ts): one table entry per distinct photometry, dark lamps dropped. */
import { describe, expect, it } from 'vitest';
import { prepareLamps } from '../../../src/engines/bake/prepareLamps';
import { resolveBakeSettings } from '../../../src/engines/bake/bakeSettings';
import { basePhotometry, isotropic, uniformRoom } from './bakeTestKit';

describe('prepareLamps', () => {
  it('shares one profile between luminaires with the same photometry, and drops lamps that emit nothing', () => {
    const shared = isotropic(100);
    const other = isotropic(50);
    const dark = basePhotometry({ candela: [[0, 0]] });
    const at = (x: number) => ({ position: [x, 1, 1] as [number, number, number], yaw: 0, pitch: 0, roll: 0 });
    const scene = {
      room: uniformRoom(4, 2.5, 3, 0.5),
      luminaires: [
        { ...at(1), photometry: shared },
        { ...at(2), photometry: other },
        { ...at(3), photometry: shared },
        { ...at(3.5), photometry: dark },
        { ...at(0.5), photometry: shared, dimming: 0 },
      ],
    };
    const { table, lamps, pointSources } = prepareLamps(scene, resolveBakeSettings({}));
    // shared, other, dark: each photometry once, in order of first use.
    expect(table.layouts).toHaveLength(3);
    expect(lamps.map((l) => l.profile.id)).toEqual([0, 1, 0]);
    expect(lamps[0].profile).toBe(lamps[2].profile);
    // Point-like openings: one source per emitting lamp.
    expect(pointSources).toBe(3);
    expect(lamps.map((l) => l.sources[0][0])).toEqual([1, 2, 3]);
  });
});
