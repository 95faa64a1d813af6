import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { InputError } from '../../../src/core/inputError';
import { importMesh } from '../../../src/engines/meshImport/importMesh';
import type { MeshFile } from '../../../src/engines/meshImport/importedMesh';
import { createRng, mutate, type Rng } from '../../fuzz/mutate';
import { modelFile, MODELS, textFile } from './modelFixtures';

const TRI = 'v 0 0 0\nv 1 0 0\nv 0 0 1\n';

describe('importMesh: broken files are InputErrors naming the file (and the OBJ line)', () => {
  it.each([
    ['no faces', 'v 0 0 0\nv 1 0 0\n', "bad.obj: no faces (luxbox needs a surface model with 'f' lines)"],
    ['a NaN coordinate', 'v 0 0 0\nv NaN 0 0\nv 0 0 1\nf 1 2 3\n', 'bad.obj: line 2: vertex coordinate "NaN" is not a finite number'],
    ['a short vertex', 'v 0 0\n', 'bad.obj: line 1: a vertex needs three coordinates, got 2'],
    ['an index out of range', `${TRI}f 1 2 4\n`, 'bad.obj: line 4: face refers to vertex 4, but 3 vertices are defined so far'],
    ['index 0', `${TRI}f 0 1 2\n`, 'bad.obj: line 4: face refers to vertex 0, but 3 vertices are defined so far'],
    ['a negative index too far back', `${TRI}f -1 -2 -4\n`, 'bad.obj: line 4: face refers to vertex -4, but 3 vertices are defined so far'],
    ['a two-vertex face', `${TRI}f 1 2\n`, 'bad.obj: line 4: a face needs at least 3 vertices, got 2'],
    ['a word for an index', `${TRI}f 1 2 three\n`, 'bad.obj: line 4: face vertex "three" is not a vertex index'],
    ['binary garbage', 'v 0 0 0\n\u0000\u0001\u0002garbage\nf 1 1 1\n', 'bad.obj: line 2: binary data (a NUL byte): not a text OBJ file'],
    ['only degenerate faces', `${TRI}f 1 1 2\n`, 'bad.obj: no triangles (luxbox needs a surface model)'],
  ])('OBJ with %s', async (_, text, message) => {
    await expect(importMesh([textFile('bad.obj', text)])).rejects.toThrow(new InputError(message));
  });

  it('negative (relative) indices and quads with texture/normal references read correctly', async () => {
    const r = await importMesh([textFile('ok.obj', `${TRI}vt 0 0\nvn 0 1 0\nf -3/1/1 -1/1/1 -2/1/1\n`)]);
    expect(r.triangleCount).toBe(1);
    // The front (moved 0.5 mm forward onto new vertices), then the back side on the file's corners (an OBJ surface is two-sided).
    expect(Array.from(r.mesh.indices)).toEqual([3, 4, 5, 0, 2, 1]);
  });

  it('statements luxbox does not use are named in one warning', async () => {
    const r = await importMesh([textFile('ok.obj', `${TRI}cstype bspline\nl 1 2\nf 1 3 2\n`)]);
    expect(r.warnings).toEqual(['ok.obj: statements luxbox does not use were ignored: "cstype" ×1, "l" ×1']);
  });

  const glb = (): Uint8Array => modelFile('table.glb').bytes;
  const withU32 = (bytes: Uint8Array, offset: number, value: number): Uint8Array => {
    const out = bytes.slice();
    new DataView(out.buffer).setUint32(offset, value, true);
    return out;
  };
  const gltfJson = (): Record<string, unknown> & { accessors: Record<string, unknown>[]; nodes: Record<string, unknown>[] } => JSON.parse(readFileSync(join(MODELS, 'table.gltf'), 'utf8'));

  it.each<[string, () => MeshFile, string]>([
    ['wrong GLB magic', () => ({ name: 'x.glb', bytes: withU32(glb(), 0, 0x12345678) }), 'x.glb: not a GLB file (the first 4 bytes are not "glTF")'],
    ['a GLB truncated', () => ({ name: 'x.glb', bytes: glb().slice(0, 1000) }), `x.glb: truncated: the header says ${glb().length.toLocaleString('en').replace(/,/g, ' ')} bytes, the file has 1 000`],
    ['a GLB length field too short', () => ({ name: 'x.glb', bytes: withU32(glb(), 8, 100) }), `x.glb: wrong length: the header says 100 bytes, the file has ${String(glb().length).replace(/\B(?=(\d{3})+(?!\d))/g, ' ')}`],
    ['a GLB of 10 bytes', () => ({ name: 'x.glb', bytes: glb().slice(0, 10) }), 'x.glb: truncated: 10 bytes is too short for a GLB'],
    ['GLB version 1', () => ({ name: 'x.glb', bytes: withU32(glb(), 4, 1) }), 'x.glb: GLB container version 1 (luxbox reads glTF 2.0)'],
    ['bad JSON', () => textFile('x.gltf', '{"asset": {"version": "2.0"},'), 'x.gltf: invalid JSON'],
    ['glTF 1.0', () => textFile('x.gltf', '{"asset": {"version": "1.0"}}'), 'x.gltf: asset.version "1.0" (luxbox reads glTF 2.0)'],
    ['no scene', () => textFile('x.gltf', '{"asset": {"version": "2.0"}}'), 'x.gltf: no scene'],
    [
      'a node cycle',
      () => {
        const j = gltfJson();
        j.nodes[1].children = [0];
        return textFile('x.gltf', JSON.stringify(j));
      },
      'x.gltf: nodes[0] appears twice in the node hierarchy (it must be a tree)',
    ],
    [
      'an index accessor past its buffer view',
      () => {
        const j = gltfJson();
        j.accessors[2].count = 5000;
        return textFile('x.gltf', JSON.stringify(j));
      },
      'x.gltf: accessors[2]: 5 000 elements of 2 bytes from byte 0 need 10 000 bytes, bufferViews[2] has 72',
    ],
    [
      'NaN positions',
      () => {
        const j = gltfJson();
        const bin = Buffer.from((j.buffers as { uri: string }[])[0].uri.split(',')[1], 'base64');
        bin.writeFloatLE(NaN, 0);
        (j.buffers as { uri: string }[])[0].uri = `data:application/octet-stream;base64,${bin.toString('base64')}`;
        return textFile('x.gltf', JSON.stringify(j));
      },
      'x.gltf: a vertex has a coordinate that is not a finite number',
    ],
    [
      'Draco compression',
      () => {
        const j = gltfJson();
        j.extensionsRequired = ['KHR_draco_mesh_compression'];
        return textFile('x.gltf', JSON.stringify(j));
      },
      'x.gltf: needs the extension KHR_draco_mesh_compression (compressed geometry; export without compression)',
    ],
  ])('glTF with %s', async (_, file, message) => {
    const error = await importMesh([file()]).catch((e: unknown) => e);
    expect(error).toBeInstanceOf(InputError);
    expect((error as Error).message.startsWith(message)).toBe(true);
  });

  it('a file luxbox does not read', async () => {
    await expect(importMesh([textFile('chair.fbx', 'Kaydara')])).rejects.toThrow(new InputError('chair.fbx: not a model luxbox reads (pick an .obj with its .mtl, or one .gltf or .glb)'));
  });
});

/** OBJ-aware corruptions on top of the fuzzer's generic ones: numbers become NaN or huge, indices leave the range, lines are cut. */
function corruptObj(text: string, rng: Rng): string {
  const lines = text.split('\n');
  const k = rng.int(lines.length);
  switch (rng.int(5)) {
    case 0:
      lines[k] = lines[k].replace(/-?\d+(\.\d+)?/, rng.pick(['NaN', '1e999', '-', '', '0x', '4294967297']));
      break;
    case 1:
      lines[k] = lines[k].replace(/\d+/, String(rng.int(100)));
      break;
    case 2:
      lines[k] = lines[k].slice(0, rng.int(lines[k].length + 1));
      break;
    case 3:
      lines.splice(k, 1);
      break;
    default:
      lines.splice(k, 0, rng.pick(['f', 'v', 'usemtl', 'mtllib', 'g', 'f 1/2/3/4', 'v 1 2 3 4 5 6 7', '\\']));
  }
  return lines.join('\n');
}

describe('importMesh: seeded fuzz of the fixtures (only InputError or a valid mesh)', () => {
  const seeds: MeshFile[][] = [[modelFile('table.obj'), modelFile('table.mtl')], [modelFile('table.gltf')], [modelFile('table.glb')], [modelFile('table-external.gltf'), modelFile('table-external.bin')]];

  it('150 mutants per fixture', async () => {
    const rng = createRng(20261123);
    const outcomes = { ok: 0, refused: 0 };
    for (const seed of seeds) {
      for (let n = 0; n < 150; n++) {
        const target = rng.int(seed.length);
        const files = seed.map((f, i) => {
          if (i !== target) return f;
          if (/\.obj$/.test(f.name) && rng.chance(0.5)) return textFile(f.name, corruptObj(new TextDecoder().decode(f.bytes), rng));
          return { name: f.name, bytes: mutate(f.bytes, rng, 'latin1').bytes };
        });
        let result;
        try {
          result = await importMesh(files);
        } catch (error) {
          if (!(error instanceof InputError)) throw new Error(`mutant ${n} of ${seed[0].name}: ${String(error)}`, { cause: error });
          expect(error.message).not.toMatch(/\n/);
          expect(error.message.length).toBeLessThanOrEqual(300);
          outcomes.refused++;
          continue;
        }
        // Accepted: a well-formed mesh.
        const { mesh } = result;
        const vertices = mesh.positions.length / 3;
        expect(mesh.positions.every(Number.isFinite)).toBe(true);
        expect(mesh.indices.every((i) => i < vertices)).toBe(true);
        expect(mesh.materialOfTriangle.length).toBe(mesh.indices.length / 3);
        expect(mesh.materialOfTriangle.every((m) => m < mesh.materials.length)).toBe(true);
        expect(mesh.materials.every((m) => m.reflectance.every((x) => x >= 0 && x < 1))).toBe(true);
        outcomes.ok++;
      }
    }
    // Both outcomes occur: the mutants reach past the first checks.
    expect(outcomes.ok).toBeGreaterThan(50);
    expect(outcomes.refused).toBeGreaterThan(50);
  }, 120_000);
});

describe('importMesh: quiet on files three would warn about', () => {
  it('POSITION without min/max (required by glTF 2.0 §3.7.2.1) is filled in: the same mesh, nothing on the console', async () => {
    const json = JSON.parse(readFileSync(join(MODELS, 'table.gltf'), 'utf8'));
    for (const a of json.accessors) {
      delete a.min;
      delete a.max;
    }
    const warn = console.warn;
    const said: unknown[] = [];
    console.warn = (...args: unknown[]) => said.push(args);
    try {
      const r = await importMesh([textFile('nobounds.gltf', JSON.stringify(json))]);
      expect(r.mesh.positions).toEqual((await importMesh([modelFile('table.gltf')])).mesh.positions);
    } finally {
      console.warn = warn;
    }
    expect(said).toEqual([]);
  });
});
