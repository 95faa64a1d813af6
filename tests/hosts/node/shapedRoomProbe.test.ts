/**
 * `luxbox probe` in a room of any shape (issue 29; src/hosts/node/createShapedRoomProbe.ts) against
 * the independent room reference (src/reference/solveRoomReference.ts, no code shared with the
 * baker): the attic of tests/engines/bake/shapedRoomVsReference.test.ts (a knee wall, a narrow spot
 * aimed up under the slope, a bare lamp), baked at 0.1 m texels and the default 64 samples, probed
 * at points on the floor, the slope, the flat ceiling and four walls, and at two points with a
 * normal in the air (one facing the floor, one the bare lamp). Direct light is evaluated at the
 * point on both sides (same source model, cells of 5 cm): within 0.5 %. Total light: the bake's
 * indirect map (surface points) or a CPU gather over the maps (plane points) against the
 * reference's final gather, within 5 % at every point (measured: 2.3 % at worst); the points lie
 * at least 20 cm from every edge.
 */
import { describe, expect, it } from 'vitest';
import type { LightingLuminaire, Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import type { RoomInput } from '../../../src/core/room/roomInput';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { probeShapedRoom, type ShapedProbePoint } from '../../../src/hosts/node/createShapedRoomProbe';
import { roomIlluminanceAt, roomSurfaceIlluminanceAt } from '../../../src/reference/roomIlluminanceAt';
import { solveRoomReference } from '../../../src/reference/solveRoomReference';
import { bakeLuminaires, shapedBakeRoom } from '../../engines/bake/shapedRoomKit';
import { withHeadlessGL } from '../../engines/bake/withHeadlessGL';
import { isotropic, realPhotometry } from '../../reference/photometryFixtures';

const gl = withHeadlessGL();
const CELL = 0.05;
const SETTINGS = { texelSize: 0.1, sourceSpacing: CELL };
const files = { iso: isotropic(1500), spot: realPhotometry('bega_84693_narrow_spot.ies') };
const lamp = (photometry: string, position: Vec3, angles: Partial<LightingLuminaire> = {}): LightingLuminaire => ({ photometry, position, yaw: 0, pitch: 0, roll: 0, ...angles });
const attic: RoomInput = {
  outline: [
    [0, 0],
    [5, 0],
    [5, 4],
    [0, 4],
  ],
  height: 2.5,
  slopes: [{ wall: 0, kneeHeight: 1, pitch: 40 }],
  reflectance: { floor: 0.3, ceiling: 0.8, walls: 0.6 },
};
const lamps = [lamp('spot', [2.5, 1.6, 3], { pitch: 120 }), lamp('iso', [1.2, 2, 2.8])];
const t = Math.tan((40 * Math.PI) / 180);
const slopeAt = (x: number, z: number): Vec3 => [x, 1 + z * t, z];
const c = Math.cos((40 * Math.PI) / 180);
const s = Math.sin((40 * Math.PI) / 180);

/** [point, surface id] on the room's surfaces, 20 cm or more from every edge; the slope's inward normal is (0, −cos 40°, sin 40°). */
const surfacePoints: [Vec3, string][] = [
  [[1, 0, 1], 'floor'],
  [[3.2, 0, 2.6], 'floor'],
  [slopeAt(2.5, 0.9), 'slope-0'],
  [slopeAt(1, 1.3), 'slope-0'],
  [[2.5, 2.5, 3], 'ceiling'],
  [[5, 1.2, 2], 'wall-1'],
  [[2, 1.5, 4], 'wall-2'],
  [[0, 0.6, 2.5], 'wall-3'],
  [[3, 0.5, 0], 'wall-0'],
];
const planePoints: { point: Vec3; normal: Vec3 }[] = [
  { point: [2.5, 0.8, 2], normal: [0, 1, 0] },
  { point: [1.5, 1.2, 2.5], normal: [-1, 0, 0] },
];

describe('probe in a room of any shape vs the room reference', () => {
  const scene: BakeScene = { room: shapedBakeRoom(attic), luminaires: bakeLuminaires(lamps, files) };
  const { maps } = createBaker(gl).bake(scene, SETTINGS);
  const reference = solveRoomReference(attic, lamps, files, { patchSize: 0.25, openingCell: CELL });
  const points: ShapedProbePoint[] = [...surfacePoints.map(([point]) => ({ point })), ...planePoints];
  const probed = probeShapedRoom(scene, maps, SETTINGS, points, 0.01);

  it('names the surface of each surface point, and none for a point with a normal', () => {
    expect(probed.map((v) => v.surface)).toEqual([...surfacePoints.map(([, id]) => id), undefined, undefined]);
  });

  it('direct within 0.5 % and total within 5 % of the reference at every point', () => {
    const expected = [...surfacePoints.map(([p, id]) => roomSurfaceIlluminanceAt(reference, id, p)), ...planePoints.map(({ point, normal }) => roomIlluminanceAt(reference, point, normal))];
    const rows = probed.map((v, i) => ({ at: points[i].point.map((x) => x.toFixed(2)).join(', '), direct: [v.direct, expected[i].direct], total: [v.total, expected[i].total] }));
    console.info(rows.map((r) => `[${r.at}] direct ${r.direct[0].toFixed(1)}/${r.direct[1].toFixed(1)} total ${r.total[0].toFixed(1)}/${r.total[1].toFixed(1)} (${(100 * (r.total[0] / r.total[1] - 1)).toFixed(2)} %)`).join('\n'));
    for (const r of rows) {
      expect(Math.abs(r.direct[0] / r.direct[1] - 1), `direct at [${r.at}]`).toBeLessThan(0.005);
      expect(Math.abs(r.total[0] / r.total[1] - 1), `total at [${r.at}]`).toBeLessThan(0.05);
    }
    // Both lamps face the slope more than the floor: its points get more direct light than the floor's.
    expect(Math.min(probed[2].direct, probed[3].direct)).toBeGreaterThan(2 * Math.max(probed[0].direct, probed[1].direct));
  });

  it("a point on a surface, probed as a point with that surface's normal, gets the same direct light", () => {
    const [point] = surfacePoints[3];
    const [asPlane] = probeShapedRoom(scene, maps, SETTINGS, [{ point, normal: [0, -c, s] }], 0.01);
    expect(asPlane.direct).toBeCloseTo(probed[3].direct, 6);
  });
});
