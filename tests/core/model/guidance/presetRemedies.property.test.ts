/**
 * No dead ends (issue 27; docs/model.md, "Remedies"): from each preset, placed in a few room sizes,
 * adding one module of each type to each rail is either allowed, or its refusal carries a one-tap
 * remedy (remedyFor) that, performed, makes that same addition allowed. Seeded, fixed count: the
 * rooms are drawn by fast-check around the fixed ones, so failures reproduce. Rooms from the
 * default 5 × 4 m up: in a smaller one a rail may have no room to grow at all, and a module longer
 * than its free space then stays refused with its reason (no remedy is invented).
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { attemptAction, checkAction } from '../../../../src/core/model/actions/actionDefinitions';
import { createConfiguration, type Configuration, type Room } from '../../../../src/core/model/configuration/configuration';
import { remedyFor } from '../../../../src/core/model/guidance/remedy';
import { validate } from '../../../../src/core/model/validation/validate';
import { catalog } from '../helpers';

function place(room: Pick<Room, 'width' | 'depth' | 'height'>, presetId: string): Configuration | null {
  const o = attemptAction(createConfiguration(room), 'placePreset', { presetId }, catalog);
  return o.ok ? o.next : null;
}

/** Every (rail, type) addition on the placed preset: allowed, or remedied; returns how many needed a remedy. */
function checkPreset(config: Configuration): { remedied: number; codes: string[] } {
  const system = config.systems[0];
  let remedied = 0;
  const codes: string[] = [];
  for (const rail of system.rails) {
    for (const type of catalog.moduleTypes) {
      const params = { railId: rail.id, type: type.id };
      if (checkAction(config, 'addModule', params, catalog) === true) continue;
      const remedy = remedyFor(config, 'addModule', params, catalog);
      expect(remedy, `${system.presetId} ${rail.id} + ${type.id}: ${JSON.stringify(checkAction(config, 'addModule', params, catalog))}`).not.toBeNull();
      let after = config;
      for (const step of remedy!.steps) {
        const o = attemptAction(after, step.name, step.params, catalog);
        expect(o.ok, `${step.name} ${JSON.stringify(step.params)}`).toBe(true);
        if (o.ok) after = o.next;
      }
      expect(validate(after, catalog)).toEqual([]);
      expect(checkAction(after, 'addModule', params, catalog), `${system.presetId} ${rail.id} + ${type.id} after ${remedy!.label}`).toBe(true);
      remedied++;
      codes.push(remedy!.parts.map((x) => x.kind).join('+'));
    }
  }
  return { remedied, codes };
}

const ROOMS = [
  { width: 5, depth: 4, height: 2.8 },
  { width: 8, depth: 6, height: 3 },
  { width: 12, depth: 9, height: 3.5 },
];

describe('every preset leaves room to grow or offers a remedy (issue 27)', () => {
  it('the L corner as shipped: its first refused + offers the 321.6 W driver', () => {
    const config = place(ROOMS[0], 'corner-l')!;
    const rail = config.systems[0].rails[0];
    const remedy = remedyFor(config, 'addModule', { railId: rail.id, type: 'spot' }, catalog)!;
    expect(remedy.parts).toEqual([{ kind: 'useDriver', params: { capacity: 321.6 } }]);
    expect(remedy.label).toBe('use the 321.6 W driver (+28 EUR)');
    expect(remedy.priceDelta).toBe(28); // 112.90 € − 84.90 €
    expect(remedy.steps).toEqual([{ name: 'setFeedDriver', params: { feedId: config.systems[0].feeds[0].id, driver: 'hlg-320h-48' } }]);
  });

  it('an enabled action has no remedy', () => {
    const config = place(ROOMS[0], 'single')!;
    expect(remedyFor(config, 'addModule', { railId: config.systems[0].rails[0].id, type: 'spot' }, catalog)).toBeNull();
  });

  for (const room of ROOMS) {
    for (const preset of catalog.presets) {
      it(`${preset.id} in ${room.width} × ${room.depth} m`, () => {
        const config = place(room, preset.id);
        if (!config) return; // the preset does not fit this room: the first-run suggestions leave it out
        checkPreset(config);
      });
    }
  }

  it('seeded rooms: 16 random rooms from 5 × 4 m to 15 × 12 m, every preset that fits', () => {
    fc.assert(
      fc.property(fc.integer({ min: 50, max: 150 }), fc.integer({ min: 40, max: 120 }), fc.integer({ min: 26, max: 45 }), (w, d, h) => {
        for (const preset of catalog.presets) {
          const config = place({ width: w / 10, depth: d / 10, height: h / 10 }, preset.id);
          if (config) checkPreset(config);
        }
      }),
      { seed: 27, numRuns: 16 },
    );
  });
});

describe('remedies are for actions that add light', () => {
  it('a heavier beam on the full L corner gets the driver; a smaller driver gets none', () => {
    const config = place(ROOMS[0], 'corner-l')!;
    const system = config.systems[0];
    const washer = system.rails[1].modules[0];
    const spot = system.rails[0].modules[0];
    // A 24 W washer turned into a 50 W flood: 260 W on the 240 W driver, refused; the remedy is the 321.6 W driver. A lighter beam is allowed.
    const typeChange = { moduleId: washer.id, type: 'flood' };
    expect(checkAction(config, 'setModuleType', typeChange, catalog)).not.toBe(true);
    expect(remedyFor(config, 'setModuleType', typeChange, catalog)!.parts).toEqual([{ kind: 'useDriver', params: { capacity: 321.6 } }]);
    expect(checkAction(config, 'setModuleBeam', { moduleId: spot.id, beam: 'medium' }, catalog)).toBe(true);
    const smaller = { feedId: system.feeds[0].id, driver: 'lpv-60-48' };
    expect(checkAction(config, 'setFeedDriver', smaller, catalog)).not.toBe(true);
    expect(remedyFor(config, 'setFeedDriver', smaller, catalog)).toBeNull();
  });
});
