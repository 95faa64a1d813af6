/**
 * prepareObjects' atlas charts (src/engines/bake/objects): faces grouped into charts, tight
 * rectangles, no texel claimed twice, a tightly packed atlas.
 */
import { describe, expect, it } from 'vitest';
import { prepareObjects } from '../../../../src/engines/bake/objects/prepareObjects';
import { boxMesh, placed } from './objectFixtures';
import { atlas, chartTriangles, cross, dot, prepared, sub, type V3 } from './prepareObjectsKit';

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
