/**
 * Issue 32's limits on imported models: offsets, strides and counts checked against their buffers
 * before any read (app and CLI share packGltf), byte caps before decoding, the OBJ scan stopping
 * at its caps, only the default glTF scene built, count caps, extents in metres whatever the unit,
 * names cut to the scene file's 200 characters. Every model here is written by the test.
 */
import { mkdtempSync, writeFileSync } from 'node:fs';
import { readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { InputError } from '../../../src/core/inputError';
import { createNodeMeshLoader } from '../../../src/hosts/node/createNodeMeshLoader';
import { importMesh } from '../../../src/engines/meshImport/importMesh';
import { MODELS, textFile } from './modelFixtures';

type Gltf = Record<string, unknown> & { accessors: Record<string, unknown>[]; bufferViews: Record<string, unknown>[]; nodes: Record<string, unknown>[]; materials: Record<string, unknown>[]; scenes: unknown[] };
const table = (): Gltf => JSON.parse(readFileSync(join(MODELS, 'table.gltf'), 'utf8'));
const gltf = (j: Gltf, name = 'x.gltf') => textFile(name, JSON.stringify(j));

async function refusal(files: Parameters<typeof importMesh>[0], options = {}): Promise<string> {
  const error = await importMesh(files, options).catch((e: unknown) => e);
  expect(error).toBeInstanceOf(InputError);
  return (error as Error).message;
}

describe('glTF accessors and buffer views are checked before anything reads them', () => {
  it('a negative byteOffset on a POSITION accessor without min/max is refused in the app and in the CLI loader', async () => {
    const j = table();
    Object.assign(j.accessors[0], { byteOffset: -4, min: undefined, max: undefined });
    expect(await refusal([gltf(j)])).toBe('x.gltf: accessors[0].byteOffset -4 must be a whole number of bytes, at least 0');
    const dir = mkdtempSync(join(tmpdir(), 'luxbox-mesh-'));
    writeFileSync(join(dir, 'x.gltf'), JSON.stringify(j));
    await expect(createNodeMeshLoader(dir).load('x.gltf')).rejects.toThrow(new InputError('x.gltf: accessors[0].byteOffset -4 must be a whole number of bytes, at least 0'));
  });

  it.each<[string, (j: Gltf) => void, string]>([
    ['an offset past the view', (j) => (j.accessors[0].byteOffset = 12), 'x.gltf: accessors[0]: 8 elements of 12 bytes from byte 12 need 108 bytes, bufferViews[0] has 96'],
    ['an unaligned offset', (j) => (j.accessors[0].byteOffset = 2), 'x.gltf: accessors[0].byteOffset 2 is not a multiple of its component size 4'],
    ['a huge count', (j) => (j.accessors[0].count = 1e9), 'x.gltf: accessors[0].count 1000000000 is not a whole number from 1 to 1 048 576'],
    ['a stride that is not a multiple of 4', (j) => (j.bufferViews[0].byteStride = 13), 'x.gltf: bufferViews[0].byteStride 13 must be a multiple of 4 from 4 to 252'],
    ['a stride shorter than an element', (j) => (j.bufferViews[0].byteStride = 8), 'x.gltf: bufferViews[0].byteStride 8 is shorter than one element of accessors[0] (12 bytes)'],
    ['a stride that runs past the view', (j) => (j.bufferViews[0].byteStride = 16), 'x.gltf: accessors[0]: 8 elements of 12 bytes every 16 from byte 0 need 124 bytes, bufferViews[0] has 96'],
    ['a view past its buffer', (j) => (j.bufferViews[2].byteLength = 1000), 'x.gltf: bufferViews[2]: 1 000 bytes from byte 192 reach beyond the 264 bytes of buffers[0]'],
    ['an unknown component type', (j) => (j.accessors[1].componentType = 5130), 'x.gltf: accessors[1].componentType 5130 is not a glTF component type'],
  ])('%s', async (_, change, message) => {
    const j = table();
    change(j);
    expect(await refusal([gltf(j)])).toBe(message);
  });

  it('an index value past its POSITION accessor is refused naming the primitive, both accessors and the numbers', async () => {
    const j = table();
    const bin = Buffer.from((j.buffers as { uri: string }[])[0].uri.split(',')[1], 'base64');
    bin.writeUInt16LE(9, 192 + 2 * 5);
    (j.buffers as { uri: string }[])[0].uri = `data:application/octet-stream;base64,${bin.toString('base64')}`;
    expect(await refusal([gltf(j)])).toBe('x.gltf: meshes[0].primitives[0]: indices accessors[2][5] = 9, but POSITION accessors[0] has 8 vertices');
  });

  it('a sparse index past its accessor is refused (the index values themselves are read and checked)', async () => {
    const j = table();
    // The box's 36 triangle indices (0 … 7) as sparse indices of a 4-element accessor.
    Object.assign(j.accessors[0], { count: 4, min: undefined, max: undefined, sparse: { count: 4, indices: { bufferView: 2, componentType: 5123 }, values: { bufferView: 1 } } });
    expect(await refusal([gltf(j)])).toMatch(/^x\.gltf: accessors\[0\]\.sparse\.indices\[\d\] = [4-7] is past the accessor's 4 elements$/);
  });
});

describe('only the default scene is built; counts are capped', () => {
  it('a GLB-sized file declaring 200 000 scenes is refused at once, naming the cap', async () => {
    const j = table();
    j.scenes = Array.from({ length: 200_000 }, () => ({ nodes: [0] }));
    expect(await refusal([gltf(j)])).toBe('x.gltf: 200 000 scenes; at most 64 are read');
  });

  it('of 60 scenes only the default one (scene 1) is built', async () => {
    const j = table();
    j.nodes.push({ mesh: 1 });
    j.scenes = Array.from({ length: 60 }, (_, k) => ({ nodes: [k === 1 ? 6 : 0] }));
    j.scene = 1;
    const r = await importMesh([gltf(j)]);
    expect(r.triangleCount).toBe(12); // one leg
  });

  it('5 000 nodes are refused with the cap', async () => {
    const j = table();
    for (let k = 0; k < 5000; k++) j.nodes.push({});
    expect(await refusal([gltf(j)])).toBe('x.gltf: 5 006 nodes; at most 4 096 are read');
  });
});

describe('byte caps before decoding; the OBJ scan stops at its caps', () => {
  it('a 30 MB OBJ is refused by its size without being read', async () => {
    // Bytes that are not UTF-8 text: had the importer read them, the refusal would name the text, not the size.
    expect(await refusal([{ name: 'big.obj', bytes: new Uint8Array(30e6).fill(0xff) }])).toBe('big.obj: an OBJ file of 30 MB; at most 24 MB are read');
  });

  it('a 20 MB OBJ of vertices stops at the vertex cap', async () => {
    const line = new TextEncoder().encode('v 0.125 0.25 0.5\n');
    const bytes = new Uint8Array(Math.floor(20e6 / line.length) * line.length);
    for (let at = 0; at < bytes.length; at += line.length) bytes.set(line, at);
    expect(await refusal([{ name: 'v.obj', bytes }])).toBe('v.obj: more than 144 000 vertices; simplify the model and import again');
  });

  it('a GLB over 64 MB and a data URI over 24 MB are refused with their limits', async () => {
    const glb = new Uint8Array(65e6);
    new DataView(glb.buffer).setUint32(0, 0x46546c67, true);
    expect(await refusal([{ name: 'x.glb', bytes: glb }])).toBe('x.glb: a GLB file of 65 MB; at most 64 MB are read');
    const j = table();
    (j.buffers as { uri: string }[])[0].uri = `data:application/octet-stream;base64,${'A'.repeat(25e6)}`;
    expect(await refusal([gltf(j)])).toBe('x.gltf: glTF JSON of 25 MB; at most 24 MB are read');
  });

  it('a line continued past 1 MB is refused', async () => {
    expect(await refusal([textFile('x.obj', `v 0 0 0\n${'1 \\\n'.repeat(400_000)}`)])).toBe('x.obj: line 2 continues past 1024 kB: not a text OBJ file');
  });
});

describe('extents in metres whatever the unit choice; names cut to what a saved file accepts', () => {
  const tri = (x: number) => `v 0 0 0\nv ${x} 0 0\nv 0 0 1\nf 1 2 3\n`;

  it('a vertex at 3.4e38 is refused with an explicit unit too', async () => {
    expect(await refusal([textFile('far.obj', tri(3.4e38))], { units: 'mm' })).toBe("far.obj: a vertex lies 3.4e+35 m from the model's origin in mm; at most 100 m (no room is larger) — check the units or the file");
    expect(await refusal([textFile('far.obj', tri(3.4e38))], { units: 'm' })).toMatch(/^far\.obj: a vertex lies 3\.4e\+38 m/);
  });

  it('120 m in metres is refused; 50 m in metres warns', async () => {
    expect(await refusal([textFile('hall.obj', tri(120))], { units: 'm' })).toMatch(/^hall\.obj: a vertex lies 120 m/);
    const r = await importMesh([textFile('hall.obj', tri(50))], { units: 'm' });
    expect(r.warnings).toContain('hall.obj: 50 m across in m — check the units');
  });

  it('a 300-character material name and a 250-character file name are cut to 200 with a warning', async () => {
    const j = table();
    j.materials[0].name = 'ä'.repeat(300);
    const fileName = `${'n'.repeat(245)}.gltf`;
    const r = await importMesh([gltf(j, fileName)]);
    expect(r.mesh.materials[0].name).toBe('ä'.repeat(200));
    expect(r.name).toBe(fileName.slice(0, 200));
    expect(r.warnings).toContain(`${fileName}: material '${'ä'.repeat(39)}…' has 300 characters; cut to 200`);
    expect(r.warnings).toContain(`the model name '${'n'.repeat(39)}…' has 250 characters; cut to 200`);
  });
});
