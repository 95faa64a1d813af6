/**
 * L3D OBJ parts as triangle meshes (docs/gldf.md, "L3D geometry"): the hand-made track spot of
 * buildL3d.ts (a 20-unit cube per part: adapter and yoke in mm, head in cm; swivel joint 3 cm
 * below the adapter, tilt joint 6 cm below that) read, unit-scaled, placed by its parts' and
 * joints' positions and turned from L3D's Z up to luxbox's y up: (x, y, z) → (x, z, −y). Bounds
 * are checked against the values worked out by hand from structure.xml (1e-6 m: float32).
 * A part over the triangle budget is refused naming the container and the entry.
 */
import { describe, expect, it } from 'vitest';
import { readL3dStructure } from '../../../src/core/gldf/readL3dStructure';
import { positionBounds } from '../../../src/core/mesh/triangleMesh';
import { l3dLocalTransform, readL3dMeshes } from '../../../src/engines/meshImport/readL3dMeshes';
import { formatCount, MAX_IMPORT_TRIANGLES } from '../../../src/engines/meshImport/triangleBudget';
import { encode, l3d, STRUCTURE } from '../../core/gldf/buildL3d';

const read = (bytes: Uint8Array) => {
  const { luminaire, zip } = readL3dStructure(bytes, 'spot.l3d');
  return readL3dMeshes(luminaire, zip);
};

function expectBounds(actual: { min: number[]; max: number[] }, min: number[], max: number[]): void {
  for (let a = 0; a < 3; a++) {
    expect(actual.min[a]).toBeCloseTo(min[a], 6);
    expect(actual.max[a]).toBeCloseTo(max[a], 6);
  }
}

/** A W×H grid of quads in the z = 0 plane, two triangles each. */
function gridObj(w: number, h: number): Uint8Array {
  const lines: string[] = [];
  for (let j = 0; j <= h; j++) for (let i = 0; i <= w; i++) lines.push(`v ${i} ${j} 0`);
  const v = (i: number, j: number): number => j * (w + 1) + i + 1;
  for (let j = 0; j < h; j++) for (let i = 0; i < w; i++) lines.push(`f ${v(i, j)} ${v(i + 1, j)} ${v(i + 1, j + 1)}`, `f ${v(i, j)} ${v(i + 1, j + 1)} ${v(i, j + 1)}`);
  return encode(lines.join('\n'));
}

describe('L3D parts as triangle meshes', () => {
  it('reads each part in its units, placed under its joints, Z up turned to y up', () => {
    const { parts, warnings } = read(l3d());
    expect(warnings).toEqual([]);
    expect(parts.map((p) => [p.partName, p.entry, p.triangleCount, p.joints])).toEqual([
      ['adapter', 'adapter/adapter.obj', 12, []],
      ['yoke', 'yoke/yoke.obj', 12, ['swivel']],
      ['head', 'head/head.obj', 12, ['swivel', 'tilt']],
    ]);
    // L3D x 0..a, y 0..a, z z0..z0+a → luxbox x 0..a, y z0..z0+a, z −a..0.
    const [adapter, yoke, head] = parts.map((p) => positionBounds(p.mesh.positions));
    expectBounds(adapter, [0, 0, -0.02], [0.02, 0.02, 0]);
    expectBounds(yoke, [0, -0.03, -0.02], [0.02, -0.01, 0]);
    expectBounds(head, [0, -0.09, -0.2], [0.2, 0.11, 0]);
    // Closed cubes: no back sides added, 12 triangles each, every index in range.
    for (const p of parts) {
      expect(p.mesh.indices.length).toBe(36);
      expect(Math.max(...p.mesh.indices)).toBeLessThan(p.mesh.positions.length / 3);
    }
  });

  it('a part’s rotation turns it about its own origin; a quarter turn about L3D z moves +x to +y (luxbox −z)', () => {
    const xml = STRUCTURE.replace('<Geometry partName="adapter">\n      <Position x="0" y="0" z="0"/><Rotation x="0" y="0" z="0"/>', '<Geometry partName="adapter">\n      <Position x="1" y="0" z="0"/><Rotation x="0" y="0" z="90"/>');
    const [adapter, yoke] = read(l3d(xml)).parts.map((p) => positionBounds(p.mesh.positions));
    // Rz(90°): (x, y) → (−y, x), then moved 1 m along x: x 0.98..1, y 0..0.02 → luxbox x 0.98..1, z −0.02..0.
    expectBounds(adapter, [0.98, 0, -0.02], [1, 0.02, 0]);
    // The children turn with it: the yoke's frame is the adapter's.
    expectBounds(yoke, [0.98, -0.03, -0.02], [1, -0.01, 0]);
  });

  it('rotations compose as Rz·Rx·Ry (about the part’s own axes, Z first): x 90° and z 90° take +x to +z', () => {
    const m = l3dLocalTransform([0, 0, 0], [90, 0, 90]);
    // On a vector Rz·Rx·Ry acts right to left: +x → (Ry: y 0) +x → (Rx 90°) +x → (Rz 90°) +y; +y → +y → +z → +z; +z → +z → −y → +x.
    // (Read the other way, Rz then Rx about fixed axes, +x would end at +z: the test tells the two apart.)
    const apply = (v: number[]): number[] => [0, 1, 2].map((r) => m[r * 4] * v[0] + m[r * 4 + 1] * v[1] + m[r * 4 + 2] * v[2]);
    expect(apply([1, 0, 0])).toEqual([0, 1, 0]);
    expect(apply([0, 1, 0])).toEqual([0, 0, 1]);
    expect(apply([0, 0, 1])).toEqual([1, 0, 0]);
  });

  it('an L3D unit the mesh importer lacks (dm) is read as metres and scaled', () => {
    const xml = STRUCTURE.replace('id="head" filename="head.obj" units="cm"', 'id="head" filename="head.obj" units="dm"');
    const head = positionBounds(read(l3d(xml)).parts[2].mesh.positions);
    // 20 dm = 2 m cube below the tilt joint at z = −0.09.
    expectBounds(head, [0, -0.09, -2], [2, 1.91, 0]);
  });

  it('a part over the triangle budget is refused naming the container and the entry', () => {
    const grid = gridObj(156, 155);
    expect(156 * 155 * 2).toBeGreaterThan(MAX_IMPORT_TRIANGLES);
    expect(() => read(l3d(STRUCTURE, { 'yoke/yoke.obj': grid }))).toThrow(
      new RegExp(`^spot\\.l3d: entry 'yoke/yoke\\.obj': yoke\\.obj has more than ${formatCount(MAX_IMPORT_TRIANGLES)} triangles; the limit is ${formatCount(MAX_IMPORT_TRIANGLES)}`),
    );
  });

  it('parts each within the budget but over it together are refused, naming the container', () => {
    // Three open grids of 16 100 triangles each (32 200 with their back sides, within a saved file's size): 48 300 in all.
    const part = gridObj(115, 70);
    expect(() => read(l3d(STRUCTURE, { 'adapter/adapter.obj': part, 'yoke/yoke.obj': part, 'head/head.obj': part }))).toThrow(/^spot\.l3d: its 3 parts have 48 300 triangles together; the limit is 48 000/);
  });

  it('an OBJ the importer refuses is named with its entry', () => {
    expect(() => read(l3d(STRUCTURE, { 'head/head.obj': encode('v 0 0 0\nv 1 0 0\nf 1 2 9\n') }))).toThrow(/^spot\.l3d: entry 'head\/head\.obj': /);
  });
});
