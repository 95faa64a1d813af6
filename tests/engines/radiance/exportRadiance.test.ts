import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import { LUMINANCE_WEIGHTS } from '../../../src/engines/bake/bakedMaps';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { resolveBakeSettings } from '../../../src/engines/bake/bakeSettings';
import { directAtPoint } from '../../../src/engines/bake/directAtPoint';
import { scenePointSources } from '../../../src/engines/bake/scenePointSources';
import { exportRadiance } from '../../../src/engines/radiance/exportRadiance';
import { toRadiance } from '../../../src/engines/radiance/radianceFrame';
import { loadRenderInput } from '../../../src/hosts/node/renderInput';
import { createRng } from '../../fuzz/mutate';
import { radianceDirect } from './radianceSceneEvaluator';

const Y = (e: Vec3): number => LUMINANCE_WEIGHTS[0] * e[0] + LUMINANCE_WEIGHTS[1] * e[1] + LUMINANCE_WEIGHTS[2] * e[2];

/** Points on all six surfaces (normal into the room) and in the air (random normals). */
function samplePoints(scene: BakeScene, n: number, seed: number): { p: Vec3; normal: Vec3 }[] {
  const rnd = createRng(seed).next;
  const { width: W, height: H, depth: D } = scene.room;
  const out: { p: Vec3; normal: Vec3 }[] = [];
  const faces: { at: (u: number, v: number) => Vec3; normal: Vec3 }[] = [
    { at: (u, v) => [u * W, 0, v * D], normal: [0, 1, 0] },
    { at: (u, v) => [u * W, H, v * D], normal: [0, -1, 0] },
    { at: (u, v) => [u * W, v * H, 0], normal: [0, 0, 1] },
    { at: (u, v) => [u * W, v * H, D], normal: [0, 0, -1] },
    { at: (u, v) => [0, v * H, u * D], normal: [1, 0, 0] },
    { at: (u, v) => [W, v * H, u * D], normal: [-1, 0, 0] },
  ];
  for (let i = 0; i < n; i++) {
    const f = faces[i % 6];
    out.push({ p: f.at(0.02 + 0.96 * rnd(), 0.02 + 0.96 * rnd()), normal: f.normal });
    const z = 2 * rnd() - 1;
    const a = 2 * Math.PI * rnd();
    const s = Math.sqrt(1 - z * z);
    out.push({ p: [(0.1 + 0.8 * rnd()) * W, (0.1 + 0.8 * rnd()) * H, (0.1 + 0.8 * rnd()) * D], normal: [s * Math.cos(a), z, s * Math.sin(a)] });
  }
  return out;
}

function filesOf(scene: BakeScene, nearField?: 'split' | 'point'): Map<string, string> {
  return new Map(exportRadiance(scene, nearField ? { nearField } : {}).map((f) => [f.path, f.text]));
}

/**
 * The exported scene, read back by an independent evaluator of Radiance's definitions, gives the
 * same direct light as luxbox's own point sources: frame, rotation order, units (cd/179 W/sr,
 * A1 = 1/πr²), data layout and the lower/upper faces of tall openings are all right.
 */
function expectSameDirect(scene: BakeScene, nearField: 'split' | 'point' | undefined, seed: number): void {
  const files = filesOf(scene, nearField);
  const lamps = scenePointSources(scene, resolveBakeSettings(nearField ? { nearField } : {}));
  const points = samplePoints(scene, 60, seed);
  const luxbox = points.map(({ p, normal }) => Y(directAtPoint(lamps, p, normal)));
  const radiance = points.map(({ p, normal }) => Y(radianceDirect(files, toRadiance(p), toRadiance(normal))));
  const peak = Math.max(...luxbox);
  expect(peak).toBeGreaterThan(1);
  let compared = 0;
  luxbox.forEach((e, i) => {
    // 1 mm spheres and 7-digit data: agreement to 0.2 % wherever the light is more than 1 % of the peak.
    if (e < 0.01 * peak) return expect(Math.abs(radiance[i] - e)).toBeLessThan(0.002 * peak);
    compared++;
    expect(Math.abs(radiance[i] / e - 1), `point ${i}: luxbox ${e}, radiance ${radiance[i]}`).toBeLessThan(0.002);
  });
  expect(compared).toBeGreaterThan(20);
}

describe('Radiance export (docs/radiance.md)', () => {
  it('maps luxbox (x, y, z) to Radiance (x, −z, y): floor corner, north wall, up', () => {
    expect(toRadiance([1, 2, 3])).toEqual([1, -3, 2]);
    const files = filesOf(loadRenderInput('tests/fixtures/scenes/small-room.json').bakeScene);
    // The floor polygon lies at Z = 0, spans Y ∈ [−2, 0], and faces up (counterclockwise from above).
    expect(files.get('scene.rad')).toMatch(/floor_material polygon floor\n0\n0\n12\n\t0 -2 0\n\t3 -2 0\n\t3 0 0\n\t0 0 0/);
  });

  it('a real room with a tilted, turned washlight: same direct light as luxbox, split near field', () => {
    expectSameDirect(loadRenderInput('tests/fixtures/scenes/small-room.json').bakeScene, undefined, 1);
  });

  it('the same room with point sources (nearField point)', () => {
    expectSameDirect(loadRenderInput('tests/fixtures/scenes/small-room.json').bakeScene, 'point', 2);
  });

  it('real asymmetric, type B and tall-opening photometry, every angle non-zero', () => {
    const base = loadRenderInput('tests/fixtures/bench/living-room.json').bakeScene;
    const scene: BakeScene = {
      ...base,
      luminaires: base.luminaires.map((l, i) => ({ ...l, yaw: 17 + 40 * i, pitch: 23 + 11 * i, roll: 31 - 7 * i })),
    };
    expectSameDirect(scene, undefined, 3);
  });

  it('writes a complete folder: scene, distributions, source.cal, views, grids, script, README', () => {
    const files = exportRadiance(loadRenderInput('tests/fixtures/scenes/small-room.json').bakeScene);
    const paths = files.map((f) => f.path).sort();
    expect(paths).toEqual(['README.md', 'luminaires/p0.dat', 'luminaires/p1.dat', 'points/floor.pts', 'points/workplane.pts', 'render.sh', 'scene.rad', 'source.cal', 'views/corner.vf', 'views/eye.vf', 'views/top.vf'].sort());
    expect(files.find((f) => f.path === 'render.sh')!.executable).toBe(true);
    const rad = files.find((f) => f.path === 'scene.rad')!.text;
    // Every file the scene names is in the folder.
    for (const dat of rad.matchAll(/corr (\S+\.dat) source\.cal/g)) expect(paths).toContain(dat[1]);
    // 3 m × 2 m room, 0.25 m grid: 12 × 8 points, "X Y Z 0 0 1".
    const floor = files
      .find((f) => f.path === 'points/floor.pts')!
      .text.trim()
      .split('\n');
    expect(floor).toHaveLength(96);
    expect(floor[0]).toBe('0.125 -0.125 0.001 0 0 1');
    // The top view looks straight down with north (+Y) up.
    expect(files.find((f) => f.path === 'views/top.vf')!.text).toMatch(/-vd 0 0\.000\d+ -1 -vu 0 1 0/);
  });
});
