import { describe, expect, it } from 'vitest';
import { folderCycles, layerViolations, readImportGraph, type ImportEdge } from './importGraph';

/**
 * The layers of docs/architecture.md, enforced: core ← engines ← ui ← hosts, no cycle between
 * folders, no product import of the reference solver, no React or three.js where a layer must
 * not have them.
 */
const graph = readImportGraph('.');

describe('layers', () => {
  it('the source tree imports only downward, without folder cycles or reference imports', () => {
    // The walk sees the whole tree (so an empty graph cannot pass).
    expect(graph.filter((e) => !e.isPackage).length).toBeGreaterThan(300);
    expect(new Set(graph.map((e) => e.from.split('/').slice(0, 3).join('/')))).toContain('src/core/model');
    expect(layerViolations(graph)).toEqual([]);
  });

  it('the same check fails on an upward import, a folder cycle, a reference import and a forbidden package', () => {
    const bad: ImportEdge[] = [
      { from: 'src/core/model/rails/geometry.ts', to: 'src/ui/planner/Planner.tsx', isPackage: false },
      { from: 'src/engines/view/lightStats.ts', to: 'src/reference/directIlluminance.ts', isPackage: false },
      { from: 'src/engines/bake/createBaker.ts', to: 'react', isPackage: true },
      { from: 'src/reference/candelaAt.ts', to: 'src/engines/bake/profileTable.ts', isPackage: false },
      { from: 'src/stray.ts', to: 'src/core/model/rails/geometry.ts', isPackage: false },
    ];
    const problems = layerViolations([...graph, ...bad]);
    expect(problems).toHaveLength(6);
    // The upward import closes a cycle through the folders that import core/model.
    expect(problems[0]).toMatch(/geometry\.ts imports src\/ui\/planner\/Planner\.tsx: an upward import/);
    expect(problems.some((p) => /lightStats\.ts imports the reference solver/.test(p))).toBe(true);
    expect(problems.some((p) => /createBaker\.ts imports the package react/.test(p))).toBe(true);
    expect(problems.some((p) => /candelaAt\.ts imports .*the reference may use only core/.test(p))).toBe(true);
    expect(problems.some((p) => /stray\.ts: lies outside the layer folders/.test(p))).toBe(true);
    expect(problems.filter((p) => p.startsWith('folders import each other'))).toEqual(['folders import each other: core/catalog → core/model → ui/planner → core/catalog']);
    // A cycle inside one layer, where no import goes upward.
    const sideways: ImportEdge = { from: 'src/ui/viewer/View3D.tsx', to: 'src/ui/planner/Planner.tsx', isPackage: false };
    expect(layerViolations([...graph, sideways])).toEqual(['folders import each other: ui/planner → ui/viewer → ui/planner']);
  });

  it('finds every cycle of a folder graph once', () => {
    const g = new Map([
      ['a', new Set(['b'])],
      ['b', new Set(['c'])],
      ['c', new Set(['a', 'd'])],
      ['d', new Set(['e'])],
      ['e', new Set(['d'])],
      ['f', new Set(['a'])],
    ]);
    expect(folderCycles(g)).toEqual([
      ['d', 'e', 'd'],
      ['a', 'b', 'c', 'a'],
    ]);
  });
});
