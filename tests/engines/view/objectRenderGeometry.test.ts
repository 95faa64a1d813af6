/**
 * The 3D view's object geometry (src/engines/view/objectRenderGeometry.ts) against the atlas the
 * baker lights: every triangle's centroid uv lands on a covered texel of its own object, the uvs
 * are the charts' isometric projection (atlas distance × texel size = world distance), and the
 * triangles are the placed meshes (same total area as prepareObjects measured).
 */
import { describe, expect, it } from 'vitest';
import { furnitureMesh } from '../../../src/core/model/objects/furniture/furnitureLibrary';
import type { BakeObject } from '../../../src/engines/bake/bakeScene';
import { prepareObjects } from '../../../src/engines/bake/objects/prepareObjects';
import { objectRenderGeometry } from '../../../src/engines/view/objectRenderGeometry';

const objects: BakeObject[] = [
  { id: 'table', mesh: furnitureMesh('dining-table'), position: [2.5, 0, 2], yaw: 0, scale: 1 },
  { id: 'chair', mesh: furnitureMesh('chair'), position: [1.2, 0, 2.4], yaw: 30, scale: 1.1 },
  { id: 'plant', mesh: furnitureMesh('floor-plant'), position: [4.2, 0, 0.5], yaw: 12, scale: 0.8 },
  { id: 'sofa', mesh: furnitureMesh('sofa'), position: [2.5, 0, 3.4], yaw: 180, scale: 1 },
];

function triangleArea(p: Float32Array, k: number): number {
  const e1 = [0, 1, 2].map((a) => p[9 * k + 3 + a] - p[9 * k + a]);
  const e2 = [0, 1, 2].map((a) => p[9 * k + 6 + a] - p[9 * k + a]);
  return 0.5 * Math.hypot(e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]);
}

describe('objectRenderGeometry', () => {
  for (const texelSize of [0.05, 0.1]) {
    const prepared = prepareObjects(objects, { texelSize });
    const geometry = objectRenderGeometry(prepared);
    const { atlas } = prepared;

    it(`texel ${texelSize} m: every triangle's centroid uv hits a covered texel of its own object`, () => {
      expect(geometry.triangleCount).toBe(prepared.triangleCount);
      let misses = 0;
      for (let k = 0; k < geometry.triangleCount; k++) {
        const u = (geometry.uvs[6 * k] + geometry.uvs[6 * k + 2] + geometry.uvs[6 * k + 4]) / 3;
        const v = (geometry.uvs[6 * k + 1] + geometry.uvs[6 * k + 3] + geometry.uvs[6 * k + 5]) / 3;
        const i = Math.floor(u * atlas.width);
        const j = Math.floor(v * atlas.height);
        const t = 4 * (j * atlas.width + i);
        const covered = atlas.position[t + 3] > 0;
        const sameObject = atlas.reflectance[t + 3] === geometry.objectOfTriangle[k] + 1;
        if (!covered || !sameObject) misses++;
      }
      expect(misses).toBe(0);
    });

    it(`texel ${texelSize} m: uvs are the charts' isometric projection (edge lengths within 1e-4 m)`, () => {
      let worst = 0;
      for (let k = 0; k < geometry.triangleCount; k++) {
        for (const [a, b] of [
          [0, 1],
          [1, 2],
          [2, 0],
        ]) {
          const world = Math.hypot(...[0, 1, 2].map((c) => geometry.positions[9 * k + 3 * b + c] - geometry.positions[9 * k + 3 * a + c]));
          const du = (geometry.uvs[6 * k + 2 * b] - geometry.uvs[6 * k + 2 * a]) * atlas.width;
          const dv = (geometry.uvs[6 * k + 2 * b + 1] - geometry.uvs[6 * k + 2 * a + 1]) * atlas.height;
          worst = Math.max(worst, Math.abs(Math.hypot(du, dv) * atlas.texelSize - world));
        }
      }
      expect(worst).toBeLessThan(1e-4);
    });

    it(`texel ${texelSize} m: the triangles are the placed meshes (area per object within 1e-5 relative), normals unit`, () => {
      const area = new Float64Array(prepared.objects.length);
      for (let k = 0; k < geometry.triangleCount; k++) area[geometry.objectOfTriangle[k]] += triangleArea(geometry.positions, k);
      prepared.objects.forEach((o, i) => expect(Math.abs(area[i] - o.area) / o.area).toBeLessThan(1e-5));
      expect(geometry.ids).toEqual(['table', 'chair', 'plant', 'sofa']);
      for (let k = 0; k < geometry.normals.length; k += 3) expect(Math.hypot(geometry.normals[k], geometry.normals[k + 1], geometry.normals[k + 2])).toBeCloseTo(1, 5);
    });
  }
});
