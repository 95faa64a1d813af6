import { readdirSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { folderCycles, folderOf, layerViolations, readImportGraph, type ImportEdge } from './importGraph';

/**
 * The layers of docs/architecture.md, enforced: core ← engines ← ui ← hosts, no cycle between
 * folders, no product import of the reference solver, no React or three.js where a layer must
 * not have them.
 */
const graph = readImportGraph('.');

/**
 * The model's domain folders, bottom to top (docs/architecture.md, "The model's folders"): each is a
 * folder of its own for the cycle check, so a domain may use the ones below it and never one above.
 */
const MODEL_FOLDERS = ['lightingScene', 'catalogSchema', 'configuration', 'rails', 'modules', 'power', 'objects', 'cues', 'validation', 'files', 'actions', 'guidance'];

describe('layers', () => {
  it('the source tree imports only downward, without folder cycles or reference imports', () => {
    // The walk sees the whole tree (so an empty graph cannot pass).
    expect(graph.filter((e) => !e.isPackage).length).toBeGreaterThan(300);
    expect(new Set(graph.map((e) => e.from.split('/').slice(0, 3).join('/')))).toContain('src/core/model');
    expect(layerViolations(graph)).toEqual([]);
  });

  it('core/model is its domain folders, each a folder of the graph, with no file at its root', () => {
    // (An empty folder a move left behind in a checkout is not part of the tree git knows.)
    const entries = readdirSync('src/core/model').filter((e) => !statSync(join('src/core/model', e)).isDirectory() || readdirSync(join('src/core/model', e)).length > 0);
    expect(entries.filter((e) => !statSync(join('src/core/model', e)).isDirectory())).toEqual([]);
    expect(entries.sort()).toEqual([...MODEL_FOLDERS].sort());
    const seen = new Set(graph.map((e) => folderOf(e.from)).filter((f) => f.startsWith('core/model')));
    expect([...seen].sort()).toEqual(MODEL_FOLDERS.map((f) => `core/model/${f}`).sort());
    // A file deeper down belongs to its domain (objects/furniture is part of objects).
    expect(folderOf('src/core/model/objects/furniture/meshParts.ts')).toBe('core/model/objects');
    // Folders import only folders below them in MODEL_FOLDERS.
    for (const e of graph) {
      const [from, to] = [folderOf(e.from), folderOf(e.to)];
      if (e.isPackage || from === to || !from.startsWith('core/model/') || !to.startsWith('core/model/')) continue;
      expect(MODEL_FOLDERS.indexOf(to.slice(11)), `${e.from} imports ${e.to}`).toBeLessThan(MODEL_FOLDERS.indexOf(from.slice(11)));
    }
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
    expect(problems.filter((p) => p.startsWith('folders import each other'))).toEqual(['folders import each other: core/catalog → core/model/actions → core/model/rails → ui/planner → core/catalog']);
    // A cycle inside one layer, where no import goes upward.
    const sideways: ImportEdge = { from: 'src/ui/viewer/View3D.tsx', to: 'src/ui/planner/Planner.tsx', isPackage: false };
    expect(layerViolations([...graph, sideways])).toEqual(['folders import each other: ui/planner → ui/viewer → ui/planner']);
    // A cycle between the model's domains (rails would need validation, which needs power, which needs rails).
    const railsOnValidation: ImportEdge = { from: 'src/core/model/rails/presets.ts', to: 'src/core/model/validation/validate.ts', isPackage: false };
    expect(layerViolations([...graph, railsOnValidation])).toEqual(['folders import each other: core/model/power → core/model/rails → core/model/validation → core/model/power']);
    // A data file counts like a module: the colour-filter library reading its JSON from core/catalog closes
    // core/catalog → core/model/catalogSchema → core/colour → core/catalog (why the JSON lives in core/colour).
    const libraryInCatalog: ImportEdge = { from: 'src/core/colour/colourFilterLibrary.ts', to: 'src/core/catalog/colour-filters.json', isPackage: false };
    expect(layerViolations([...graph, libraryInCatalog])).toEqual(['folders import each other: core/catalog → core/model/catalogSchema → core/colour → core/catalog']);
    // The walk reads JSON imports as edges.
    expect(graph).toContainEqual({ from: 'src/core/colour/colourFilterLibrary.ts', to: 'src/core/colour/colour-filters.json', isPackage: false });
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
