import { describe, expect, it } from 'vitest';
import { filterSpectrum } from '../../../../src/core/colour/colourFilterSpectra';
import { billOfMaterials } from '../../../../src/core/model/power/billOfMaterials';
import { parseCatalog } from '../../../../src/core/model/catalogSchema/catalogSchema';
import { deserializeConfiguration, serializeConfiguration } from '../../../../src/core/model/files/sceneFile';
import { decodeShareString, encodeShareString } from '../../../../src/core/model/files/shareLink';
import { moduleLightColour } from '../../../../src/core/model/modules/moduleFilter';
import { toLightingScene } from '../../../../src/core/model/files/toLightingScene';
import { validate } from '../../../../src/core/model/validation/validate';
import { cctToLinearRgb } from '../../../../src/core/photometry/cct';
import { catalog, enabled, only, run, withPreset } from '../helpers';

const luminance = ([r, g, b]: readonly number[]): number => 0.2126 * r + 0.7152 * g + 0.0722 * b;
const moduleIds = (s: ReturnType<typeof withPreset>) => only(s).rails.flatMap((r) => r.modules.map((m) => m.id));

describe('colour filters on modules', () => {
  it('the default catalog sells the whole library as LX-GEL accessories and its spots take them', () => {
    expect(catalog.filters?.length).toBe(43);
    expect(catalog.moduleTypes.filter((t) => t.filterHolder).map((t) => t.id)).toEqual(expect.arrayContaining(['spot']));
    expect(catalog.moduleTypes.find((t) => t.id === 'flood')?.filterHolder).toBeUndefined();
  });

  it('setModuleFilter puts a gel in front of a spot and null takes it out (the field is left out)', () => {
    const s = withPreset('single', 1, 1);
    const [m] = moduleIds(s);
    const f = run(s, 'setModuleFilter', { moduleId: m, filter: 'lee-204' });
    expect(only(f).rails[0].modules[0].filter).toBe('lee-204');
    expect(validate(f, catalog)).toEqual([]);
    const back = run(f, 'setModuleFilter', { moduleId: m, filter: null });
    expect('filter' in only(back).rails[0].modules[0]).toBe(false);
    expect(back).toEqual(s);
  });

  it('refuses a type without a holder and an unknown filter, with the reason; validate() names the field', () => {
    const s = withPreset('corner-l', 1, 3);
    const flood = only(s)
      .rails.flatMap((r) => r.modules)
      .find((m) => m.type === 'flood')!;
    expect(enabled(s, 'setModuleFilter', { moduleId: flood.id, filter: 'lee-201' })).toMatchObject({ ok: false, reason: 'Wide flood has no filter holder: it takes no colour filter' });
    const spot = only(s)
      .rails.flatMap((r) => r.modules)
      .find((m) => m.type === 'spot')!;
    expect(enabled(s, 'setModuleFilter', { moduleId: spot.id, filter: 'lee-999' })).toMatchObject({ ok: false, reason: "unknown colour filter 'lee-999' (not among the catalog's filters)" });
    // A state built by hand (a file) is judged the same way.
    const bad = { ...s, systems: [{ ...only(s), rails: only(s).rails.map((r) => ({ ...r, modules: r.modules.map((m) => (m.id === flood.id ? { ...m, filter: 'lee-201' } : m)) })) }] };
    const problems = validate(bad, catalog);
    expect(problems).toHaveLength(1);
    expect(problems[0]).toMatchObject({ code: 'no-filter-holder' });
    expect(problems[0].path).toMatch(/^systems\[0\]\.rails\[\d\]\.modules\[\d\]\.filter$/);
  });

  it('a filtered spot cannot become a type without a holder until the filter is out', () => {
    const s = withPreset('single', 1, 1);
    const [m] = moduleIds(s);
    const f = run(s, 'setModuleFilter', { moduleId: m, filter: 'lee-106' });
    expect(enabled(f, 'setModuleType', { moduleId: m, type: 'flood' })).toMatchObject({ ok: false, reason: 'Wide flood has no filter holder: it takes no colour filter' });
    // The warm-dim spot has a holder too: the filter stays.
    expect(only(run(f, 'setModuleType', { moduleId: m, type: 'spot-warmdim' })).rails[0].modules[0].filter).toBe('lee-106');
    const out = run(f, 'setModuleFilter', { moduleId: m, filter: null });
    expect(enabled(out, 'setModuleType', { moduleId: m, type: 'flood' })).toBe(true);
  });

  it('the bill of materials has one line per filter article, priced to the cent', () => {
    let s = withPreset('single', 1, 1);
    const ids = moduleIds(s);
    s = run(s, 'setModuleFilter', { moduleId: ids[0], filter: 'lee-204' });
    s = run(s, 'setModuleFilter', { moduleId: ids[1], filter: 'lee-204' });
    s = run(s, 'setModuleFilter', { moduleId: ids[2], filter: 'lee-209' });
    const before = billOfMaterials(withPreset('single', 1, 1), catalog).total;
    const bom = billOfMaterials(s, catalog);
    const gels = bom.lines.filter((l) => l.kind === 'filter');
    expect(gels).toEqual([
      { article: 'LX-GEL-204', name: 'LEE 204 Full C.T. Orange colour filter', count: 2, unitPrice: 14.9, total: 29.8, kind: 'filter' },
      { article: 'LX-GEL-209', name: 'LEE 209 0.3ND colour filter', count: 1, unitPrice: 14.9, total: 14.9, kind: 'filter' },
    ]);
    expect(bom.total).toBe(Math.round((before + 44.7) * 100) / 100);
    expect(bom.lines[bom.lines.length - 1].kind).toBe('filter');
  });

  it('the lighting scene carries the filtered colour: luminance τ_v (lumen loss), unfiltered unchanged', () => {
    let s = withPreset('single', 1, 1);
    const ids = moduleIds(s);
    s = run(s, 'setModuleFilter', { moduleId: ids[1], filter: 'lee-209' });
    const lum = toLightingScene(s, catalog).luminaires;
    expect(lum[0].color).toEqual(cctToLinearRgb(3000));
    const tau = moduleLightColour({ cct: 3000, filter: 'lee-209' }).transmission;
    expect(luminance(lum[1].color!)).toBeCloseTo(tau, 12);
    // LEE states 50.0 % for 0.3ND under its tungsten source (dataset src_a Y); measured at 3000 K: 0.4990.
    expect(Math.abs(tau - filterSpectrum('lee-209').stated.sourceA!.Y / 100)).toBeLessThan(0.007);
    // A deep colour: LEE 106 Primary Red passes ≈ 13 % and the light is red.
    s = run(s, 'setModuleFilter', { moduleId: ids[2], filter: 'lee-106' });
    const red = toLightingScene(s, catalog).luminaires[2].color!;
    expect(red[0]).toBeGreaterThan(10 * red[1]);
    expect(luminance(red)).toBeCloseTo(moduleLightColour({ cct: 3000, filter: 'lee-106' }).transmission, 12);
  });

  it('a filter travels in scene files and share links; a file naming a filter a flood cannot take is refused', () => {
    const s = withPreset('corner-l', 1, 3);
    const spot = only(s)
      .rails.flatMap((r) => r.modules)
      .find((m) => m.type === 'spot')!;
    const f = run(s, 'setModuleFilter', { moduleId: spot.id, filter: 'lee-205' });
    expect(deserializeConfiguration(serializeConfiguration(f, catalog), catalog)).toEqual(f);
    expect(decodeShareString(encodeShareString(f, catalog), catalog)).toEqual(f);
    const flood = only(s)
      .rails.flatMap((r) => r.modules)
      .find((m) => m.type === 'flood')!;
    const text = serializeConfiguration(f, catalog).replace(`"id": "${flood.id}",`, `"id": "${flood.id}",\n"filter": "lee-205",`);
    expect(text).toContain('"filter": "lee-205",');
    expect(() => deserializeConfiguration(text, catalog)).toThrow(/filter.*Wide flood has no filter holder/);
  });

  it('a catalog naming a filter the library lacks, or one twice, is refused naming the field', () => {
    const data = structuredClone(catalog) as Record<string, unknown> & { filters: { id: string }[] };
    data.filters[3].id = 'rosco-99';
    expect(() => parseCatalog(data)).toThrow(/filters\[3\]\.id.*'rosco-99' is not a filter of the colour-filter library/);
    const twice = structuredClone(catalog) as Record<string, unknown> & { filters: { id: string }[] };
    twice.filters[1].id = twice.filters[0].id;
    expect(() => parseCatalog(twice)).toThrow(/filters\[1\]\.id.*duplicate id 'lee-204'/);
  });
});
