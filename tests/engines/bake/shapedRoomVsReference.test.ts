/**
 * Rooms of any shape (issue 29) baked by the GPU baker — the room's surfaces as charts of the
 * objects' atlas, inside an enclosure of black sinks (src/engines/bake/shapedRoom) — against the
 * independent room reference (src/reference/solveRoomReference.ts: patches on the same planar
 * surfaces, form factors with sight lines decided in plan, a final gather at the query point;
 * it shares no code with the baker). Compared at the G-buffer point of fully covered atlas
 * texels; points within 5 cm of a surface's or an opening's edge are left out and counted.
 */
import { describe, expect, it } from 'vitest';
import type { LightingLuminaire } from '../../../src/core/model/lightingScene/lightingScene';
import type { RoomInput } from '../../../src/core/room/roomInput';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { solveRoomReference } from '../../../src/reference/solveRoomReference';
import { isotropic, realPhotometry } from '../../reference/photometryFixtures';
import { bakeLuminaires, compareWithReference, relativeErrors, shapedBakeRoom } from './shapedRoomKit';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
const baker = createBaker(gl);

/** Source-cell size of both models (the baker's sourceSpacing, the reference's openingCell). */
const CELL = 0.05;
const SETTINGS = { texelSize: 0.1, sourceSpacing: CELL };
const REFERENCE = { patchSize: 0.25, openingCell: CELL };
const finishes = { floor: 0.3, ceiling: 0.8, walls: 0.6 };

const files = { iso: isotropic(1500), down: realPhotometry('bega_50975_downlight_lm1995_crlf.ies'), spot: realPhotometry('bega_84693_narrow_spot.ies') };
const lamp = (photometry: string, position: [number, number, number], angles: Partial<LightingLuminaire> = {}): LightingLuminaire => ({ photometry, position, yaw: 0, pitch: 0, roll: 0, ...angles });

function run(name: string, input: RoomInput, lamps: LightingLuminaire[], stride: number) {
  const scene: BakeScene = { room: shapedBakeRoom(input), luminaires: bakeLuminaires(lamps, files) };
  const t0 = performance.now();
  const { maps, report } = baker.bake(scene, SETTINGS);
  const bakeMs = performance.now() - t0;
  const reference = solveRoomReference(input, lamps, files, REFERENCE);
  const c = compareWithReference(scene, maps, reference, stride);
  const peak = Math.max(...c.points.map((p) => p.reference.total));
  const direct = relativeErrors(c.points, 'direct', 0.01 * peak);
  const total = relativeErrors(c.points, 'total', 0.01 * peak);
  const pct = (x: number) => `${(100 * x).toFixed(2)} %`;
  console.info(
    `${name}: bake ${bakeMs.toFixed(0)} ms, atlas ${maps.objects!.atlas.width}×${maps.objects!.atlas.height}; reference ${reference.patches.length} patches; ${c.points.length} points, ${c.nearEdge} near an edge; ` +
      `direct RMS ${pct(direct.rms)} max ${pct(direct.max)}; total RMS ${pct(total.rms)} max ${pct(total.max)} at ${total.worst?.surface} [${total.worst?.point.map((v) => v.toFixed(2)).join(', ')}] ` +
      `(bake ${total.worst?.bake.total.toFixed(1)}, reference ${total.worst?.reference.total.toFixed(1)} lx); report ${JSON.stringify(report.timings_ms)}`,
  );
  return { direct, total, c, maps, report };
}

describe('shaped rooms: GPU bake vs the room reference', () => {
  it('an L-shaped living room with a downlight in each arm: ≤ 3 % RMS, no point worse than 20 %', () => {
    const input: RoomInput = {
      outline: [
        [0, 0],
        [6, 0],
        [6, 3],
        [3.5, 3],
        [3.5, 5],
        [0, 5],
      ],
      height: 2.6,
      reflectance: finishes,
    };
    const r = run('L', input, [lamp('down', [4.5, 2.5, 1.5]), lamp('down', [1.5, 2.5, 4])], 3);
    expect(r.direct.rms).toBeLessThan(0.005);
    expect(r.total.rms).toBeLessThan(0.03);
    expect(r.total.max).toBeLessThan(0.2);
  }, 600_000);
});
