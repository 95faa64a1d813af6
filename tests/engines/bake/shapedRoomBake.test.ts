/**
 * Rooms of any shape in the baker (issue 29, src/engines/bake/shapedRoom): the room's own
 * surfaces shadow the lamps (the inner corner of an L), closed rooms keep every lumen
 * (CIE 171:2006 §5.8: Σ E·A = Φ/(1 − ρ) for uniform ρ), an opening lets out what the reference
 * says, and the enclosure's box surfaces are one-texel black sinks that never show.
 */
import { existsSync, mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import type { LightingLuminaire, Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import type { RoomInput } from '../../../src/core/room/roomInput';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { luxOf, type BakedMaps } from '../../../src/engines/bake/bakedMaps';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { ENCLOSURE_MARGIN, encloseShapedRoom } from '../../../src/engines/bake/shapedRoom/encloseShapedRoom';
import { ROOM_OBJECT_PREFIX } from '../../../src/engines/bake/shapedRoom/roomSurfaceObjects';
import { roomDirectAt } from '../../../src/reference/roomDirect';
import { roomFluxes, solveRoomReference } from '../../../src/reference/solveRoomReference';
import { writeBakeOutput } from '../../../src/hosts/node/writeBakeOutput';
import { isotropic } from '../../reference/photometryFixtures';
import { bakeLuminaires, shapedBakeRoom } from './shapedRoomKit';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
const baker = createBaker(gl);

const LUMENS = 1000;
const files = { iso: isotropic(LUMENS) };
const lamp = (position: Vec3): LightingLuminaire => ({ photometry: 'iso', position, yaw: 0, pitch: 0, roll: 0 });
const uniform = (rho: number) => ({ floor: rho, ceiling: rho, walls: rho });

const L_OUTLINE: [number, number][] = [
  [0, 0],
  [6, 0],
  [6, 3],
  [3.5, 3],
  [3.5, 5],
  [0, 5],
];
const ATTIC: Omit<RoomInput, 'reflectance'> = {
  outline: [
    [0, 0],
    [5, 0],
    [5, 4],
    [0, 4],
  ],
  height: 2.5,
  slopes: [
    { wall: 0, kneeHeight: 1, pitch: 40 },
    { wall: 2, kneeHeight: 1.2, pitch: 35 },
  ],
};

const sceneOf = (input: RoomInput, lamps: LightingLuminaire[]): BakeScene => ({ room: shapedBakeRoom(input), luminaires: bakeLuminaires(lamps, files) });

/** Σ E·A (lm, Y) over the room's surfaces (atlas texels of the room's objects: E·coverage·texel²) and over the enclosure's sinks. */
function fluxes(scene: BakeScene, maps: BakedMaps, kind: 'direct' | 'total'): { room: number; sinks: number } {
  const surfaces = encloseShapedRoom(scene).room.enclosure!.surfaces.length;
  const o = maps.objects!;
  const e = luxOf(o[kind]);
  const t2 = o.atlas.texelSize ** 2;
  let room = 0;
  for (let k = 0; k < e.length; k++) {
    const object = o.atlas.reflectance[4 * k + 3] - 1;
    if (object >= 0 && object < surfaces) room += e[k] * o.atlas.position[4 * k + 3] * t2;
  }
  let sinks = 0;
  for (const name of ['floor', 'ceiling', 'north', 'south', 'west', 'east'] as const) {
    const m = maps[name];
    sinks += luxOf(m[kind])[0] * m.layout.lengthU * m.layout.lengthV;
  }
  return { room, sinks };
}

describe('shaped rooms in the baker', () => {
  it('encloses the room: a margin on every side, the surfaces as the first objects, box surfaces black one-texel sinks', () => {
    // An outline that does not start at the origin: bake coordinates shift it to the margin.
    const outline = L_OUTLINE.map(([x, z]): [number, number] => [x - 2, z + 1]);
    const scene = sceneOf({ outline, height: 2.6, reflectance: uniform(0.5) }, [lamp([0, 2, 2])]);
    const enclosed = encloseShapedRoom(scene);
    const e = enclosed.room.enclosure!;
    expect(e.offset).toEqual([ENCLOSURE_MARGIN + 2, ENCLOSURE_MARGIN, ENCLOSURE_MARGIN - 1]);
    expect([enclosed.room.width, enclosed.room.height, enclosed.room.depth]).toEqual([6 + 2 * ENCLOSURE_MARGIN, 2.6 + 2 * ENCLOSURE_MARGIN, 5 + 2 * ENCLOSURE_MARGIN]);
    expect(enclosed.luminaires[0].position).toEqual([2 + ENCLOSURE_MARGIN, 2 + ENCLOSURE_MARGIN, 1 + ENCLOSURE_MARGIN]);
    expect(enclosed.objects!.map((o) => o.id)).toEqual(['floor', 'ceiling', 'wall-0', 'wall-1', 'wall-2', 'wall-3', 'wall-4', 'wall-5'].map((s) => ROOM_OBJECT_PREFIX + s));
    expect(Object.values(enclosed.room.reflectance).every((r) => r === 0)).toBe(true);
    // Remembered: the same scene gives the same objects array (one prepared atlas for every relight group).
    expect(encloseShapedRoom(scene).objects).toBe(enclosed.objects);
    expect(encloseShapedRoom(enclosed)).toBe(enclosed);
    const { maps, report } = baker.bake(scene, { texelSize: 0.2, samples: 16, bounces: 1 });
    for (const name of ['floor', 'ceiling', 'north', 'south', 'west', 'east'] as const) expect([maps[name].layout.width, maps[name].layout.height]).toEqual([1, 1]);
    // Closed room: nothing reaches the sinks.
    expect(fluxes(scene, maps, 'total').sinks).toBe(0);
    expect(report.objects!.slice(0, 8).map((o) => o.id)).toEqual(enclosed.objects!.map((o) => o.id));
    // The floor's area is the L's (6 × 5 − 2.5 × 2 = 25 m²).
    expect(report.objects![0].area).toBeCloseTo(25, 4);
  }, 300_000);

  it('the inner corner of an L casts a shadow: exactly zero direct light behind it, the reference’s value beside it', () => {
    const input: RoomInput = { outline: L_OUTLINE, height: 2.6, reflectance: uniform(0.5) };
    const pos: Vec3 = [5, 2, 1];
    const scene = sceneOf(input, [lamp(pos)]);
    const { maps } = baker.bake(scene, { texelSize: 0.1, samples: 16, bounces: 1, sourceSpacing: 0.05 });
    const reference = solveRoomReference(input, [lamp(pos)], files, { patchSize: 1, openingCell: 0.05 });
    const e = encloseShapedRoom(scene).room.enclosure!;
    const o = maps.objects!;
    const direct = luxOf(o.direct);
    let shadowed = 0;
    let lit = 0;
    for (let k = 0; k < direct.length; k++) {
      if (o.atlas.position[4 * k + 3] < 0.999 || o.atlas.reflectance[4 * k + 3] !== 1) continue; // the floor's full texels
      const p: Vec3 = [o.atlas.position[4 * k] - e.offset[0], 0, o.atlas.position[4 * k + 2] - e.offset[2]];
      // Shadow edge in plan: the line from the lamp through the inner corner (3.5, 3); 10 cm clear of it either side.
      const side = (3.5 - pos[0]) * (p[2] - pos[2]) - (3 - pos[2]) * (p[0] - pos[0]);
      const distance = Math.abs(side) / Math.hypot(3.5 - pos[0], 3 - pos[2]);
      if (p[2] <= 3.1 || distance < 0.1) continue;
      const ref = roomDirectAt(reference.sources, reference.sight, p, [0, 1, 0]);
      const refY = 0.2126 * ref[0] + 0.7152 * ref[1] + 0.0722 * ref[2];
      if (side < 0) {
        // Behind the corner, seen from the lamp.
        expect(refY).toBe(0);
        expect(direct[k]).toBe(0);
        shadowed++;
      } else {
        expect(Math.abs(direct[k] / refY - 1)).toBeLessThan(1e-3);
        lit++;
      }
    }
    expect(shadowed).toBeGreaterThan(50);
    expect(lit).toBeGreaterThan(50);
  }, 300_000);

  for (const [name, input] of [
    ['an L', { outline: L_OUTLINE, height: 2.6 }],
    ['an attic under two slopes', ATTIC],
  ] as const) {
    it(`${name}, closed, ρ = 0.6: Σ E·A over the room's surfaces = Φ/(1 − ρ) within 1 %, and Σ E_dir·A = Φ within 0.5 %`, () => {
      const rho = 0.6;
      const scene = sceneOf({ ...input, reflectance: uniform(rho) }, [lamp([1.5, 1.8, 2])]);
      const { maps } = baker.bake(scene, { texelSize: 0.1, samples: 64, bounces: 4 });
      const direct = fluxes(scene, maps, 'direct');
      const total = fluxes(scene, maps, 'total');
      console.info(`${name}: Σ E_dir·A ${direct.room.toFixed(1)} lm (Φ ${LUMENS}), Σ E·A ${total.room.toFixed(1)} lm (Φ/(1 − ρ) ${(LUMENS / (1 - rho)).toFixed(1)}), sinks ${total.sinks}`);
      expect(Math.abs(direct.room / LUMENS - 1)).toBeLessThan(0.005);
      expect(Math.abs(total.room / (LUMENS / (1 - rho)) - 1)).toBeLessThan(0.01);
      expect(total.sinks).toBe(0);
    }, 300_000);
  }

  it('openings: light that reaches them is lost; Σ E·A in the room and the light let out match the reference', () => {
    const input: RoomInput = {
      outline: L_OUTLINE,
      height: 2.6,
      reflectance: uniform(0.5),
      openings: [
        { wall: 0, offset: 1, width: 1.2, sill: 0.9, height: 1.2, kind: 'window' },
        { wall: 5, offset: 2, width: 0.9, sill: 0, height: 2, kind: 'door' },
      ],
    };
    const pos: Vec3 = [2, 2, 2];
    const scene = sceneOf(input, [lamp(pos)]);
    const { maps } = baker.bake(scene, { texelSize: 0.1, samples: 64, bounces: 4, sourceSpacing: 0.05 });
    const reference = roomFluxes(solveRoomReference(input, [lamp(pos)], files, { patchSize: 0.25, openingCell: 0.05 }));
    const total = fluxes(scene, maps, 'total');
    // What the surfaces do not absorb has left: Φ = Σ (1 − ρ)·E·A + escaped (the sinks' one texel is no measure of it).
    const escaped = LUMENS - 0.5 * total.room;
    console.info(`opening: Σ E·A room ${total.room.toFixed(1)} lm (reference ${reference.total.toFixed(1)}), escaped ${escaped.toFixed(1)} lm (reference ${reference.escaped.toFixed(1)}, of it direct ${reference.escapedDirect.toFixed(1)})`);
    expect(total.sinks).toBeGreaterThan(0);
    expect(Math.abs(total.room / reference.total - 1)).toBeLessThan(0.02);
    expect(Math.abs(escaped / reference.escaped - 1)).toBeLessThan(0.15);
  }, 300_000);

  it('luxbox bake’s output: report.json’s surfaces are the room’s (floor area of the polygon), objects.json lists them first, no sink files', () => {
    const input: RoomInput = { outline: L_OUTLINE, height: 2.6, reflectance: uniform(0.5), openings: [{ wall: 5, offset: 2, width: 0.9, sill: 0, height: 2, kind: 'door' }] };
    const scene = sceneOf(input, [lamp([2, 2, 2])]);
    const { maps, report } = baker.bake(scene, { texelSize: 0.2, samples: 16, bounces: 1 });
    const dir = mkdtempSync(join(tmpdir(), 'luxbox-shaped-'));
    writeBakeOutput(dir, 'l.json', maps, report);
    const json = JSON.parse(readFileSync(join(dir, 'report.json'), 'utf8'));
    expect(Object.keys(json.surfaces)).toEqual(['floor', 'ceiling', 'wall-0', 'wall-1', 'wall-2', 'wall-3', 'wall-4', 'wall-5']);
    expect(json.surfaces.floor.area).toBeCloseTo(25, 4);
    // Wall 5 (x = 0, 5 m × 2.6 m) less its 0.9 × 2 m door.
    expect(json.surfaces['wall-5'].area).toBeCloseTo(5 * 2.6 - 0.9 * 2, 4);
    expect(json.surfaces.floor.avg).toBeGreaterThan(0);
    expect(existsSync(join(dir, 'north.pfm'))).toBe(false);
    expect(existsSync(join(dir, 'north.total.pfm'))).toBe(false);
    const objects = JSON.parse(readFileSync(join(dir, 'objects.json'), 'utf8'));
    expect(objects.objects.map((o: { id: string }) => o.id)).toEqual(Object.keys(json.surfaces).map((id) => ROOM_OBJECT_PREFIX + id));
  }, 300_000);
});
