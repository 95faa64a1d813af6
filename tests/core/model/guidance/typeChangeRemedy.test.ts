/**
 * A longer module type that does not fit its rail (issue 27, "No dead ends"): remedyFor offers the
 * first rail change after which setModuleType passes (another distribution, a longer rail), and none
 * where the rail cannot change enough (at the catalog's longest rail, packed), where the model's
 * reason stays the answer.
 */
import { describe, expect, it } from 'vitest';
import { attemptAction, checkAction } from '../../../../src/core/model/actions/actionDefinitions';
import type { Configuration } from '../../../../src/core/model/configuration/configuration';
import { remedyFor } from '../../../../src/core/model/guidance/remedy';
import { validate } from '../../../../src/core/model/validation/validate';
import { catalog, enabled, run, withPreset } from '../helpers';

/**
 * Rail `railId` emptied, arranged from the start and packed with 0.25 m washers (24 W: the 240 W
 * driver carries a full 1.5 m rail of them, the 321.6 W one a 3 m rail, so space, not power, is what
 * refuses one more).
 */
function pack(config: Configuration, railId: string): Configuration {
  let c = config;
  for (const m of c.systems[0].rails[0].modules) c = run(c, 'removeModule', { moduleId: m.id });
  c = run(c, 'setDistribution', { railId, distribution: 'start' });
  while (enabled(c, 'addModule', { railId, type: 'washer' }) === true) c = run(c, 'addModule', { railId, type: 'washer' });
  const more = checkAction(c, 'addModule', { railId, type: 'washer' }, catalog);
  if (more === true || more.code !== 'noRoomForModule') throw new Error(`not packed by space: ${JSON.stringify(more)}`);
  return c;
}

function perform(config: Configuration, steps: readonly { name: string; params: Record<string, unknown> }[]): Configuration {
  let c = config;
  for (const s of steps) {
    const o = attemptAction(c, s.name as never, s.params, catalog);
    if (!o.ok) throw new Error(`${s.name}: ${o.reason}`);
    c = o.next;
  }
  return c;
}

describe('a module type that does not fit: remedy or reason', () => {
  it('a washer turned into the 0.6 m linear diffuser on a packed 1.5 m rail: the rail is lengthened to 1.9 m, then it fits', () => {
    let config = withPreset('single', 1, 1);
    const rail = config.systems[0].rails[0];
    config = pack(config, rail.id);
    expect(config.systems[0].rails[0].modules.length).toBe(6);
    const washer = config.systems[0].rails[0].modules[0];
    const params = { moduleId: washer.id, type: 'linear' };
    const verdict = checkAction(config, 'setModuleType', params, catalog);
    expect(verdict !== true && verdict.code).toBe('typeDoesNotFit');
    const remedy = remedyFor(config, 'setModuleType', params, catalog)!;
    expect(remedy).not.toBeNull();
    // Six washers fill 1.5 m; one 0.35 m longer needs 1.85 m, on the 0.1 m steps 1.9 m.
    expect(remedy.parts).toEqual([{ kind: 'lengthenRail', params: { rail: 1, length: 1.9 } }]);
    const after = perform(config, remedy.steps);
    expect(validate(after, catalog)).toEqual([]);
    expect(checkAction(after, 'setModuleType', params, catalog)).toBe(true);
    // The shortest rail that takes it: one step shorter still refuses (the remedy is the first that fits).
    const length = after.systems[0].rails[0].length;
    expect(length).toBeGreaterThan(rail.length);
    const shorter = perform(config, [{ name: 'setRailLength', params: { railId: rail.id, length: Math.round((length - catalog.rail.step) * 100) / 100 } }]);
    expect(checkAction(shorter, 'setModuleType', params, catalog)).not.toBe(true);
  });

  it('a packed 3 m rail (the longest there is) offers nothing: the model’s reason stays', () => {
    let config = withPreset('single', 1, 1, 0, { width: 12, depth: 8, height: 3 });
    const rail = config.systems[0].rails[0];
    config = run(config, 'setRailLength', { railId: rail.id, length: catalog.rail.maxLength });
    config = run(config, 'setFeedDriver', { feedId: config.systems[0].feeds[0].id, driver: 'hlg-320h-48' });
    config = pack(config, rail.id);
    expect(config.systems[0].rails[0].modules.length).toBe(12);
    const washer = config.systems[0].rails[0].modules[0];
    const params = { moduleId: washer.id, type: 'linear' };
    const verdict = checkAction(config, 'setModuleType', params, catalog);
    expect(verdict !== true && verdict.code).toBe('typeDoesNotFit');
    expect(verdict !== true && verdict.reason).toBe('a Linear diffuser (0.6 m) does not fit here without clashing');
    expect(remedyFor(config, 'setModuleType', params, catalog)).toBeNull();
  });
});
