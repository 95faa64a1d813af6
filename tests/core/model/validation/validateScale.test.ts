/** validate() on large halls (issue 18): pair checks through a grid, a cheap first problem reported before any pair check. */
import { describe, expect, it } from 'vitest';
import { validate } from '../../../../src/core/model/validation/validate';
import { catalog, hall } from '../helpers';

describe('validate at scale', () => {
  it('a hall with 500 rails validates with O(n) exact rectangle tests', () => {
    const config = hall(25, 20);
    const stats = { pairTests: 0 };
    expect(validate(config, catalog, { stats })).toEqual([]);
    // 500 rails + 475 joints = 975 elements; all pairs would be ~475 000 tests.
    expect(stats.pairTests).toBeLessThan(975 * 4);
  });

  it('finds clashes and self-crossings through the grid like the pairwise check', () => {
    const config = hall(3, 5, 0.03); // rows 3 cm apart with 5 cm wide rails: neighbours clash, rows 6 cm apart do not
    const codes = validate(config, catalog).map((p) => `${p.path} ${p.code}`);
    expect(codes).toEqual(['systems[0] system-overlap', 'systems[1] system-overlap', 'systems[1] system-overlap', 'systems[2] system-overlap']);
  });

  it('reports a duplicate id first, without pair checks (firstOnly)', () => {
    const config = hall(2461, 1, 0); // every system on the same spot, and ids repeated
    const dup = { ...config, systems: config.systems.map((s) => ({ ...s, id: 's1' })) };
    const stats = { pairTests: 0 };
    const problems = validate(dup, catalog, { firstOnly: true, stats });
    expect(problems[0].message).toBe("id 's1' is used twice");
    expect(stats.pairTests).toBe(0);
    const clash = validate(config, catalog, { firstOnly: true, stats });
    expect(clash[0]).toEqual({ code: 'system-overlap', path: 'systems[0]', message: 'system s1 overlaps system s3', params: { id: 's1', other: 's3' } });
    expect(stats.pairTests).toBe(1);
  });
});
