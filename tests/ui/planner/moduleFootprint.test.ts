import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import type { ModuleInstance } from '../../../src/core/model/configuration/configuration';
import type { ModulePlacement } from '../../../src/core/model/rails/geometry';
import { moduleFootprint } from '../../../src/ui/planner/moduleFootprint';
import { deleteTarget } from '../../../src/ui/planner/deleteTarget';
import { selectionPath } from '../../../src/ui/planner/selection';
import { actionDefinitions } from '../../../src/core/model/actions/actionDefinitions';
import { createConfiguration } from '../../../src/core/model/configuration/configuration';

const placement = (heading: number): ModulePlacement => ({
  moduleId: 'm1',
  railId: 'r1',
  systemId: 's1',
  offset: 0,
  length: 0.25,
  centre: [2, 1],
  heading,
  footprint: { centre: [2, 1], axis: [1, 0], halfLength: 0.125, halfWidth: 0.025 },
});
const washerLeft: ModuleInstance = { id: 'm1', type: 'washer', beam: 'left', cct: 3000, dimming: 1 };
const spot: ModuleInstance = { id: 'm1', type: 'spot', beam: 'narrow', cct: 3000, dimming: 1 };
// A measured footprint that is a single point one mounting height out along C0.
const alongC0 = { polygon: [[1, 0]] as [number, number][], peak: [1, 0] as [number, number] };

describe('moduleFootprint', () => {
  it("turns the measured footprint like the luminaire: C0 of a 'wash to the left' (roll 90) lands left of the rail", () => {
    // Rail along +x (heading 0); left of it, seen from above, is −z (up on the plan).
    const f = moduleFootprint(placement(0), washerLeft, defaultCatalog, 2, alongC0)!;
    expect(f.kind).toBe('polygon');
    if (f.kind !== 'polygon') return;
    expect(f.points[0].x).toBeCloseTo(2, 9);
    expect(f.points[0].z).toBeCloseTo(1 - 2, 9);
  });

  it('a rail heading 90° (pointing to −z) with roll 90 sends C0 to −x', () => {
    const f = moduleFootprint(placement(90), washerLeft, defaultCatalog, 1.5, alongC0)!;
    if (f.kind !== 'polygon') throw new Error('expected polygon');
    expect(f.points[0].x).toBeCloseTo(2 - 1.5, 9);
    expect(f.points[0].z).toBeCloseTo(1, 9);
  });

  it("falls back to the catalog beam angle's cone while the photometry loads (12° spot, 2.2 m: r = 0.2312 m)", () => {
    const f = moduleFootprint(placement(0), spot, defaultCatalog, 2.2, undefined)!;
    if (f.kind !== 'ellipse') throw new Error('expected ellipse');
    expect(f.ellipse.rx).toBeCloseTo(2.2 * Math.tan((6 * Math.PI) / 180), 9);
  });

  it('draws nothing for an optic with no beam angle until its photometry is measured', () => {
    expect(moduleFootprint(placement(0), washerLeft, defaultCatalog, 2, undefined)).toBeNull();
    expect(moduleFootprint(placement(0), { ...spot, type: 'unknown' }, defaultCatalog, 2, undefined)).toBeNull();
  });
});

describe('selectionPath and deleteTarget', () => {
  const config = actionDefinitions.placePreset.perform(createConfiguration(), { presetId: 'single' }, defaultCatalog);
  const s = config.systems[0];
  const r = s.rails[0];
  const m = r.modules[1];
  it('expands a module selection to its rail and system, and Delete removes the deepest part', () => {
    expect(selectionPath(config, { kind: 'module', id: m.id })).toEqual({ systemId: s.id, railId: r.id, moduleId: m.id });
    expect(deleteTarget(selectionPath(config, { kind: 'module', id: m.id }))).toEqual({ name: 'removeModule', params: { moduleId: m.id } });
    expect(deleteTarget(selectionPath(config, { kind: 'system', id: s.id }))).toEqual({ name: 'deleteSystem', params: { systemId: s.id } });
    expect(selectionPath(config, { kind: 'module', id: 'gone' })).toEqual({});
    expect(deleteTarget({})).toEqual({ reason: 'select a system, a module or an object first' });
  });
});
