/**
 * prepareObjects (src/engines/bake/objects): the atlas charts and their G-buffer, and the flattened
 * BVH, checked against independent computations from the placed meshes (areas from cross products,
 * point–triangle distances, the triangles' own atlas uv footprints).
 */
import { describe, expect, it } from 'vitest';
import { InputError } from '../../../../src/core/inputError';
import { createObjectRayCaster } from '../../../../src/engines/bake/objects/createObjectRayCaster';
import { prepareObjects } from '../../../../src/engines/bake/objects/prepareObjects';
import type { PreparedObjects } from '../../../../src/engines/bake/objects/preparedObjects';
import { createRng } from '../../../fuzz/mutate';
import { sceneTriangles } from './bruteForceRays';
import { boxMesh, placed, testScene, triangleSoup } from './objectFixtures';

type V3 = [number, number, number];

const objects = testScene();
const prepared = prepareObjects(objects, { texelSize: 0.05 });
const { atlas } = prepared;

/** The texture triangles of one chart: v0, v1, v2 (float32 as stored). */
function chartTriangles(p: PreparedObjects): Map<number, V3[][]> {
  const out = new Map<number, V3[][]>();
  const T = p.bvh.triangles;
  for (let k = 0; k < p.triangleCount; k++) {
    const o = 16 * k;
    const v0: V3 = [T[o], T[o + 1], T[o + 2]];
    const v1: V3 = [v0[0] + T[o + 4], v0[1] + T[o + 5], v0[2] + T[o + 6]];
    const v2: V3 = [v0[0] + T[o + 8], v0[1] + T[o + 9], v0[2] + T[o + 10]];
    const chart = T[o + 11];
    if (!out.has(chart)) out.set(chart, []);
    out.get(chart)!.push([v0, v1, v2]);
  }
  return out;
}

const sub = (a: V3, b: V3): V3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: V3, b: V3): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a: V3, b: V3): V3 => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];

/** Distance from p to triangle (a, b, c) in 3D: the plane distance if p projects inside, else the nearest edge. */
function pointTriangleDistance(p: V3, [a, b, c]: V3[]): number {
  const n = cross(sub(b, a), sub(c, a));
  const len = Math.hypot(...n);
  const h = dot(sub(p, a), n) / len;
  const q: V3 = [p[0] - (h * n[0]) / len, p[1] - (h * n[1]) / len, p[2] - (h * n[2]) / len];
  const inside = [
    [a, b],
    [b, c],
    [c, a],
  ].every(([u, v]) => dot(cross(sub(v, u), sub(q, u)), n) >= 0);
  if (inside) return Math.abs(h);
  const segment = (u: V3, v: V3): number => {
    const d = sub(v, u);
    const s = Math.min(1, Math.max(0, dot(sub(p, u), d) / dot(d, d)));
    return Math.hypot(...sub(p, [u[0] + s * d[0], u[1] + s * d[1], u[2] + s * d[2]]));
  };
  return Math.min(segment(a, b), segment(b, c), segment(c, a));
}

describe('prepareObjects: charts', () => {
  it("a cube's 6 faces become 6 charts of 2 triangles, each as large as its face", () => {
    const p = prepareObjects([placed('cube', boxMesh(1, 1, 1), [1, 0, 1])], { texelSize: 0.1 });
    expect(p.charts).toHaveLength(6);
    for (const c of p.charts) expect([c.triangleCount, c.columns, c.rows]).toEqual([2, 10, 10]);
  });

  it('a yawed box keeps tight charts (minimum-area rectangle), and faces with their own corners still join', () => {
    const p = prepareObjects([placed('cabinet', boxMesh(0.6, 1.8, 0.4), [3, 0, 3.5], 30)], { texelSize: 0.05 });
    const sizes = p.charts.map((c) => `${c.columns}x${c.rows}`).sort();
    expect(sizes).toEqual(['12x8', '12x8', '36x12', '36x12', '36x8', '36x8']);
    // The same box with every triangle on its own three vertices (split normals): still 6 charts.
    const box = boxMesh(1, 1, 1);
    const positions = new Float32Array(36 * 3);
    box.indices.forEach((v, i) => positions.set(box.positions.subarray(3 * v, 3 * v + 3), 3 * i));
    const split = { ...box, positions, indices: new Uint32Array(36).map((_, i) => i) };
    expect(prepareObjects([placed('split', split, [1, 0, 1], 17)], { texelSize: 0.1 }).charts).toHaveLength(6);
  });

  it('coplanar triangles that share no edge, or that bend by more than 1°, are separate charts', () => {
    const quad = (x0: number, tilt: number): number[] => [x0, 0, 0, x0 + 1, 0, 0, x0 + 1, tilt, -1, x0, 0, -1];
    const mesh = (tilt: number) => ({
      positions: new Float32Array([...quad(0, tilt), ...quad(2, 0), 4, 0, 0, 5, 0, 0, 5, 0, -1]),
      // Two unit quads 1 m apart in y = 0, then a triangle in the same plane sharing no edge with them.
      indices: new Uint32Array([0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7, 8, 9, 10]),
      materialOfTriangle: new Uint16Array(5),
      materials: [{ name: 'm', reflectance: [0.5, 0.5, 0.5] as [number, number, number] }],
    });
    expect(prepareObjects([placed('flat', mesh(0), [0, 1, 2])], { texelSize: 0.1 }).charts.map((c) => c.triangleCount)).toEqual([2, 2, 1]);
    // Lifting one corner of the first quad by 0.03 m bends its halves by 2.4° (normals (0, 1, t) and (−t, 1, 0)): they part.
    const bent = prepareObjects([placed('bent', mesh(0.03), [0, 1, 2])], { texelSize: 0.1 });
    expect(bent.charts.map((c) => c.triangleCount)).toEqual([1, 1, 2, 1]);
  });

  it('a tessellated plane is one chart; a finely tessellated cylinder does not drift into bent charts', () => {
    // 20 × 20 quads on a 2 × 2 m plane, yawed: one chart, its area exact.
    const n = 20;
    const grid: number[] = [];
    const gridIndices: number[] = [];
    for (let j = 0; j <= n; j++) for (let i = 0; i <= n; i++) grid.push((2 * i) / n, 0, (-2 * j) / n);
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const a = j * (n + 1) + i;
        gridIndices.push(a, a + 1, a + n + 2, a, a + n + 2, a + n + 1);
      }
    }
    const material = [{ name: 'm', reflectance: [0.5, 0.5, 0.5] as [number, number, number] }];
    const plane = { positions: new Float32Array(grid), indices: new Uint32Array(gridIndices), materialOfTriangle: new Uint16Array(2 * n * n), materials: material };
    const flat = prepareObjects([placed('plane', plane, [1, 0.5, 3], 23)], { texelSize: 0.05 });
    expect(flat.charts).toHaveLength(1);
    expect([flat.charts[0].columns, flat.charts[0].rows]).toEqual([40, 40]);
    // A 720-sided open cylinder (0.5° between neighbours, r = 0.3 m): each chart stays within 1° of its seed.
    const sides = 720;
    const cyl: number[] = [];
    const cylIndices: number[] = [];
    for (let i = 0; i < sides; i++) {
      const phi = (2 * Math.PI * i) / sides;
      cyl.push(0.3 * Math.cos(phi), 0, -0.3 * Math.sin(phi), 0.3 * Math.cos(phi), 1, -0.3 * Math.sin(phi));
      const a = 2 * i,
        b = 2 * ((i + 1) % sides);
      cylIndices.push(a, b, b + 1, a, b + 1, a + 1);
    }
    const cylinder = { positions: new Float32Array(cyl), indices: new Uint32Array(cylIndices), materialOfTriangle: new Uint16Array(2 * sides), materials: material };
    const p = prepareObjects([placed('cylinder', cylinder, [2, 0, 2])], { texelSize: 0.05 });
    const byChart = chartTriangles(p);
    let widest = 0;
    for (const tris of byChart.values()) {
      const normals = tris.map((t) => {
        const c = cross(sub(t[1], t[0]), sub(t[2], t[0]));
        const l = Math.hypot(...c);
        return [c[0] / l, c[1] / l, c[2] / l] as V3;
      });
      for (const a of normals) for (const b of normals) widest = Math.max(widest, Math.acos(Math.min(1, dot(a, b))));
    }
    expect((widest * 180) / Math.PI).toBeLessThanOrEqual(2 + 1e-6);
    expect(p.charts.length).toBeGreaterThan(sides / 5);
    expect(p.charts.length).toBeLessThan(sides / 2);
    expect(p.objects[0].area).toBeCloseTo(2 * Math.PI * 0.3 * Math.sin(Math.PI / sides) * (sides / Math.PI), 4);
  });

  it('no texel is claimed twice: triangle uv footprints of different charts never share a texel; gutters and edges stay empty', () => {
    const owner = new Int32Array(atlas.width * atlas.height).fill(-1);
    const T = prepared.bvh.triangles;
    const clashes: string[] = [];
    for (let k = 0; k < prepared.triangleCount; k++) {
      const o = 16 * k;
      const us = [T[o + 3], T[o + 12], T[o + 14]].map((u) => u * atlas.width);
      const vs = [T[o + 7], T[o + 13], T[o + 15]].map((v) => v * atlas.height);
      const chart = T[o + 11];
      for (let j = Math.floor(Math.min(...vs)); j < Math.ceil(Math.max(...vs)); j++) {
        for (let i = Math.floor(Math.min(...us)); i < Math.ceil(Math.max(...us)); i++) {
          const at = j * atlas.width + i;
          if (owner[at] >= 0 && owner[at] !== chart) clashes.push(`texel (${i}, ${j}): charts ${owner[at]} and ${chart}`);
          owner[at] = chart;
        }
      }
    }
    expect(clashes).toEqual([]);
    // Every covered texel belongs to its chart's rectangle; two rectangles are ≥ 2 texels apart; none touches the edge.
    const strays: string[] = [];
    for (let j = 0; j < atlas.height; j++) {
      for (let i = 0; i < atlas.width; i++) {
        const g = 4 * (j * atlas.width + i);
        if (atlas.position[g + 3] === 0) continue;
        const c = prepared.charts[atlas.normal[g + 3] - 1];
        if (!(i >= c.x && i < c.x + c.columns && j >= c.y && j < c.y + c.rows)) strays.push(`texel (${i}, ${j}) outside chart ${atlas.normal[g + 3] - 1}`);
      }
    }
    expect(strays).toEqual([]);
    for (const c of prepared.charts) {
      expect(c.x).toBeGreaterThanOrEqual(1);
      expect(c.y).toBeGreaterThanOrEqual(1);
      expect(c.x + c.columns).toBeLessThanOrEqual(atlas.width - 1);
      expect(c.y + c.rows).toBeLessThanOrEqual(atlas.height - 1);
    }
    const sorted = [...prepared.charts].sort((a, b) => a.x - b.x);
    for (let a = 0; a < sorted.length; a++) {
      for (let b = a + 1; b < sorted.length && sorted[b].x < sorted[a].x + sorted[a].columns + 2; b++) {
        const A = sorted[a],
          B = sorted[b];
        const gapX = Math.max(B.x - (A.x + A.columns), A.x - (B.x + B.columns));
        const gapY = Math.max(B.y - (A.y + A.rows), A.y - (B.y + B.rows));
        expect(Math.max(gapX, gapY)).toBeGreaterThanOrEqual(2);
      }
    }
  });

  it('the atlas is packed tightly: chart cells fill most of it', () => {
    const cells = prepared.charts.reduce((s, c) => s + (c.columns + 2) * (c.rows + 2), 0);
    expect(cells / (atlas.width * atlas.height)).toBeGreaterThan(0.75);
    expect(atlas.texelSize).toBe(0.05);
  });
});

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
