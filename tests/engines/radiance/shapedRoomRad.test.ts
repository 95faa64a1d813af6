/**
 * The Radiance export of a room of any shape (issue 29): per surface of roomSurfaces one material
 * and its polygons, whose areas (Newell, in Radiance's frame) add up to the surface's area without
 * its openings and whose right-hand normals point into the room; then, where Radiance is
 * installed, Radiance's direct light at floor points against the independent reference's
 * (src/reference, which shadows by the room's own walls).
 */
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { exportRadiance } from '../../../src/engines/radiance/exportRadiance';
import { roomRad } from '../../../src/engines/radiance/roomRad';
import { loadLightingSceneFile } from '../../../src/hosts/node/loadLightingSceneFile';
import { compileOctree, findRadianceBin, rtraceLux, writeExportFiles } from '../../../src/hosts/node/radianceTools';
import { roomSurfaces } from '../../../src/core/room/roomSurfaces';
import { referencePointSources } from '../../../src/reference/pointSources';
import { roomDirectAt } from '../../../src/reference/roomDirect';
import type { Photometry } from '../../../src/core/photometry/types';
import type { Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import { parseRad } from './radianceSceneEvaluator';
import { normaliseRoom } from '../../../src/core/room/normaliseRoom';
import type { RoomInput } from '../../../src/core/room/roomInput';
import { pointInsideRoom } from '../../../src/core/room/ceilingHeightAt';
import { clearOfWalls } from '../../../src/engines/view/shapedRoomCamera';
import { EYE_MARGIN } from '../../../src/engines/view/frameTheLight';

const FIXTURE = 'tests/fixtures/scenes/attic-l-room.json';
const loaded = loadLightingSceneFile(FIXTURE);
const shape = loaded.scene.room.shape!;
// Objects are not part of this check (the export writes the room and the luminaires).
const bakeScene = { ...loaded.bakeScene, objects: undefined };

/** Radiance (X, Y, Z) back to luxbox (x, y, z) = (X, Z, −Y). */
const fromRadiance = (v: number[]): Vec3 => [v[0], v[2], -v[1]];

function newell(poly: Vec3[]): Vec3 {
  const n: Vec3 = [0, 0, 0];
  poly.forEach((a, i) => {
    const b = poly[(i + 1) % poly.length];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  });
  return n;
}

describe('Radiance export of a room of any shape', () => {
  it('one material per surface; its polygons cover the surface less its openings, normals into the room', () => {
    const prims = parseRad(roomRad(bakeScene));
    const surfaces = roomSurfaces(shape);
    const materials = prims.filter((p) => p.type === 'plastic');
    expect(materials.map((m) => m.name)).toEqual(surfaces.map((s) => `${s.id.replace('-', '_')}_material`));
    let polygons = 0;
    for (const s of surfaces) {
      const material = materials.find((m) => m.name === `${s.id.replace('-', '_')}_material`)!;
      expect(material.reals).toEqual([...s.reflectance, 0, 0]);
      const mine = prims.filter((p) => p.type === 'polygon' && p.modifier === material.name);
      polygons += mine.length;
      let area = 0;
      for (const p of mine) {
        const vertices = Array.from({ length: p.reals.length / 3 }, (_, k) => fromRadiance(p.reals.slice(3 * k, 3 * k + 3)));
        const n = newell(vertices);
        const a = Math.hypot(...n) / 2;
        area += a;
        // The right-hand normal (Radiance's front) is the surface's inward normal.
        expect(
          n
            .map((c) => c / (2 * a))
            .map((c, i) => c - s.inward[i])
            .every((d) => Math.abs(d) < 1e-5),
        ).toBe(true);
      }
      // Coordinates are written to 7 significant digits: areas agree to about 1e-6 relative.
      expect(area).toBeCloseTo(s.area, 4);
    }
    // The walls with openings come in pieces around them: the door's wall 4 left of, above and right of
    // it; the window's wall 1 (z 1.5 to 2.7) in strips cut at its sides and at z = 1.4 / tan 40° = 1.668,
    // where the slope over its south end meets the flat ceiling: 1 + 2 + 2 + 1 pieces.
    const door = surfaces.find((s) => s.id === 'wall-4')!;
    expect(door.openings).toHaveLength(1);
    expect(prims.filter((p) => p.type === 'polygon' && p.modifier === 'wall_4_material')).toHaveLength(3);
    expect(prims.filter((p) => p.type === 'polygon' && p.modifier === 'wall_1_material')).toHaveLength(6);
    expect(polygons).toBe(surfaces.length - 2 + 3 + 6);
  });

  it('the illuminance grids keep only points inside the outline and under the ceiling', () => {
    const files = exportRadiance(bakeScene);
    const floor = files
      .find((f) => f.path === 'points/floor.pts')!
      .text.trim()
      .split('\n');
    const plan = floor.map((line) => line.split(' ').map(Number)).map(([X, Y]) => [X, -Y]);
    // The L is 6 × 5 m less its 2.5 × 2 m notch; at 0.25 m the notch's edges fall between grid points: 24 × 20 − 10 × 8 points.
    expect(plan.every(([x, z]) => !(x > 3.5 && z > 3))).toBe(true);
    expect(plan.length).toBeGreaterThan(0);
    expect(plan.length).toBe(24 * 20 - 10 * 8);
  });

  it('the eye view stands inside the outline, clear of every wall and under the slope; the top and corner views look down from above the ceiling', () => {
    // The fixture (its light to frame), the same L dark (the eye across the room), and a U whose bounding box centre is in its notch.
    const u: RoomInput = {
      outline: [
        [0, 0],
        [6, 0],
        [6, 5],
        [4, 5],
        [4, 1.5],
        [2, 1.5],
        [2, 5],
        [0, 5],
      ],
      height: 2.5,
      reflectance: { floor: 0.3, ceiling: 0.8, walls: 0.5 },
    };
    const uShape = normaliseRoom(u);
    const uScene = { room: { width: 6, height: 2.5, depth: 5, reflectance: bakeScene.room.reflectance, shape: uShape }, luminaires: [] };
    const cases = [
      { scene: bakeScene, room: shape },
      { scene: { ...bakeScene, luminaires: [] }, room: shape },
      { scene: uScene, room: uShape },
    ];
    for (const { scene, room } of cases) {
      const files = exportRadiance(scene);
      const view = (name: string) => {
        const text = files.find((f) => f.path === `views/${name}.vf`)!.text;
        const numbers = (flag: string) =>
          /-(vp|vd) (\S+) (\S+) (\S+)/g
            .exec(text.slice(text.indexOf(flag)))!
            .slice(2)
            .map(Number);
        return { eye: fromRadiance(numbers('-vp')), dir: fromRadiance(numbers('-vd')) };
      };
      const { eye, dir } = view('eye');
      expect(pointInsideRoom(room, eye), `eye [${eye.join(', ')}]`).toBe(true);
      // Clear of every wall by the eye camera's margin (frameTheLight.ts EYE_MARGIN), written to 7 digits.
      expect(clearOfWalls(room, [eye[0], eye[2]], EYE_MARGIN * 0.999), `eye [${eye.join(', ')}] near a wall`).toBe(true);
      // Looking into the room: a point a metre ahead is still inside.
      const ahead: Vec3 = [eye[0] + dir[0], eye[1] + dir[1], eye[2] + dir[2]];
      expect(pointInsideRoom(room, ahead), `ahead of the eye [${ahead.join(', ')}]`).toBe(true);
      for (const name of ['top', 'corner']) {
        const outside = view(name);
        expect(outside.eye[1]).toBeGreaterThan(room.height);
        expect(outside.dir[1]).toBeLessThan(0);
      }
    }
    // The U's bounding box centre (3, 2.5) is in its notch: no camera stands there.
    expect(pointInsideRoom(uShape, [3, 1.6, 2.5])).toBe(false);
  });

  const bin = process.env.LUXBOX_RADIANCE_BIN ?? findRadianceBin(join(__dirname, '../../..'));
  it.skipIf(!bin)(
    'Radiance (rtrace, direct only) agrees with the reference at floor points, one in the shadow of the inner corner',
    () => {
      const dir = mkdtempSync(join(tmpdir(), 'luxbox-radiance-shape-'));
      writeExportFiles(dir, exportRadiance(bakeScene));
      compileOctree(bin!, dir);
      // (3.4, 4.9) sees the downlight but not the wall washer at (4.5, 1.5, 1.5): the notch is between them.
      const points: Vec3[] = [
        [1, 0, 1],
        [2.5, 0, 2],
        [5, 0, 1],
        [1, 0, 4.5],
        [3.4, 0, 4.9],
      ];
      const radiance = rtraceLux(bin!, dir, ['-ab', '0', '-dt', '0', '-dc', '1'], points.map(([x, y, z]) => `${x} ${-z} ${y + 0.001} 0 0 1`).join('\n') + '\n');
      const photometries = new Map<string, Photometry>(loaded.scene.luminaires.map((l, i) => [l.photometry, bakeScene.luminaires[i].photometry]));
      const sources = referencePointSources({ ...loaded.scene, objects: undefined }, photometries);
      const sight = { convex: shape.convex, corners: shape.corners };
      const reference = points.map((q) => {
        const [r, g, b] = roomDirectAt(sources, sight, q, [0, 1, 0]);
        return 0.2126 * r + 0.7152 * g + 0.0722 * b;
      });
      console.table(points.map((p, i) => ({ point: p.join(', '), radiance: radiance[i], reference: reference[i] })));
      for (let i = 0; i < points.length; i++) expect(Math.abs(radiance[i] / reference[i] - 1), `point ${points[i]}`).toBeLessThan(0.01);
      // The shadowed point gets only the downlight: the washer alone gives it nothing in the reference.
      const washerOnly = referencePointSources({ ...loaded.scene, objects: undefined, luminaires: [loaded.scene.luminaires[1]] }, photometries);
      expect(roomDirectAt(washerOnly, sight, points[4], [0, 1, 0])).toEqual([0, 0, 0]);
    },
    120_000,
  );
});
