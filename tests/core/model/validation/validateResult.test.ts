/**
 * validateResult (what the action binding checks) examines only what changed,
 * so it must agree with a full validate(): random raw edits, valid or not, of
 * a state with a few systems, and edits of an already invalid state.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Configuration, LightSystem } from '../../../../src/core/model/configuration/configuration';
import { validate } from '../../../../src/core/model/validation/validate';
import { validateResult } from '../../../../src/core/model/validation/validateResult';
import { catalog, run, withPreset } from '../helpers';

const unit = fc.double({ min: 0, max: 1, noNaN: true });
const edit = fc.record({ kind: fc.nat(9), i: fc.nat(10), a: unit, b: unit });
type Edit = { kind: number; i: number; a: number; b: number };

function patchSystem(s: Configuration, i: number, patch: (x: LightSystem) => LightSystem): Configuration {
  const k = i % s.systems.length;
  return { ...s, systems: s.systems.map((x, j) => (j === k ? patch(x) : x)) };
}

/** A raw change of the kind an action (careful or not) makes: new objects for what changes, the rest shared. */
function apply(s: Configuration, e: Edit): Configuration {
  const { width: W, depth: D } = s.room;
  switch (e.kind) {
    case 0:
      return patchSystem(s, e.i, (x) => ({ ...x, x: -0.5 + e.a * (W + 1), z: -0.5 + e.b * (D + 1) }));
    case 1:
      // turned across the others' rails, somewhere inside the room: clashes and room bounds
      return patchSystem(s, e.i, (x) => ({ ...x, rotation: [90, 270, 400, 90.5][e.i % 4], x: 0.5 + e.a * (W - 1), z: 0.5 + e.b * (D - 1) }));
    case 2:
      return patchSystem(s, e.i, (x) => ({ ...x, suspension: e.a * 2.5 }));
    case 3:
      return patchSystem(s, e.i, (x) => ({ ...x, rails: x.rails.map((r, k) => (k === e.i % x.rails.length ? { ...r, length: e.b < 0.5 ? 0.3 + Math.round(e.a * 30) / 10 : 0.3 + 3 * e.a } : r)) }));
    case 4:
      return patchSystem(s, e.i, (x) => ({ ...x, rails: x.rails.map((r) => ({ ...r, modules: r.modules.map((m) => ({ ...m, type: ['spot', 'linear', 'washer', 'nope'][e.i % 4] })) })) }));
    case 5:
      // a copy of a system, shifted: same ids, and maybe a clash
      return { ...s, systems: [...s.systems, { ...s.systems[e.i % s.systems.length], x: e.a * W, z: e.b * D }] };
    case 6:
      // one dimension at a time, so each must send the check down the full path
      return { ...s, room: { ...s.room, ...[{ width: 1 + e.a * 9 }, { depth: 1 + e.a * 7 }, { height: 2.2 + e.a * 1.5 }][e.i % 3] } };
    case 7:
      return { ...s, room: { ...s.room, reflectance: { ...s.room.reflectance, floor: e.a * 1.1 } } };
    case 8:
      return { ...s, nextId: e.a < 0.3 ? 3 : s.nextId };
    default:
      return { ...s, systems: s.systems.filter((_, j) => j !== e.i % s.systems.length) };
  }
}

function start(): Configuration {
  let s = withPreset('corner-l', 1, 4);
  s = run(s, 'placePreset', { presetId: 'single', x: 4, z: 1 });
  return run(s, 'placePreset', { presetId: 'long-line', x: 1, z: 5.5 });
}

describe('validateResult', () => {
  it('agrees with validate() on the result, from valid and from invalid states', () => {
    const base = start();
    expect(validate(base, catalog)).toEqual([]);
    let cheap = 0;
    const verdicts = { valid: 0, invalid: 0 };
    fc.assert(
      fc.property(edit, edit, (e1, e2) => {
        const mid = apply(base, e1);
        for (const [before, after] of [
          [base, mid],
          [mid, apply(mid, e2)],
        ]) {
          const full = validate(after, catalog);
          const found = validateResult(before, after, catalog);
          expect(found.length === 0).toBe(full.length === 0);
          verdicts[full.length === 0 ? 'valid' : 'invalid']++;
          // the reason given is one of validate()'s problems
          if (found.length > 0) expect(full).toContainEqual(found[0]);
          if (before === base && e1.kind !== 6) cheap++;
        }
      }),
      { seed: 20251123, numRuns: 1500 },
    );
    expect(cheap).toBeGreaterThan(1000);
    expect(verdicts.valid).toBeGreaterThan(300);
    expect(verdicts.invalid).toBeGreaterThan(300);
  });
});
