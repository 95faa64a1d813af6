/**
 * Issue 32's contract for imports: what the importer accepts and addObject places is saved and
 * opened again unchanged (1 MB file limit, 200-character names in the schema, finite vertices).
 * Models are generated (fast-check, seeded, fixed run count): OBJ files with random vertices over
 * many magnitudes, random faces, material names up to 300 characters, random units; grids near
 * the stored-size limit; the glTF table with long names and scaled nodes.
 */
import fc from 'fast-check';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { InputError } from '../../../src/core/inputError';
import { importMesh } from '../../../src/engines/meshImport/importMesh';
import type { MeshFile } from '../../../src/engines/meshImport/importedMesh';
import { MESH_UNITS } from '../../../src/engines/meshImport/meshUnits';
import { MODELS, textFile } from './modelFixtures';
import { saveAndReopen } from './saveAndReopen';

const RUNS = 120;

const name = fc.oneof(fc.string({ minLength: 1, maxLength: 12 }), fc.string({ minLength: 190, maxLength: 300 }), fc.constant('ø'.repeat(150) + '😀'.repeat(40)));
const coordinate = fc.oneof(fc.double({ min: -3, max: 3, noNaN: true }), fc.double({ min: -5000, max: 5000, noNaN: true }), fc.constantFrom(0, 1e-30, 99.9, 100.1, 3.4e38, -3.4e38));

const objModel = fc
  .record({
    vertices: fc.array(fc.tuple(coordinate, coordinate, coordinate), { minLength: 3, maxLength: 60 }),
    faces: fc.array(fc.tuple(fc.nat(), fc.nat(), fc.nat(), fc.nat({ max: 3 })), { minLength: 1, maxLength: 80 }),
    materials: fc.array(name, { minLength: 1, maxLength: 4 }),
    fileName: name,
  })
  .map(({ vertices, faces, materials, fileName }): MeshFile[] => {
    const lines = [`mtllib m.mtl`, ...vertices.map(([x, y, z]) => `v ${x} ${y} ${z}`)];
    faces.forEach(([a, b, c, m], i) => {
      if (i % 7 === 0) lines.push(`usemtl ${materials[m % materials.length].replace(/\s/g, '_')}`);
      lines.push(`f ${(a % vertices.length) + 1} ${(b % vertices.length) + 1} ${(c % vertices.length) + 1}`);
    });
    const mtl = materials.map((m, i) => `newmtl ${m.replace(/\s/g, '_')}\nKd ${(i * 0.3) % 1} 0.5 0.7`).join('\n');
    return [textFile(`${fileName.replace(/[\\/\s]/g, '_')}.obj`, lines.join('\n')), textFile('m.mtl', mtl)];
  });

/** An n×n quad grid of side `size` metres: near n = 129 it crosses the stored-size limit. */
const gridModel = fc.record({ n: fc.integer({ min: 100, max: 135 }), size: fc.double({ min: 0.5, max: 20, noNaN: true }) }).map(({ n, size }): MeshFile[] => {
  const lines: string[] = [];
  for (let j = 0; j <= n; j++) for (let i = 0; i <= n; i++) lines.push(`v ${(i / n) * size} 0 ${(j / n) * size}`);
  for (let j = 0; j < n; j++)
    for (let i = 0; i < n; i++) {
      const a = j * (n + 1) + i + 1;
      lines.push(`f ${a} ${a + n + 1} ${a + n + 2} ${a + 1}`);
    }
  return [textFile('grid.obj', lines.join('\n'))];
});

const table = readFileSync(join(MODELS, 'table.gltf'), 'utf8');
const gltfModel = fc.record({ material: name, scale: fc.constantFrom(1, 10, 60, 200, 1e20), fileName: name }).map(({ material, scale, fileName }): MeshFile[] => {
  const json = JSON.parse(table);
  for (const m of json.materials) m.name = material;
  json.nodes[0].scale = [scale, scale, scale];
  return [textFile(`${fileName.replace(/[\\/\s]/g, '_')}.gltf`, JSON.stringify(json))];
});

describe('imports that are accepted and placed save and reopen (property, issue 32)', () => {
  it(`${RUNS} generated models`, async () => {
    const tally = { accepted: 0, placed: 0, refused: 0 };
    await fc.assert(
      fc.asyncProperty(fc.oneof({ arbitrary: objModel, weight: 6 }, { arbitrary: gridModel, weight: 1 }, { arbitrary: gltfModel, weight: 2 }), fc.constantFrom('auto' as const, ...MESH_UNITS), async (files, units) => {
        let imported;
        try {
          imported = await importMesh(files, { units });
        } catch (error) {
          if (!(error instanceof InputError)) throw error;
          tally.refused++;
          return;
        }
        tally.accepted++;
        const { problems, placed } = saveAndReopen(imported);
        if (placed) tally.placed++;
        expect(problems).toEqual([]);
      }),
      { seed: 32, numRuns: RUNS },
    );
    // The generators reach all three outcomes: refused, accepted and placed.
    expect(tally.refused).toBeGreaterThan(0);
    expect(tally.placed).toBeGreaterThan(RUNS / 10);
  }, 120_000);
});
