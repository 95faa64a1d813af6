import { describe, expect, it } from 'vitest';
import { layoutModules } from '../../../../src/core/model/rails/distribution';

// Hand-computed layouts (docs/model.md definitions); offsets are module starts.
const close = (a: number[] | null, b: number[]) => {
  expect(a).not.toBeNull();
  a!.forEach((x, i) => expect(x).toBeCloseTo(b[i], 12));
};

describe('layoutModules', () => {
  it('start packs from the rail start', () => close(layoutModules([0.2, 0.3], 1, 'start'), [0, 0.2]));
  it('end packs against the rail end', () => close(layoutModules([0.2, 0.3], 1, 'end'), [0.5, 0.7]));
  it('inside-centred centres each module in its L/n cell', () => {
    // cells of 0.5: centres 0.25 and 0.75
    close(layoutModules([0.2, 0.3], 1, 'inside-centred'), [0.15, 0.6]);
  });
  it('outside-centred puts the outer modules at the ends and spaces centres evenly', () => {
    // centres 0.1, 0.5, 0.9
    close(layoutModules([0.2, 0.2, 0.2], 1, 'outside-centred'), [0, 0.4, 0.8]);
    close(layoutModules([0.2], 1, 'outside-centred'), [0.4]);
  });
  it('an empty rail lays out nothing', () => expect(layoutModules([], 1, 'end')).toEqual([]));
  it('refuses more module length than rail for every distribution', () => {
    for (const d of ['start', 'end', 'inside-centred', 'outside-centred'] as const) expect(layoutModules([0.6, 0.5], 1, d)).toBeNull();
  });
  it('inside-centred refuses a module longer than its cell even when the total fits', () => {
    // 0.6 + 0.15 = 0.75 ≤ 1, but the 0.6 module exceeds the 0.5 cell
    expect(layoutModules([0.6, 0.15], 1, 'inside-centred')).toBeNull();
    close(layoutModules([0.6, 0.15], 1, 'start'), [0, 0.6]);
  });
  it('outside-centred refuses neighbours that would overlap', () => {
    // centres 0.075, 0.5, 0.925: 0.15 spot next to a 0.6 linear needs 0.375 between centres, has 0.425 → fits
    close(layoutModules([0.15, 0.6, 0.15], 1, 'outside-centred'), [0, 0.2, 0.85]);
    // centres 0.3, 0.6125, 0.925: the 0.6 and 0.15 modules need 0.375 between centres but get 0.3125
    expect(layoutModules([0.6, 0.15, 0.15], 1, 'outside-centred')).toBeNull();
  });
  it('exactly full rails fit (float noise tolerated)', () => {
    const l = Array(10).fill(0.1);
    close(
      layoutModules(l, 1, 'inside-centred'),
      l.map((_, i) => i / 10),
    );
    close(
      layoutModules(l, 1, 'outside-centred'),
      l.map((_, i) => i / 10),
    );
    expect(layoutModules([...l, 0.1], 1, 'start')).toBeNull();
  });
});
