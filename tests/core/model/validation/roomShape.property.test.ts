/**
 * The always-valid property in rooms with a shape (issue 29): from an attic L (a slope on its
 * north wall), random sequences of the actions that move things in the plan; every enabled action
 * leaves validate() empty and a refused one, performed anyway, a state it rejects. After each
 * sequence an independent check of what "inside the room" means, written without the model's
 * footprint code: every corner of every rail, connector and module rectangle in the outline
 * (even–odd rule), the ceiling above each at least the shortest suspension above the modules (or,
 * for clips, the flat ceiling), every vertex of every placed object in the outline and under the
 * ceiling. Seeded so failures reproduce.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { createConfiguration, WALL_NAMES, type Configuration } from '../../../../src/core/model/configuration/configuration';
import { validate } from '../../../../src/core/model/validation/validate';
import { rectCorners, systemElementTree } from '../../../../src/core/model/rails/geometry';
import { moduleHeight } from '../../../../src/core/model/rails/suspensionPoints';
import { objectMesh, objectPlacement } from '../../../../src/core/model/objects/objectGeometry';
import { placedPositions } from '../../../../src/core/mesh/placeMesh';
import { FURNITURE_LIBRARY } from '../../../../src/core/model/objects/furniture/furnitureLibrary';
import { catalog } from '../helpers';
import { alwaysValidStep } from './alwaysValidStep';

const RUNS = Number(process.env.ROOM_SHAPE_RUNS ?? 300);
const unit = fc.noBias(fc.integer({ min: 0, max: 999_999 })).map((n) => n / 1_000_000);
const step = fc.record({ kind: fc.nat(11), i: fc.nat(50), j: fc.nat(50), a: unit, b: unit, c: unit });
type Step = { kind: number; i: number; j: number; a: number; b: number; c: number };
const pick = <T>(xs: readonly T[], i: number, fallback: T): T => (xs.length ? xs[i % xs.length] : fallback);

/** The L of `w` × `d` m whose notch is the last 40 % in x and 40 % in z, a slope (knee 1.6 m, 35°) on its north wall. */
function attic(w: number, d: number): Configuration {
  const outline = [
    [0, 0],
    [w, 0],
    [w, 0.6 * d],
    [0.6 * w, 0.6 * d],
    [0.6 * w, d],
    [0, d],
  ] as const;
  return createConfiguration({ width: w, depth: d, height: 2.8, shape: { outline, slopes: [{ wall: 0, kneeHeight: 1.6, pitch: 35 }], openings: [{ wall: 4, offset: 0.2, width: 0.9, sill: 0, height: 2, kind: 'door' }] } });
}

/** Even–odd point in polygon, boundary (within 1e-7 m) counting as inside: independent of src/core/room. */
function inside([x, z]: readonly number[], poly: readonly (readonly number[])[]): boolean {
  let odd = false;
  for (let i = 0, j = poly.length - 1; i < poly.length; j = i++) {
    const [ax, az] = poly[i];
    const [bx, bz] = poly[j];
    const t = Math.max(0, Math.min(1, ((x - ax) * (bx - ax) + (z - az) * (bz - az)) / ((bx - ax) ** 2 + (bz - az) ** 2)));
    if (Math.hypot(x - ax - t * (bx - ax), z - az - t * (bz - az)) < 1e-7) return true;
    if (az > z !== bz > z && x < ((bx - ax) * (z - az)) / (bz - az) + ax) odd = !odd;
  }
  return odd;
}

/** The ceiling over (x, z): the flat ceiling (setRoom changes its height) or the slope on the north wall (z = 0), 1.6 + z·tan 35°. */
const ceilingAt = (z: number, height: number) => Math.min(height, 1.6 + z * Math.tan((35 * Math.PI) / 180));

function toAction(s: Configuration, st: Step): [string, unknown] {
  const { width: W, depth: D } = s.room;
  const sys = pick(
    s.systems.map((x) => x.id),
    st.i,
    'none',
  );
  const rail = pick(
    s.systems.flatMap((x) => x.rails.map((r) => r.id)),
    st.i,
    'none',
  );
  const obj = pick(
    s.objects.map((o) => o.id),
    st.i,
    'none',
  );
  if (s.systems.length === 0 && st.c < 0.7) return ['placePreset', { presetId: pick(catalog.presets, st.j, catalog.presets[0]).id, x: st.a * W, z: st.b * D, rotation: 90 * (st.i % 4) }];
  switch (st.kind) {
    case 0:
      return ['placePreset', { presetId: pick(catalog.presets, st.j, catalog.presets[0]).id, x: st.a * W, z: st.b * D, rotation: 90 * (st.i % 4) }];
    case 1:
      return ['moveSystem', { systemId: sys, x: st.a * W, z: st.b * D }];
    case 2:
      return ['rotateSystem', { systemId: sys, by: 90 * (st.j % 4) }];
    case 3:
      return ['setSuspension', { systemId: sys, suspension: 0.1 + st.a * 0.8 }];
    case 4:
      return ['setMounting', { systemId: sys, mounting: st.b < 0.5 ? 'surface' : 'suspended' }];
    case 5:
      return ['setRailLength', { railId: rail, length: 0.5 + 0.1 * (st.j % 26) }];
    case 6:
      return ['addRail', { systemId: sys, connector: pick(catalog.connectors, st.j, catalog.connectors[0]).id, turn: [0, 90, -90][st.i % 3], length: 0.5 + st.a * 2 }];
    case 7:
    case 8: {
      const item = pick(FURNITURE_LIBRARY, st.j, FURNITURE_LIBRARY[0]);
      const placement = item.mount === 'wall' ? { on: 'wall', wall: WALL_NAMES[st.i % 4], u: st.a * Math.max(W, D), y: 0.5 + st.b * 1.5 } : { on: 'floor', x: st.a * W, z: st.b * D };
      return ['addObject', { source: { kind: 'library', item: item.id }, placement }];
    }
    case 9:
      return ['moveObject', { objectId: obj, placement: { on: 'floor', x: st.a * W, z: st.b * D } }];
    case 10:
      return ['setRoom', { width: st.c < 0.5 ? W : W + 0.5, depth: D, height: 2.6 + st.a * 0.6 }];
    default:
      return ['deleteSystem', { systemId: sys }];
  }
}

describe('always valid in a room with a shape', () => {
  it('enabled actions keep validate() empty, and what they leave is inside the L and under its slope', () => {
    const tally = { enabled: 0, refused: 0, systems: 0, underSlope: 0, objects: 0 };
    fc.assert(
      fc.property(unit, unit, fc.array(step, { minLength: 4, maxLength: 20 }), (a, b, steps) => {
        let s = attic(4 + a * 4, 4 + b * 4);
        if (validate(s, catalog).length > 0) throw new Error('the attic L is valid');
        for (const st of steps) {
          const [name, params] = toAction(s, st);
          s = alwaysValidStep(s, name, params, tally);
        }
        const outline = s.room.shape!.outline;
        for (const sys of s.systems) {
          tally.systems++;
          const corners = systemElementTree(sys, catalog).elements.flat().flatMap(rectCorners);
          for (const c of corners) if (!inside(c, outline)) throw new Error(`system ${sys.id}: corner ${c} outside the L`);
          const lowest = Math.min(...corners.map(([, z]) => ceilingAt(z, s.room.height)));
          if (lowest < s.room.height - 1e-9) tally.underSlope++;
          if (sys.mounting === 'surface') {
            if (lowest < s.room.height - 1e-9) throw new Error(`system ${sys.id}: clips under the slope`);
          } else if (lowest - moduleHeight(sys, s.room, catalog) < catalog.suspension.min - 1e-9) throw new Error(`system ${sys.id}: closer to the slope than the shortest suspension`);
        }
        for (const o of s.objects) {
          tally.objects++;
          const placed = placedPositions(objectMesh(s, o.id), objectPlacement(o, s.room));
          for (let k = 0; k < placed.length; k += 3) {
            if (!inside([placed[k], placed[k + 2]], outline)) throw new Error(`object ${o.id}: a vertex outside the L`);
            if (placed[k + 1] > ceilingAt(placed[k + 2], s.room.height) + 1e-6) throw new Error(`object ${o.id}: a vertex above the ceiling`);
          }
        }
      }),
      { numRuns: RUNS, seed: 29 },
    );
    console.log(`room shape always-valid: ${RUNS} sequences, ${JSON.stringify(tally)}`);
    // The sequences reach what they test: systems placed, some of them under the slope, objects in the room.
    expect(tally.enabled).toBeGreaterThan(RUNS);
    expect(tally.systems).toBeGreaterThan(RUNS / 4);
    expect(tally.underSlope).toBeGreaterThan(0);
    expect(tally.objects).toBeGreaterThan(RUNS / 10);
  }, 300_000);
});
