/**
 * `luxbox bake` and `luxbox probe` on a furnished scene (tests/fixtures/models/furnished-room.json:
 * a downlight 2.45 m above the OBJ table, a GLB table beside it, nearField 'point'), as a pipeline
 * runs them: object maps and objects.json next to the wall maps, report.objects, probe points with
 * normals (occlusion, gather).
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import { LUMINANCE_WEIGHTS } from '../../../src/engines/bake/bakedMaps';
import { resolveBakeSettings } from '../../../src/engines/bake/bakeSettings';
import { directAtPoint } from '../../../src/engines/bake/directAtPoint';
import { scenePointSources } from '../../../src/engines/bake/scenePointSources';
import { loadLightingSceneFileAsync } from '../../../src/hosts/node/loadLightingSceneFile';
import { decodePfm } from '../../../src/hosts/node/writePfm';
import { TABLE } from '../../engines/meshImport/modelFixtures';

const root = join(__dirname, '../../..');
const scene = join(root, 'tests/fixtures/models/furnished-room.json');
/** Enough samples and bounces that two estimators of indirect light agree within a few per cent (measured 1.3 %). */
const settings = ['--texel', '0.1', '--samples', '128', '--bounces', '8'];

function luxbox(args: string[]) {
  const r = spawnSync(process.execPath, [join(root, 'bin/luxbox.js'), ...args], { cwd: root, encoding: 'utf8' });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

describe('luxbox bake: a furnished scene', () => {
  it('writes the atlas maps, the mask, objects.json and report.objects', () => {
    const out = mkdtempSync(join(tmpdir(), 'luxbox-furnished-'));
    const r = luxbox(['bake', scene, '--out', out, '--texel', '0.1', '--samples', '32', '--bounces', '2']);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    const objects = JSON.parse(readFileSync(join(out, 'objects.json'), 'utf8'));
    const { width, height, texel_size_m: texel } = objects.atlas;
    expect(texel).toBe(0.1);
    const direct = decodePfm(readFileSync(join(out, 'objects.direct.pfm')));
    const indirect = decodePfm(readFileSync(join(out, 'objects.indirect.pfm')));
    const total = decodePfm(readFileSync(join(out, 'objects.total.pfm')));
    const mask = decodePfm(readFileSync(join(out, 'objects.mask.pfm')));
    for (const m of [direct, indirect, total, mask]) expect([m.width, m.height]).toEqual([width, height]);
    for (let i = 0; i < total.rgb.length; i++) expect(total.rgb[i]).toBeCloseTo(direct.rgb[i] + indirect.rgb[i], 2);
    // The mask (grey PFM: object index + 1) agrees with the texel counts and rectangles of objects.json.
    expect(objects.objects.map((o: { id: string; mesh: string }) => [o.id, o.mesh])).toEqual([
      ['dining-table', 'table.obj'],
      ['objects[1]', 'table.glb'],
    ]);
    objects.objects.forEach((o: { index: number; texels: number; rect: { i0: number; j0: number; i1: number; j1: number } }) => {
      let count = 0;
      for (let j = 0; j < height; j++) {
        for (let i = 0; i < width; i++) {
          if (mask.rgb[3 * (j * width + i)] !== o.index + 1) continue;
          count++;
          expect(i >= o.rect.i0 && i <= o.rect.i1 && j >= o.rect.j0 && j <= o.rect.j1).toBe(true);
        }
      }
      expect(count).toBe(o.texels);
      // Each table is 2.668 m² of surface: at 0.1 m texels, with partly covered border texels, more than 267 texels.
      expect(o.texels).toBeGreaterThan(TABLE.area / (texel * texel));
    });

    const report = JSON.parse(readFileSync(join(out, 'report.json'), 'utf8'));
    expect(report.warnings).toEqual([]);
    expect(report.objects.map((o: { id: string }) => o.id)).toEqual(['dining-table', 'objects[1]']);
    expect(report.bake.objects.map((o: { id: string }) => o.id)).toEqual(['dining-table', 'objects[1]']);
    for (const [k, o] of report.objects.entries()) {
      expect(o).toMatchObject({ mesh: ['table.obj', 'table.glb'][k], triangles: 60, units: 'm', texels: objects.objects[k].texels });
      // Five closed boxes wound outward (docs/furniture.md, "Which side of a face is lit"): nothing turned, no back sides.
      expect(o.orientation).toEqual({ parts: 5, closed: 5, turnedOutward: 0, trianglesReversed: 0, twoSided: 0, oneSided: 0, undecided: 0, enclosedFaces: 0, droppedCopies: 0, backTriangles: 0 });
      expect(o.area).toBeCloseTo(TABLE.area, 5);
      expect(o.minLux).toBeLessThanOrEqual(o.meanLux);
      expect(o.meanLux).toBeLessThanOrEqual(o.maxLux);
    }
    // The downlight hangs over the OBJ table: its top gets far more light than the GLB table beside it.
    expect(report.objects[0].maxLux).toBeGreaterThan(5 * report.objects[1].maxLux);
  }, 120_000);
});

describe('luxbox probe: points with normals in a furnished scene', () => {
  const points: [Vec3, Vec3 | null][] = [
    // 0: under the OBJ table's top (0.71 m), facing up: the lamp 2.45 m above is hidden by the top.
    [
      [1.3, 0.3, 1.5],
      [0, 1, 0],
    ],
    // 1: above the top, facing up: unoccluded.
    [
      [1.3, 0.76, 1.5],
      [0, 1, 0],
    ],
    // 2: in free space, facing the south-west: unoccluded.
    [
      [0.5, 1.0, 0.5],
      [-0.6, 0.8, 0],
    ],
    // 3, 4: on the floor under the table, as a surface point and with a normal.
    [[1.3, 0, 1.5], null],
    [
      [1.3, 0, 1.5],
      [0, 1, 0],
    ],
    // 5, 6: on the open floor (the lamp's ray passes beside the table), both ways.
    [[2.2, 0, 0.4], null],
    [
      [2.2, 0, 0.4],
      [0, 1, 0],
    ],
    // 7, 8: on the north wall, both ways.
    [[2.0, 1.2, 0], null],
    [
      [2.0, 1.2, 0],
      [0, 0, 1],
    ],
  ];

  it('occlusion exactly 0 under the table, directAtPoint where nothing is in the way, gather ≈ maps', async () => {
    const dir = mkdtempSync(join(tmpdir(), 'luxbox-probe-'));
    const file = join(dir, 'points.json');
    writeFileSync(file, JSON.stringify({ points: points.map(([p, n]) => (n ? [...p, ...n] : p)) }));
    const r = luxbox(['probe', scene, file, ...settings]);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    const values = JSON.parse(r.stdout) as { total: number[]; direct: number[]; indirect: number[] };
    values.total.forEach((t, i) => expect(t).toBeCloseTo(values.direct[i] + values.indirect[i], 9));

    // The same point sources on the CPU without any object (directAtPoint), as lux.
    const loaded = await loadLightingSceneFileAsync(scene);
    const lamps = scenePointSources(loaded.bakeScene, resolveBakeSettings({ texelSize: 0.1, samples: 128, bounces: 8 }));
    const unoccluded = (p: Vec3, n: Vec3): number => {
      const len = Math.hypot(...n);
      const rgb = directAtPoint(lamps, p, [n[0] / len, n[1] / len, n[2] / len]);
      return LUMINANCE_WEIGHTS[0] * rgb[0] + LUMINANCE_WEIGHTS[1] * rgb[1] + LUMINANCE_WEIGHTS[2] * rgb[2];
    };
    expect(unoccluded([1.3, 0.3, 1.5], [0, 1, 0])).toBeGreaterThan(10);
    expect(values.direct[0]).toBe(0);
    expect(values.direct[3]).toBe(0);
    expect(values.direct[4]).toBe(0);
    for (const k of [1, 2, 6, 8]) expect(values.direct[k]).toBeCloseTo(unoccluded(points[k][0], points[k][1]!), 9);
    expect(values.direct[5]).toBeCloseTo(unoccluded([2.2, 0, 0.4], [0, 1, 0]), 9);
    expect(values.direct[7]).toBeCloseTo(unoccluded([2.0, 1.2, 0], [0, 0, 1]), 9);

    // Two estimators of the same indirect light: the baked surface map (bilinear) and the CPU gather over every map (4096 rays).
    for (const [surfacePoint, gathered] of [
      [3, 4],
      [5, 6],
      [7, 8],
    ]) {
      expect(Math.abs(values.indirect[gathered] / values.indirect[surfacePoint] - 1)).toBeLessThan(0.05);
    }
    // Under the table less light arrives from above than on the open floor.
    expect(values.indirect[4]).toBeLessThan(values.indirect[6]);
  }, 120_000);

  it('refuses a point outside the room and a normal without direction, as one line', () => {
    const dir = mkdtempSync(join(tmpdir(), 'luxbox-probe-bad-'));
    const file = join(dir, 'points.json');
    writeFileSync(
      file,
      JSON.stringify({
        points: [
          [1, 1, 1, 0, 1, 0],
          [5, 1, 1, 0, 1, 0],
        ],
      }),
    );
    let r = luxbox(['probe', scene, file, ...settings]);
    expect(r.status).toBe(1);
    expect(r.stderr).toBe('luxbox probe: points.json: points[1]: x = 5 m is outside the room (0..4 m)\n');
    writeFileSync(file, JSON.stringify({ points: [[1, 1, 1, 0, 0, 0]] }));
    r = luxbox(['probe', scene, file, ...settings]);
    expect(r.stderr).toBe('luxbox probe: points.json: points[0]: the normal [0, 0, 0] has no direction\n');
    writeFileSync(file, JSON.stringify({ points: [[1, 1, 1, 0, 1]] }));
    r = luxbox(['probe', scene, file, ...settings]);
    expect(r.stderr).toBe('luxbox probe: points.json: points[0]: must be [x, y, z] (a point on a surface) or [x, y, z, nx, ny, nz] (a point and a normal)\n');
  }, 60_000);
});
