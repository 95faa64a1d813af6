/**
 * prepareObjects (src/engines/bake/objects): the atlas charts and their G-buffer, and the flattened
 * BVH, checked against independent computations from the placed meshes (areas from cross products,
 * point–triangle distances, the triangles' own atlas uv footprints). The charts are in
 * prepareObjectsCharts.test.ts.
 */
import { describe, expect, it } from 'vitest';
import { InputError } from '../../../../src/core/inputError';
import { createObjectRayCaster } from '../../../../src/engines/bake/objects/createObjectRayCaster';
import { prepareObjects } from '../../../../src/engines/bake/objects/prepareObjects';
import { createRng } from '../../../fuzz/mutate';
import { sceneTriangles } from './bruteForceRays';
import { boxMesh, placed, testScene, triangleSoup } from './objectFixtures';
import { atlas, chartTriangles, cross, dot, objects, pointTriangleDistance, prepared, sub, type V3 } from './prepareObjectsKit';

describe('prepareObjects: G-buffer', () => {
  it('Σ coverage · texelSize² per object equals its area within 2 % (exact clipping: within 1e-4)', () => {
    const sums = prepared.objects.map(() => 0);
    const counts = prepared.objects.map(() => 0);
    for (let g = 0; g < atlas.position.length; g += 4) {
      if (atlas.position[g + 3] === 0) continue;
      const k = atlas.reflectance[g + 3] - 1;
      sums[k] += atlas.position[g + 3] * atlas.texelSize ** 2;
      counts[k]++;
    }
    objects.forEach((o, k) => {
      const tris = sceneTriangles([o]);
      let area = 0;
      for (let t = 0; t < tris.count; t++) {
        const P = tris.positions;
        const v = [0, 1, 2].map((c): V3 => [P[9 * t + 3 * c], P[9 * t + 3 * c + 1], P[9 * t + 3 * c + 2]]);
        area += Math.hypot(...cross(sub(v[1], v[0]), sub(v[2], v[0]))) / 2;
      }
      expect(prepared.objects[k].area).toBeCloseTo(area, 9);
      expect(Math.abs(sums[k] - area) / area).toBeLessThan(1e-4);
      expect(prepared.objects[k].texelCount).toBe(counts[k]);
    });
    // The boxes' areas analytically: 2(wh + wd + hd), scaled.
    expect(prepared.objects[0].area).toBeCloseTo(2 * (1.2 * 0.75 + 1.2 * 0.8 + 0.75 * 0.8), 5);
    expect(prepared.objects[2].area).toBeCloseTo(6 * 0.25, 5);
  });

  it('every covered texel has its point on a triangle of its chart (< 1e-5 m), the normal of that plane, and lies in its object bounds', () => {
    const byChart = chartTriangles(prepared);
    const bad: string[] = [];
    let covered = 0;
    for (let g = 0; g < atlas.position.length; g += 4) {
      const values = [0, 1, 2, 3].flatMap((a) => [atlas.position[g + a], atlas.normal[g + a], atlas.reflectance[g + a]]);
      if (!values.every(Number.isFinite)) bad.push(`texel ${g / 4}: not finite`);
      if (atlas.position[g + 3] === 0) {
        if (values.some((v) => v !== 0)) bad.push(`empty texel ${g / 4} is not all 0`);
        continue;
      }
      covered++;
      const p: V3 = [atlas.position[g], atlas.position[g + 1], atlas.position[g + 2]];
      const n: V3 = [atlas.normal[g], atlas.normal[g + 1], atlas.normal[g + 2]];
      const tris = byChart.get(atlas.normal[g + 3] - 1)!;
      let best = Infinity;
      let bestNormal: V3 = [0, 0, 0];
      for (const tri of tris) {
        const d = pointTriangleDistance(p, tri);
        if (d < best) {
          best = d;
          const c = cross(sub(tri[1], tri[0]), sub(tri[2], tri[0]));
          const l = Math.hypot(...c);
          bestNormal = [c[0] / l, c[1] / l, c[2] / l];
        }
      }
      if (!(best < 1e-5)) bad.push(`texel ${g / 4}: ${best} m from its chart`);
      if (!(dot(n, bestNormal) > 1 - 1e-6) || Math.abs(Math.hypot(...n) - 1) > 1e-6) bad.push(`texel ${g / 4}: normal ${n} vs ${bestNormal}`);
      const info = prepared.objects[atlas.reflectance[g + 3] - 1];
      for (let a = 0; a < 3; a++) {
        if (p[a] < info.bounds.min[a] - 1e-5 || p[a] > info.bounds.max[a] + 1e-5) bad.push(`texel ${g / 4}: outside ${info.id}'s bounds`);
      }
      if (!(atlas.position[g + 3] > 0 && atlas.position[g + 3] <= 1)) bad.push(`texel ${g / 4}: coverage ${atlas.position[g + 3]}`);
    }
    expect(bad.slice(0, 10)).toEqual([]);
    expect(covered).toBe(prepared.objects.reduce((s, o) => s + o.texelCount, 0));
  });

  it("reflectance is the object's override, else the triangle's material, clamped to [0, 0.999]", () => {
    const soup = triangleSoup(3, 40, 0, 1, 0.2);
    const p = prepareObjects([placed('grey', boxMesh(1, 1, 1, 0.3), [1, 0, 1]), { ...placed('bright', boxMesh(1, 1, 1), [3, 0, 1]), reflectance: [1.5, 0.2, -1] }, placed('soup', soup, [0, 0, 3])], { texelSize: 0.1 });
    const seen = new Set<string>();
    for (let g = 0; g < p.atlas.reflectance.length; g += 4) {
      if (p.atlas.position[g + 3] === 0) continue;
      seen.add(`${p.atlas.reflectance[g + 3]}: ${Array.from(p.atlas.reflectance.subarray(g, g + 3)).map((x) => x.toFixed(3))}`);
    }
    expect([...seen].sort()).toEqual(['1: 0.300,0.300,0.300', '2: 0.999,0.200,0.000', '3: 0.200,0.400,0.600', '3: 0.700,0.700,0.700']);
  });

  it('atlas uv of a point on a triangle names a texel whose sample point is within half a texel diagonal', () => {
    const rng = createRng(5);
    const T = prepared.bvh.triangles;
    const caster = createObjectRayCaster(prepared);
    const reach = (atlas.texelSize * Math.SQRT2) / 2 + 1e-5;
    let checked = 0;
    for (let r = 0; r < 1500; r++) {
      // A ray straight at a random point of a random triangle, from 2 cm in front of it.
      const k = rng.int(prepared.triangleCount);
      const o = 16 * k;
      let a = rng.next(),
        b = rng.next();
      if (a + b > 1) [a, b] = [1 - a, 1 - b];
      const point: V3 = [0, 1, 2].map((i) => T[o + i] + a * T[o + 4 + i] + b * T[o + 8 + i]) as V3;
      const n = cross([T[o + 4], T[o + 5], T[o + 6]], [T[o + 8], T[o + 9], T[o + 10]]);
      const l = Math.hypot(...n);
      const origin: V3 = [0, 1, 2].map((i) => point[i] + (0.02 * n[i]) / l) as V3;
      const hit = caster.closestHit(origin, sub(point, origin), 2);
      if (!hit || Math.abs(hit.t - 1) > 1e-6) continue; // another triangle in between
      expect(hit.frontFace).toBe(true);
      const i = Math.floor(hit.atlasUv[0] * atlas.width);
      const j = Math.floor(hit.atlasUv[1] * atlas.height);
      const g = 4 * (j * atlas.width + i);
      expect(atlas.position[g + 3]).toBeGreaterThan(0);
      expect(atlas.normal[g + 3] - 1).toBe(T[o + 11]);
      expect(Math.hypot(...sub([atlas.position[g], atlas.position[g + 1], atlas.position[g + 2]], point))).toBeLessThan(reach);
      checked++;
    }
    expect(checked).toBeGreaterThan(1000);
  });

  it('is deterministic: the same input gives identical arrays', () => {
    const again = prepareObjects(testScene(), { texelSize: 0.05 });
    const bytes = (a: Float32Array): Buffer => Buffer.from(a.buffer, a.byteOffset, a.byteLength);
    for (const name of ['position', 'normal', 'reflectance'] as const) expect(bytes(again.atlas[name]).equals(bytes(atlas[name]))).toBe(true);
    for (const name of ['nodes', 'triangles'] as const) expect(bytes(again.bvh[name]).equals(bytes(prepared.bvh[name]))).toBe(true);
    const { atlas: a1, bvh: b1, ...rest1 } = again;
    const { atlas: a0, bvh: b0, ...rest0 } = prepared;
    expect(rest1).toEqual(rest0);
    expect([a1.width, a1.height, a1.texelSize, b1.nodesHeight, b1.trianglesHeight]).toEqual([a0.width, a0.height, a0.texelSize, b0.nodesHeight, b0.trianglesHeight]);
  });
});

describe('prepareObjects: atlas size', () => {
  it('a huge mesh with a tiny texel grows texelSize by 1.25 steps and stays within maxAtlasSize', () => {
    const p = prepareObjects([placed('hall', boxMesh(40, 10, 30), [20, 0, 15])], { texelSize: 0.01, maxAtlasSize: 256 });
    expect(p.atlas.width).toBeLessThanOrEqual(256);
    expect(p.atlas.height).toBeLessThanOrEqual(256);
    const steps = Math.log(p.atlas.texelSize / 0.01) / Math.log(1.25);
    expect(Math.abs(steps - Math.round(steps))).toBeLessThan(1e-9);
    expect(steps).toBeGreaterThanOrEqual(10);
    // One step less does not fit: the growth stops at the first size that does.
    expect(() => prepareObjects([placed('hall', boxMesh(40, 10, 30), [20, 0, 15])], { texelSize: p.atlas.texelSize / 1.25, maxAtlasSize: 256 })).not.toThrow();
    const smaller = prepareObjects([placed('hall', boxMesh(40, 10, 30), [20, 0, 15])], { texelSize: p.atlas.texelSize / 1.25, maxAtlasSize: 256 });
    expect(smaller.atlas.texelSize).toBeCloseTo(p.atlas.texelSize, 12);
    let sum = 0;
    for (let g = 0; g < p.atlas.position.length; g += 4) sum += p.atlas.position[g + 3] * p.atlas.texelSize ** 2;
    expect(sum / p.objects[0].area).toBeCloseTo(1, 4);
  });

  it('the default limit is 2048 texels', () => {
    const p = prepareObjects([placed('box', boxMesh(20, 3, 20), [10, 0, 10])], { texelSize: 0.005 });
    expect(Math.max(p.atlas.width, p.atlas.height)).toBeLessThanOrEqual(2048);
    expect(p.atlas.texelSize).toBeGreaterThan(0.005);
  });
});

describe('prepareObjects: BVH textures', () => {
  it('every triangle lies in exactly one leaf, inside the boxes of the leaf and all its ancestors; depth ≤ 30', () => {
    const { nodes, triangles: T } = prepared.bvh;
    const seen = new Uint8Array(prepared.triangleCount);
    const problems: string[] = [];
    let maxDepth = 0;
    let leaves = 0;
    const inside = (node: number, x: number, a: number): boolean => nodes[8 * node + a] <= x && x <= nodes[8 * node + 4 + a];
    const walk = (node: number, ancestors: number[]): void => {
      maxDepth = Math.max(maxDepth, ancestors.length);
      const chain = [...ancestors, node];
      if (nodes[8 * node + 3] < 0) {
        leaves++;
        const count = -nodes[8 * node + 3];
        const first = nodes[8 * node + 7];
        for (let k = first; k < first + count; k++) {
          if (seen[k]++) problems.push(`triangle ${k} in two leaves`);
          const o = 16 * k;
          for (const e of [null, 4, 8]) {
            for (let a = 0; a < 3; a++) {
              const x = T[o + a] + (e === null ? 0 : T[o + e + a]);
              for (const n of chain) if (!inside(n, x, a)) problems.push(`triangle ${k} leaves node ${n}`);
            }
          }
        }
        return;
      }
      const left = nodes[8 * node + 3];
      const right = nodes[8 * node + 7];
      if (!(left > node && right > node && Number.isInteger(left) && Number.isInteger(right))) problems.push(`node ${node}: children ${left}, ${right}`);
      walk(left, chain);
      walk(right, chain);
    };
    walk(0, []);
    expect(problems.slice(0, 10)).toEqual([]);
    expect(Array.from(seen).every((s) => s === 1)).toBe(true);
    expect(maxDepth).toBeLessThanOrEqual(30);
    // three-mesh-bvh's SAH tree with ~6 triangles per leaf: far fewer leaves than triangles.
    expect(leaves).toBeLessThan(prepared.triangleCount / 2);
    expect(prepared.bvh.nodesHeight).toBe(Math.ceil(((2 * leaves - 1) * 2) / prepared.bvh.width));
    expect(prepared.bvh.trianglesHeight).toBe(Math.ceil((4 * prepared.triangleCount) / prepared.bvh.width));
  });

  it('no objects: a 1 × 1 empty atlas and a BVH that nothing hits', () => {
    const p = prepareObjects([], { texelSize: 0.1 });
    expect([p.atlas.width, p.atlas.height, p.triangleCount, p.charts.length]).toEqual([1, 1, 0, 0]);
    const caster = createObjectRayCaster(p);
    expect(caster.closestHit([0, 0, 0], [1, 1, 1], 1e9)).toBeNull();
    expect(caster.anyHit([-1, -1, -1], [1, 1, 1], 1e9)).toBe(false);
  });
});

describe('prepareObjects: bad input', () => {
  const box = boxMesh(1, 1, 1);
  const cases: [string, Parameters<typeof prepareObjects>[0], Parameters<typeof prepareObjects>[1], RegExp][] = [
    ['zero scale', [placed('b', box, [0, 0, 0], 0, 0)], { texelSize: 0.1 }, /object 1 \("b"\): scale must be a positive number \(got 0\)/],
    ['index out of range', [placed('b', { ...box, indices: new Uint32Array([0, 1, 9]), materialOfTriangle: new Uint16Array(1) }, [0, 0, 0])], { texelSize: 0.1 }, /triangle 0 uses vertex 9, but the mesh has 8 vertices/],
    ['missing material', [placed('b', { ...box, materialOfTriangle: new Uint16Array(12).fill(3) }, [0, 0, 0])], { texelSize: 0.1 }, /triangle 0 names material 3, but the mesh has 1 materials/],
    ['NaN vertex', [placed('b', { ...box, positions: box.positions.map((v, i) => (i === 4 ? NaN : v)) }, [0, 0, 0])], { texelSize: 0.1 }, /vertex 1 is not a finite point/],
    ['only degenerate triangles', [placed('flat', { ...box, positions: new Float32Array(24) }, [0, 0, 0])], { texelSize: 0.1 }, /object 1 \("flat"\): the mesh has no triangle with an area of at least 1e-10 m²/],
    ['zero texel size', [placed('b', box, [0, 0, 0])], { texelSize: 0 }, /texel size must be a positive number of metres \(got 0\)/],
    ['tiny atlas', [placed('b', box, [0, 0, 0])], { texelSize: 0.1, maxAtlasSize: 2 }, /maxAtlasSize must be an integer of at least 3 texels/],
  ];
  it.each(cases)('%s → InputError naming the object and the problem', (_, input, options, message) => {
    expect(() => prepareObjects(input, options)).toThrow(InputError);
    expect(() => prepareObjects(input, options)).toThrow(message);
  });
});
