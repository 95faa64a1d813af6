/**
 * `luxbox bake` and `luxbox probe` end to end, as a CI pipeline runs them:
 * a child process (re-executing itself under xvfb-run when DISPLAY is unset),
 * files on disk, one stderr line and exit 1 for bad input.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { PNG } from 'pngjs';
import { SURFACE_NAMES } from '../../../src/core/model/lightingScene/lightingScene';
import { decodePfm } from '../../../src/hosts/node/writePfm';
import { loadLightingSceneFile } from '../../../src/hosts/node/loadLightingSceneFile';
import { referencePointSources } from '../../../src/reference/pointSources';
import { directIlluminanceAt } from '../../../src/reference/directIlluminance';

const root = join(__dirname, '../../..');
const scene = join(root, 'tests/fixtures/scenes/small-room.json');
const points = join(root, 'tests/fixtures/scenes/small-room.points.json');
const quick = ['--texel', '0.1', '--samples', '16', '--bounces', '2'];

function luxbox(args: string[], env: NodeJS.ProcessEnv = process.env) {
  // The timeout turns a hang (a device read forever) into a failure.
  const r = spawnSync(process.execPath, [join(root, 'bin/luxbox.js'), ...args], { cwd: root, env, encoding: 'utf8', timeout: 120_000 });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

describe('luxbox bake / probe', () => {
  const out = mkdtempSync(join(tmpdir(), 'luxbox-bake-'));

  it('bake writes report.json, three PFMs and a PNG per surface (docs/scene-format.md contract)', () => {
    // No DISPLAY: the command must re-run itself under xvfb-run.
    const env = { ...process.env };
    delete env.DISPLAY;
    const r = luxbox(['bake', scene, '--out', out, ...quick], env);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    const report = JSON.parse(readFileSync(join(out, 'report.json'), 'utf8'));
    expect(Object.keys(report.surfaces).sort()).toEqual([...SURFACE_NAMES].sort());
    expect(report.surfaces.floor.area).toBeCloseTo(6, 9);
    expect(report.surfaces.north.area).toBeCloseTo(7.5, 9);
    expect(report.settings).toMatchObject({ texelSize: 0.1, samples: 16, bounces: 2 });
    for (const key of ['direct', 'indirect', 'blur', 'blend', 'total']) expect(report.timings_ms[key]).toBeGreaterThanOrEqual(0);
    for (const name of SURFACE_NAMES) {
      const s = report.surfaces[name];
      expect(s.min).toBeLessThanOrEqual(s.avg);
      expect(s.avg).toBeLessThanOrEqual(s.max);
      expect(s.avg).toBeCloseTo(s.direct_avg + s.indirect_avg, 3);
      const total = decodePfm(readFileSync(join(out, `${name}.total.pfm`)));
      const direct = decodePfm(readFileSync(join(out, `${name}.direct.pfm`)));
      const indirect = decodePfm(readFileSync(join(out, `${name}.indirect.pfm`)));
      expect([total.width, total.height]).toEqual(s.texels);
      for (let i = 0; i < total.rgb.length; i++) expect(total.rgb[i]).toBeCloseTo(direct.rgb[i] + indirect.rgb[i], 2);
      const png = PNG.sync.read(readFileSync(join(out, `${name}.png`)));
      expect(png.width).toBeGreaterThan(s.texels[0]);
    }
    // The washlight (floor-standing, tilted to the north-west) lights the floor's first rows (v = z small).
    const floor = decodePfm(readFileSync(join(out, 'floor.direct.pfm')));
    expect(Math.max(...floor.rgb.slice(0, floor.width * 3 * 5))).toBeGreaterThan(Math.max(...floor.rgb.slice(-floor.width * 3 * 5)));
  });

  it('probe prints total/direct/indirect lux that match the baked maps', () => {
    const r = luxbox(['probe', scene, points, ...quick]);
    expect(r.status).toBe(0);
    const values = JSON.parse(r.stdout);
    expect(Object.keys(values)).toEqual(['total', 'direct', 'indirect']);
    expect(values.total).toHaveLength(5);
    values.total.forEach((t: number, i: number) => expect(Math.abs(t - values.direct[i] - values.indirect[i])).toBeLessThan(1e-5 * t));
    // Point 1 is the ceiling above a pure downlight with almost no uplight: little direct.
    expect(values.direct[1]).toBeLessThan(0.01 * values.direct[0]);
    // Direct light is evaluated exactly at each point (not read from the maps): the same
    // I·cosθ/d² as the independent CPU reference's point sources, at every probe point.
    const loaded = loadLightingSceneFile(scene);
    const photometries = new Map(loaded.scene.luminaires.map((l, i) => [l.photometry, loaded.bakeScene.luminaires[i].photometry]));
    const sources = referencePointSources(loaded.scene, photometries);
    const pts = JSON.parse(readFileSync(points, 'utf8')).points as [number, number, number][];
    const normals: [number, number, number][] = [
      [0, 1, 0],
      [0, -1, 0],
      [1, 0, 0],
      [-1, 0, 0],
      [0, 0, 1],
    ];
    pts.forEach((p, i) => {
      const onPlane: [number, number, number] = [p[0], p[1], i === 4 ? 0 : p[2]];
      const [r, g, b] = directIlluminanceAt(sources, onPlane, normals[i]);
      const y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
      expect(Math.abs(values.direct[i] - y)).toBeLessThanOrEqual(1e-9 + 1e-9 * y);
    });
    // The indirect part is the bilinear lookup of the indirect map: point 0 [1.5, 0, 1.0] is a
    // texel corner of the 0.1 m floor map, so it is the mean of the four texels around it.
    const floor = decodePfm(readFileSync(join(out, 'floor.indirect.pfm')));
    const at = (i: number, j: number) => {
      const o = (j * floor.width + i) * 3;
      return 0.2126 * floor.rgb[o] + 0.7152 * floor.rgb[o + 1] + 0.0722 * floor.rgb[o + 2];
    };
    const avg4 = (at(14, 9) + at(15, 9) + at(14, 10) + at(15, 10)) / 4;
    expect(Math.abs(values.indirect[0] - avg4)).toBeLessThan(1e-5 * avg4);
  });

  it('--near-field point makes one source per luminaire; a bad value is one line, exit 1', () => {
    const dirOut = mkdtempSync(join(tmpdir(), 'luxbox-near-'));
    const r = luxbox(['bake', scene, '--out', dirOut, ...quick, '--bounces', '0', '--near-field', 'point']);
    expect(r.status).toBe(0);
    expect(JSON.parse(readFileSync(join(dirOut, 'report.json'), 'utf8')).bake.pointSources).toBe(2);
    const bad = luxbox(['bake', scene, '--out', dirOut, '--near-field', 'far']);
    expect(bad.status).toBe(1);
    expect(bad.stderr).toMatch(/^luxbox bake: bake: --near-field must be split or point, got "far"\n$/);
  });

  const dir = mkdtempSync(join(tmpdir(), 'luxbox-bad-'));
  const bad: [string, string, string[], RegExp][] = [
    [
      'lamp above the ceiling',
      JSON.stringify({
        version: 1,
        room: { width: 3, height: 2.5, depth: 2, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } },
        luminaires: [{ photometry: 'x.ies', position: [1, 3.1, 1], yaw: 0, pitch: 0, roll: 0 }],
      }),
      [],
      /^luxbox bake: scene\.json: luminaires\[0\]\.position\[1\]: 3\.1 m is above the ceiling/,
    ],
    ['broken JSON', '{ "version": 1,\n  "room": { ', [], /^luxbox bake: scene\.json: line 2, column \d+: invalid JSON/],
    [
      'missing photometry file',
      JSON.stringify({ version: 1, room: { width: 3, height: 2.5, depth: 2, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } }, luminaires: [{ photometry: 'nope.ies', position: [1, 2, 1] }] }),
      [],
      /^luxbox bake: scene\.json: luminaires\[0\]\.photometry: cannot read "nope\.ies" \(no such file\)\n$/,
    ],
    // Issue 32: read forever before (a character device reports size 0).
    [
      'photometry /dev/zero',
      JSON.stringify({ version: 1, room: { width: 3, height: 2.5, depth: 2, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } }, luminaires: [{ photometry: '/dev/zero', position: [1, 2, 1] }] }),
      [],
      /^luxbox bake: scene\.json: luminaires\[0\]\.photometry: cannot read "\/dev\/zero" \(\/dev\/zero is outside the scene's folder \(give more with --allow\)\)\n$/,
    ],
    [
      'bad flag value',
      JSON.stringify({ version: 1, room: { width: 3, height: 2.5, depth: 2, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } }, luminaires: [] }),
      ['--samples', '0'],
      /^luxbox bake: samples 0 is not an integer in 1\.\.65536\n$/,
    ],
  ];
  for (const [name, text, extra, message] of bad) {
    it(`bad input (${name}): one stderr line, exit 1`, () => {
      const file = join(dir, 'scene.json');
      writeFileSync(file, text);
      const r = luxbox(['bake', file, '--out', join(dir, 'out'), ...extra]);
      expect(r.status).toBe(1);
      expect(r.stderr.trimEnd().split('\n')).toHaveLength(1);
      expect(r.stderr).toMatch(message);
    });
  }

  it('probe point off every surface: one clear line, exit 1', () => {
    const file = join(dir, 'points.json');
    writeFileSync(
      file,
      JSON.stringify({
        points: [
          [1.5, 0, 1],
          [1.5, 1.2, 1],
        ],
      }),
    );
    const r = luxbox(['probe', scene, file, ...quick]);
    expect(r.status).toBe(1);
    expect(r.stderr).toBe('luxbox probe: points.json: points[1]: [1.5, 1.2, 1] is 1.00 m from the nearest surface (north); probe points must lie within 0.01 m of a surface\n');
  });
});
