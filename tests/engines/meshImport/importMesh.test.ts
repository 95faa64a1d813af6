import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { InputError } from '../../../src/core/inputError';
import { importMesh } from '../../../src/engines/meshImport/importMesh';
import { importObjMesh } from '../../../src/engines/meshImport/importObjMesh';
import { MAX_REFLECTANCE } from '../../../src/engines/meshImport/clampReflectance';
import { areaByMaterial, isClosedAndConsistent, modelFile, MODELS, signedVolume, TABLE, textFile } from './modelFixtures';

const F32 = 1e-6;

function expectBounds(actual: { min: number[]; max: number[] }, min: number[], max: number[], tol = F32): void {
  actual.min.forEach((v, a) => expect(v).toBeCloseTo(min[a], -Math.log10(tol)));
  actual.max.forEach((v, a) => expect(v).toBeCloseTo(max[a], -Math.log10(tol)));
}

describe('importMesh: the fixture table in every format', () => {
  it('OBJ + MTL: 60 triangles, the table bounds, two materials with Kd as ρ, closed and outward', async () => {
    const r = await importMesh([modelFile('table.obj'), modelFile('table.mtl')]);
    expect(r.name).toBe('table.obj');
    expect(r.triangleCount).toBe(TABLE.triangles);
    expect(r.units).toBe('m');
    expect(r.detectedUnits).toBe('m');
    expect(r.warnings).toEqual([]);
    expectBounds(r.bounds, [-0.6, 0, -0.4], [0.6, 0.75, 0.4]);
    expect(r.mesh.materials).toEqual([
      { name: 'top', reflectance: [0.6, 0.45, 0.3] },
      { name: 'legs', reflectance: [0.2, 0.2, 0.2] },
    ]);
    // Welded: 5 boxes × 8 corners, each box closed with its edges shared by opposite windings.
    expect(r.mesh.positions.length / 3).toBe(40);
    expect(isClosedAndConsistent(r.mesh)).toBe(true);
    expect(signedVolume(r.mesh)).toBeCloseTo(TABLE.volume, 6);
    const [top, legs] = areaByMaterial(r.mesh);
    expect(top).toBeCloseTo(TABLE.topArea, 5);
    expect(top + legs).toBeCloseTo(TABLE.area, 5);
  });

  it('glTF with an embedded buffer: the same table; one leg mesh placed by four nodes', async () => {
    const r = await importMesh([modelFile('table.gltf')]);
    expect(r.triangleCount).toBe(TABLE.triangles);
    expect(r.units).toBe('m');
    expect(r.warnings).toEqual([]);
    expectBounds(r.bounds, [-0.6, 0, -0.4], [0.6, 0.75, 0.4]);
    expect(r.mesh.materials.map((m) => m.name)).toEqual(['top', 'legs']);
    // baseColorFactor read from the JSON as written (linear by the glTF spec).
    expect(r.mesh.materials[0].reflectance).toEqual([0.6, 0.45, 0.3]);
    expect(r.mesh.materials[1].reflectance).toEqual([0.2, 0.2, 0.2]);
    expect(isClosedAndConsistent(r.mesh)).toBe(true);
    expect(signedVolume(r.mesh)).toBeCloseTo(TABLE.volume, 6);
    expect(areaByMaterial(r.mesh)[0]).toBeCloseTo(TABLE.topArea, 5);
  });

  it('GLB: the root node turned 90° about +y swaps the x and z extents; winding stays outward', async () => {
    const r = await importMesh([modelFile('table.glb')]);
    expect(r.triangleCount).toBe(TABLE.triangles);
    expectBounds(r.bounds, [-0.4, 0, -0.6], [0.4, 0.75, 0.6], 1e-5);
    expect(signedVolume(r.mesh)).toBeCloseTo(TABLE.volume, 5);
    expect(isClosedAndConsistent(r.mesh)).toBe(true);
  });

  it('glTF with an external .bin: found among the picked files, or through readFile; missing is an InputError', async () => {
    const withFile = await importMesh([modelFile('table-external.gltf'), modelFile('table-external.bin')]);
    expect(withFile.triangleCount).toBe(TABLE.triangles);
    const asked: string[] = [];
    const viaReader = await importMesh([modelFile('table-external.gltf')], {
      readFile: async (name) => {
        asked.push(name);
        return new Uint8Array(readFileSync(join(MODELS, name)));
      },
    });
    expect(asked).toEqual(['table-external.bin']);
    expect(viaReader.mesh.positions).toEqual(withFile.mesh.positions);
    await expect(importMesh([modelFile('table-external.gltf')])).rejects.toThrow(new InputError('table-external.gltf: buffers[0]: table-external.bin is missing (pick it together with table-external.gltf)'));
  });

  it('a mirroring node transform keeps the faces counterclockwise from outside', async () => {
    const json = JSON.parse(readFileSync(join(MODELS, 'table.gltf'), 'utf8'));
    json.nodes[0].scale = [-1, 1, 1];
    const r = await importMesh([textFile('mirrored.gltf', JSON.stringify(json))]);
    expect(signedVolume(r.mesh)).toBeCloseTo(TABLE.volume, 6);
  });

  it('the OBJ path is also synchronous (importObjMesh), with the same result', async () => {
    const files = [modelFile('table.obj'), modelFile('table.mtl')];
    const sync = importObjMesh(files);
    const async = await importMesh(files);
    expect(sync.mesh.positions).toEqual(async.mesh.positions);
    expect(sync.mesh.indices).toEqual(async.mesh.indices);
  });
});

describe('importMesh: materials', () => {
  it('a missing MTL: every material grey 0.5, with a warning naming the library', async () => {
    const r = await importMesh([modelFile('table.obj')]);
    expect(r.mesh.materials).toEqual([
      { name: 'top', reflectance: [0.5, 0.5, 0.5] },
      { name: 'legs', reflectance: [0.5, 0.5, 0.5] },
    ]);
    expect(r.warnings).toEqual(['table.obj: material library table.mtl not found; its materials are grey 0.5']);
  });

  it('Kd ≥ 1 is clamped below 1, and a material the MTL lacks is grey, each with a warning', async () => {
    const obj = 'mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 0 1\nv 0 1 0\nusemtl white\nf 1 3 2\nusemtl ghost\nf 1 2 4\n';
    const r = await importMesh([textFile('t.obj', obj), textFile('m.mtl', 'newmtl white\nKd 1 1 1.2\n')]);
    expect(r.mesh.materials).toEqual([
      { name: 'white', reflectance: [MAX_REFLECTANCE, MAX_REFLECTANCE, MAX_REFLECTANCE] },
      { name: 'ghost', reflectance: [0.5, 0.5, 0.5] },
    ]);
    expect(r.warnings).toEqual([`m.mtl: material 'white': Kd [1, 1, 1.2] clamped to [0, ${MAX_REFLECTANCE}] → [${MAX_REFLECTANCE}, ${MAX_REFLECTANCE}, ${MAX_REFLECTANCE}]`, "t.obj: material 'ghost' is not defined in m.mtl; grey 0.5 used"]);
    // Two open triangles from an OBJ (no sides in the format): their back sides follow with the same materials.
    expect(Array.from(r.mesh.materialOfTriangle)).toEqual([0, 1, 0, 1]);
    expect(r.orientation).toMatchObject({ twoSided: 1, backTriangles: 2 });
  });

  it('a glTF base-colour texture: the factor is used, with a warning', async () => {
    const json = JSON.parse(readFileSync(join(MODELS, 'table.gltf'), 'utf8'));
    json.materials[0].pbrMetallicRoughness.baseColorTexture = { index: 0 };
    json.textures = [{ source: 0 }];
    json.images = [{ uri: 'wood.png' }];
    const r = await importMesh([textFile('textured.gltf', JSON.stringify(json))]);
    expect(r.mesh.materials[0].reflectance).toEqual([0.6, 0.45, 0.3]);
    expect(r.warnings).toEqual(["textured.gltf: material 'top' has a base-colour texture; luxbox uses its base colour factor"]);
  });
});

describe('importMesh: units', () => {
  const tableIn = (factor: number): string => readFileSync(join(MODELS, 'table.obj'), 'utf8').replace(/^v (\S+) (\S+) (\S+)$/gm, (_, x, y, z) => `v ${x * factor} ${y * factor} ${z * factor}`);

  it.each([
    [1, 'm'],
    [100, 'cm'],
  ] as const)('the table written ×%d is detected as %s and comes out in metres', async (factor, unit) => {
    const r = await importMesh([textFile('t.obj', tableIn(factor)), modelFile('table.mtl')]);
    expect(r.detectedUnits).toBe(unit);
    expect(r.units).toBe(unit);
    expectBounds(r.bounds, [-0.6, 0, -0.4], [0.6, 0.75, 0.4], 1e-5);
  });

  it('the rule prefers m, then cm, then mm: a 4 m kitchen in mm (4000) is mm, the 1.2 m table in mm (1200) reads as 12 m in cm', async () => {
    const kitchen = 'v 0 0 0\nv 4000 0 0\nv 0 900 600\nf 1 2 3\n';
    expect((await importMesh([textFile('k.obj', kitchen)])).detectedUnits).toBe('mm');
    const table = await importMesh([textFile('t.obj', tableIn(1000)), modelFile('table.mtl')]);
    expect(table.detectedUnits).toBe('cm');
    expect(table.bounds.max[0] - table.bounds.min[0]).toBeCloseTo(12, 4);
    const fixed = await importMesh([textFile('t.obj', tableIn(1000)), modelFile('table.mtl')], { units: 'mm' });
    expectBounds(fixed.bounds, [-0.6, 0, -0.4], [0.6, 0.75, 0.4], 1e-5);
  });

  it('an override wins: the cm table read as metres is 120 m long (with a warning); inches scale by 0.0254', async () => {
    const asMetres = await importMesh([textFile('t.obj', tableIn(100)), modelFile('table.mtl')], { units: 'm' });
    expect(asMetres.detectedUnits).toBe('cm');
    expect(asMetres.units).toBe('m');
    expect(asMetres.bounds.max[0] - asMetres.bounds.min[0]).toBeCloseTo(120, 4);
    expect(asMetres.warnings).toEqual(['t.obj: 120 m across in m — check the units']);
    const inches = await importMesh([textFile('t.obj', tableIn(1 / 0.0254)), modelFile('table.mtl')], { units: 'in' });
    expectBounds(inches.bounds, [-0.6, 0, -0.4], [0.6, 0.75, 0.4], 1e-5);
  });

  it('no plausible unit (a 1 mm speck in metres): metres assumed, with a warning', async () => {
    const r = await importMesh([textFile('speck.obj', 'v 0 0 0\nv 0.001 0 0\nv 0 0.001 0\nf 1 2 3\n')]);
    expect(r.units).toBe('m');
    expect(r.warnings[0]).toBe('speck.obj: its largest extent (0.001 file units) is not a plausible object size in m, cm, mm or inches (0.05–30 m); metres assumed');
  });

  it('glTF is metres by specification, whatever its size', async () => {
    const json = JSON.parse(readFileSync(join(MODELS, 'table.gltf'), 'utf8'));
    json.nodes[0].scale = [100, 100, 100];
    const r = await importMesh([textFile('big.gltf', JSON.stringify(json))]);
    expect(r.detectedUnits).toBe('m');
    expect(r.bounds.max[0]).toBeCloseTo(60, 4);
    const asCm = await importMesh([textFile('big.gltf', JSON.stringify(json))], { units: 'cm' });
    expect(asCm.bounds.max[0]).toBeCloseTo(0.6, 5);
  });
});

describe('importMesh: the triangle budget (48 000, what a saved configuration holds)', () => {
  /** An n×n grid of quads in the xz plane, 2n² triangles. */
  const grid = (n: number): string => {
    const lines: string[] = [];
    for (let j = 0; j <= n; j++) for (let i = 0; i <= n; i++) lines.push(`v ${i / n} 0 ${j / n}`);
    for (let j = 0; j < n; j++)
      for (let i = 0; i < n; i++) {
        const a = j * (n + 1) + i + 1;
        lines.push(`f ${a} ${a + n + 1} ${a + n + 2} ${a + 1}`);
      }
    return lines.join('\n');
  };

  it('155² quads = 48 050 triangles are refused while scanning, with the limit and what to do', async () => {
    await expect(importMesh([textFile('kitchen.obj', grid(155))])).rejects.toThrow(
      new InputError("kitchen.obj has more than 48 000 triangles; the limit is 48 000 (what a saved configuration holds) — simplify the model (e.g. Blender's Decimate) and import again"),
    );
  });

  it('an open OBJ sheet is stored with its back side (issue #35): 91² quads (16 562 triangles, 33 124 stored) load; 92² quads are refused by their stored size', async () => {
    const r = await importMesh([textFile('floor.obj', grid(91))]);
    expect(r.triangleCount).toBe(16_562);
    expect(r.mesh.indices.length / 3).toBe(2 * 16_562);
    await expect(importMesh([textFile('floor.obj', grid(92))])).rejects.toThrow(
      new InputError('floor.obj: 33 856 triangles on 17 298 vertices take 0.91 MB in a saved configuration; at most 0.90 MB fit — simplify the model and import again'),
    );
  }, 30_000);

  it('a model under the triangle budget whose vertices are not shared is refused by its stored size, with the numbers', async () => {
    // 40 000 separate triangles (each an open surface, stored with its back side): 240 000 vertices, 12 bytes each, do not fit in 0.9 MB of base64.
    const lines: string[] = [];
    for (let t = 0; t < 40_000; t++) {
      const x = (t % 200) / 200;
      const z = Math.floor(t / 200) / 200;
      lines.push(`v ${x} 0 ${z}`, `v ${x + 0.004} 0 ${z}`, `v ${x} 0 ${z + 0.004}`, 'f -3 -1 -2');
    }
    await expect(importMesh([textFile('soup.obj', lines.join('\n'))])).rejects.toThrow(
      new InputError('soup.obj: 80 000 triangles on 240 000 vertices take 5.33 MB in a saved configuration; at most 0.90 MB fit — simplify the model and import again'),
    );
  }, 30_000);

  it('a glTF is counted from its JSON before any geometry is built', async () => {
    const json = JSON.parse(readFileSync(join(MODELS, 'table.gltf'), 'utf8'));
    // 3 996 more uses of the table's 12-triangle top: 48 012 triangles.
    for (let k = 0; k < 3996; k++) {
      json.nodes[0].children.push(json.nodes.length);
      json.nodes.push({ mesh: 0 });
    }
    await expect(importMesh([textFile('huge.gltf', JSON.stringify(json))])).rejects.toThrow(
      new InputError("huge.gltf has 48 012 triangles; the limit is 48 000 (what a saved configuration holds) — simplify the model (e.g. Blender's Decimate) and import again"),
    );
  });
});
