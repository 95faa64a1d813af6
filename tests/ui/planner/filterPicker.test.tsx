import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import { findColourFilter } from '../../../src/core/colour/colourFilterLibrary';
import { displaySwatch, swatchCss } from '../../../src/core/colour/displaySwatch';
import { moduleColour } from '../../../src/core/colour/moduleColour';
import type { Configuration, ModuleInstance } from '../../../src/core/model/configuration/configuration';
import { filterMatches } from '../../../src/core/model/modules/moduleFilter';
import { createActionGate } from '../../../src/ui/planner/actionGate';
import { cctTint } from '../../../src/ui/planner/cctTint';
import { FilterPicker } from '../../../src/ui/planner/FilterPicker';
import { ModuleOptions } from '../../../src/ui/planner/ModuleOptions';
import { moduleTint } from '../../../src/ui/planner/moduleTint';
import { catalog, only, run, withPreset } from '../../core/model/helpers';

const base = withPreset('corner-l', 1, 3);
const mods = only(base).rails.flatMap((r) => r.modules);
const spot = mods.find((m) => m.type === 'spot')!;
const flood = mods.find((m) => m.type === 'flood')!;
const gate = (c: Configuration) =>
  createActionGate(
    c,
    catalog,
    () => {},
    () => {},
  );
const moduleIn = (c: Configuration, id: string): ModuleInstance =>
  only(c)
    .rails.flatMap((r) => r.modules)
    .find((m) => m.id === id)!;
const picker = (c: Configuration, id: string) => renderToStaticMarkup(<FilterPicker module={moduleIn(c, id)} catalog={catalog} gate={gate(c)} />);

describe('filter picker', () => {
  it('unfiltered 3000 K spot: the source itself (x 0.4369, y 0.4041, 100 %, 3000 K Duv 0), "No filter" pressed, four kind groups', () => {
    const html = picker(base, spot.id);
    expect(html).toContain('Unfiltered, 3000 K');
    expect(html).toContain('CIE x 0.4369, y 0.4041');
    expect(html).toContain('Transmission 100%');
    expect(html).toContain('CCT 3,000 K, Duv 0.0000');
    expect(html).toMatch(/aria-pressed="true"[^>]*data-testid="filter-none"/);
    for (const heading of ['Warming (CTO)', 'Cooling (CTB)', 'Neutral density', 'Colours']) expect(html).toContain(`<h3>${heading}</h3>`);
    expect(html.match(/data-testid="filter-lee-/g)).toHaveLength(43);
  });

  it('with LEE 106 Primary Red: its name, x,y, ≈ 13 % and no CCT; the chip is pressed; the swatch is red', () => {
    const c = run(base, 'setModuleFilter', { moduleId: spot.id, filter: 'lee-106' });
    const html = picker(c, spot.id);
    const colour = moduleColour(3000, 'lee-106');
    expect(html).toContain('<strong>LEE 106 Primary Red</strong>');
    expect(html).toContain(`CIE x ${colour.x.toFixed(4)}, y ${colour.y.toFixed(4)}`);
    expect(html).toContain(`Transmission ${(colour.transmission * 100).toFixed(1)}%`);
    expect(html).toContain('Coloured light: no colour temperature');
    expect(html).toMatch(/aria-pressed="true"[^>]*data-testid="filter-lee-106"/);
    const [r, g, b] = displaySwatch(colour.linearRgb);
    expect(r).toBe(255);
    expect(g + b).toBeLessThan(60);
    expect(html).toContain(`data-colour="${swatchCss(colour.linearRgb)}"`);
  });

  it('only module types with a filter holder show the picker', () => {
    const g = gate(base);
    expect(renderToStaticMarkup(<ModuleOptions module={spot} catalog={catalog} gate={g} onClose={() => {}} />)).toContain('data-testid="filter-picker"');
    expect(renderToStaticMarkup(<ModuleOptions module={flood} catalog={catalog} gate={g} onClose={() => {}} />)).not.toContain('data-testid="filter-picker"');
  });

  it('search: every word in number, name or maker', () => {
    const f = findColourFilter('lee-201');
    expect(filterMatches(f, '201')).toBe(true);
    expect(filterMatches(f, 'c.t. BLUE')).toBe(true);
    expect(filterMatches(f, 'lee blue')).toBe(true);
    expect(filterMatches(f, 'orange')).toBe(false);
    expect(filterMatches(f, '  ')).toBe(true);
  });
});

describe('display swatch and plan tint', () => {
  it('normalises the largest component to 1 and applies the sRGB transfer (IEC 61966-2-1)', () => {
    expect(displaySwatch([1, 1, 1])).toEqual([255, 255, 255]);
    expect(displaySwatch([0.4, 0.4, 0.4])).toEqual([255, 255, 255]); // an ND filter stays white on screen
    // 0.5 → 1.055·0.5^(1/2.4) − 0.055 = 0.73536 → 187.5 → 188; 0.001 → 12.92·0.001 = 0.01292 → 3.29 → 3
    expect(displaySwatch([0.2, 0.1, 0.0002])).toEqual([255, 188, 3]);
    expect(displaySwatch([0, 0, 0])).toEqual([0, 0, 0]);
  });

  it('the plan tints a filtered module with its light, an unfiltered one with its CCT tint', () => {
    expect(moduleTint({ cct: 3000 })).toBe(cctTint(3000));
    expect(moduleTint({ cct: 3000, filter: 'lee-119' })).toBe(swatchCss(moduleColour(3000, 'lee-119').linearRgb));
    expect(moduleTint({ cct: 3000, filter: 'not-a-filter' })).toBe(cctTint(3000));
  });
});
