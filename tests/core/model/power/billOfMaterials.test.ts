import { describe, expect, it } from 'vitest';
import { billOfMaterials, railUnitPrice } from '../../../../src/core/model/power/billOfMaterials';
import { createConfiguration } from '../../../../src/core/model/configuration/configuration';
import { catalog, only, run, withPreset } from '../helpers';

describe('bill of materials', () => {
  it('prices the L-corner preset by hand', () => {
    const bom = billOfMaterials(withPreset('corner-l', 1, 3), catalog);
    const byArticle = Object.fromEntries(bom.lines.map((l) => [l.article, l]));
    // rails: 40 + 60·L
    expect(byArticle['LX-RAIL-2000']).toMatchObject({ count: 1, unitPrice: 160, total: 160 });
    expect(byArticle['LX-RAIL-1500']).toMatchObject({ count: 1, unitPrice: 130, total: 130 });
    expect(byArticle['LX-CON-90']).toMatchObject({ count: 1, unitPrice: 24 });
    // suspension points (suspensionPoints.ts): 0.5 m in from the start (min(0.5, 2/4)), the corner point,
    // 0.375 m before the end (min(0.5, 1.5/4)); gaps 1.55 and 1.175 m ≤ 2 m: 3 kits
    expect(byArticle['LX-SUSP']).toMatchObject({ count: 3, total: 54 });
    expect(byArticle['LX-FEED']).toMatchObject({ count: 1, total: 65 });
    // 234 W: more than the default 100.8 W driver, so the new system got the smallest that carries it
    expect(byArticle['MW-HLG-240H-48']).toMatchObject({ count: 1, unitPrice: 84.9, total: 84.9, kind: 'driver' });
    expect(byArticle['LX-SPOT-N12-3000']).toMatchObject({ count: 2, total: 378 });
    expect(byArticle['LX-FLOOD-48-3000']).toMatchObject({ count: 2, total: 298 });
    expect(byArticle['LX-WASH-25-3000']).toMatchObject({ count: 2, total: 518 });
    expect(bom.total).toBe(1711.9); // 160 + 130 + 24 + 54 + 65 + 84.90 + 378 + 298 + 518
    expect(bom.currency).toBe('EUR');
    expect(bom.watts).toBe(2 * 43 + 2 * 50 + 2 * 24);
    expect(bom.lumens).toBe(2 * 2044 + 2 * 825 + 2 * 1615);
  });
  it('line totals are count × unit price and sum to the total, to the cent', () => {
    let s = createConfiguration({ width: 12, depth: 10, height: 3 });
    for (const p of catalog.presets) s = run(s, 'placePreset', { presetId: p.id });
    const m = s.systems[0].rails[0].modules[0].id;
    s = run(s, 'setModuleCct', { moduleId: m, cct: 2700 });
    const bom = billOfMaterials(s, catalog);
    for (const l of bom.lines) expect(l.total).toBeCloseTo(l.count * l.unitPrice, 10);
    expect(bom.total).toBeCloseTo(
      bom.lines.reduce((a, l) => a + l.total, 0),
      10,
    );
    expect(bom.lines.some((l) => l.article === 'LX-SPOT-N12-2700' && l.count === 1)).toBe(true);
    expect(railUnitPrice(1.3, catalog)).toBe(118);
  });
  it('changing a CCT or deleting a system changes the price', () => {
    const s = withPreset('single', 1, 1);
    const before = billOfMaterials(s, catalog).total;
    expect(billOfMaterials(run(s, 'setModuleBeam', { moduleId: only(s).rails[0].modules[0].id, beam: 'medium' }), catalog).total).toBe(before - 20);
    expect(billOfMaterials(run(s, 'deleteSystem', { systemId: only(s).id }), catalog)).toMatchObject({ total: 0, lines: [] });
  });
});
