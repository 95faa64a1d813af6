import { describe, expect, it } from 'vitest';
import { placedPositions } from '../../../src/core/mesh/placeMesh';
import { furnitureMesh } from '../../../src/core/model/objects/furniture/furnitureLibrary';
import type { BakeObject } from '../../../src/engines/bake/bakeScene';
import { objectsRad } from '../../../src/engines/radiance/objectsRad';
import { toRadiance } from '../../../src/engines/radiance/radianceFrame';
import { parseRad } from './radianceSceneEvaluator';

type V = [number, number, number];
const sub = (a: V, b: V): V => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const cross = (a: V, b: V): V => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];

/** Area-weighted normal sum and area of triangles (any frame). */
function areaAndNormal(triangles: V[][]): { area: number; normal: V } {
  const normal: V = [0, 0, 0];
  let area = 0;
  for (const [a, b, c] of triangles) {
    const n = cross(sub(b, a), sub(c, a));
    area += Math.hypot(...n) / 2;
    for (let k = 0; k < 3; k++) normal[k] += n[k] / 2;
  }
  return { area, normal };
}

describe('objects in the Radiance export (docs/radiance.md)', () => {
  const sofa: BakeObject = { id: 'sofa', mesh: furnitureMesh('sofa'), position: [2, 0, 3], yaw: 30, scale: 1.25 };
  const table: BakeObject = { id: 'table', mesh: furnitureMesh('coffee-table'), position: [1, 0, 1], yaw: 0, scale: 1, reflectance: [0.6, 0.4, 0.2] };

  it('one polygon per triangle with the mesh’s placed corners, front faces kept, per-material and overriding reflectances', () => {
    const { rad, triangles } = objectsRad([sofa, table]);
    const primitives = parseRad(rad);
    const polygons = primitives.filter((p) => p.type === 'polygon');
    const materials = new Map(primitives.filter((p) => p.type === 'plastic').map((p) => [p.name, p.reals]));
    expect(polygons.length).toBe(triangles);
    for (const [o, object] of [sofa, table].entries()) {
      const world = placedPositions(object.mesh, object);
      const corner = (i: number): V => toRadiance([world[3 * i], world[3 * i + 1], world[3 * i + 2]]);
      const mine = polygons.filter((p) => p.name.startsWith(`object${o}_t`));
      expect(mine.length).toBe(object.mesh.indices.length / 3);
      // Same triangles in the same vertex order: area and area-weighted normal (the front side) agree.
      const expected = areaAndNormal(Array.from({ length: mine.length }, (_, t) => [0, 1, 2].map((k) => corner(object.mesh.indices[3 * t + k]))));
      const written = areaAndNormal(mine.map((p) => [0, 1, 2].map((k) => p.reals.slice(3 * k, 3 * k + 3) as V)));
      expect(written.area).toBeCloseTo(expected.area, 4);
      for (let k = 0; k < 3; k++) expect(written.normal[k]).toBeCloseTo(expected.normal[k], 4);
      // Placement scale: the sofa's area is 1.25² of its own mesh's.
      const local = areaAndNormal(Array.from({ length: mine.length }, (_, t) => [0, 1, 2].map((k) => Array.from(object.mesh.positions.slice(3 * object.mesh.indices[3 * t + k], 3 * object.mesh.indices[3 * t + k] + 3)) as V)));
      expect(written.area / local.area).toBeCloseTo(object.scale ** 2, 4);
      for (const p of mine) {
        const t = Number(p.name.slice(`object${o}_t`.length));
        const reals = materials.get(p.modifier)!;
        const rho = object.reflectance ?? object.mesh.materials[object.mesh.materialOfTriangle[t]].reflectance;
        expect(reals.slice(0, 3)).toEqual((typeof rho === 'number' ? [rho, rho, rho] : rho).map((x) => Number(x.toPrecision(7))));
        expect(reals.slice(3)).toEqual([0, 0]);
      }
    }
  });

  it('leaves degenerate triangles out (Radiance refuses them) and counts only what it writes', () => {
    const mesh = {
      positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0]),
      indices: new Uint32Array([0, 1, 2, 0, 1, 3]),
      materialOfTriangle: new Uint16Array([0, 0]),
      materials: [{ name: 'm', reflectance: [0.5, 0.5, 0.5] as [number, number, number] }],
    };
    const { rad, triangles } = objectsRad([{ id: 'flat', mesh, position: [0, 0, 0], yaw: 0, scale: 1 }]);
    expect(triangles).toBe(1);
    expect(parseRad(rad).filter((p) => p.type === 'polygon')).toHaveLength(1);
  });
});
