/**
 * Rooms of any shape in `luxbox bench` (issue 29): an L-shaped living room, an attic with a knee
 * wall and a spot aimed under the slope, a room with a chimney breast — each baked at every rung
 * of SHAPED_LADDER (after an untimed warm-up bake) and compared with the independent room
 * reference (src/reference/solveRoomReference.ts) at fully covered atlas texels of the room's
 * surfaces (shapedRoomComparison.ts: points within 5 cm of an edge left out and counted). Each rung
 * is also baked with `brightPatches: 0` in the same run, right after: a shaped room's box surfaces
 * are black sinks, so that is the bake before bright patches on atlas charts existed, and the ratio
 * of the two times is what the patches cost (docs/baker.md, "Rooms of any shape").
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { LightingLuminaire } from '../../core/model/lightingScene/lightingScene';
import { parsePhotometry } from '../../core/photometry/parsePhotometry';
import type { Photometry } from '../../core/photometry/types';
import { normaliseRoom } from '../../core/room/normaliseRoom';
import type { RoomInput } from '../../core/room/roomInput';
import type { BakeScene } from '../../engines/bake/bakeScene';
import type { Baker } from '../../engines/bake/createBaker';
import { solveRoomReference } from '../../reference/solveRoomReference';
import type { BenchQuality } from './benchScenes';
import { compareWithReference, relativeErrors } from './shapedRoomComparison';
import { percentCell, referenceSceneTable } from './referenceSceneTable';

export interface ShapedBenchScene {
  name: string;
  description: string;
  room: RoomInput;
  luminaires: LightingLuminaire[];
  /** `photometry` key → file under public/ies. */
  files: Record<string, string>;
}

const finishes = { floor: 0.3, ceiling: 0.8, walls: 0.6 };
const lamp = (photometry: string, position: [number, number, number], pitch = 0): LightingLuminaire => ({ photometry, position, yaw: 0, pitch, roll: 0 });

export const SHAPED_SCENES: readonly ShapedBenchScene[] = [
  {
    name: 'l-living',
    description: 'L-shaped living room, 6 × 5 m outline (2.5 × 2 m notch), 2.6 m, a downlight (BEGA 50975) in each arm',
    room: {
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
    },
    luminaires: [lamp('down', [4.5, 2.5, 1.5]), lamp('down', [1.5, 2.5, 4])],
    files: { down: 'bega_50975_downlight_lm1995_crlf.ies' },
  },
  {
    name: 'attic-spot',
    description: 'attic 5 × 4 m, 2.5 m, a 40° slope from a 1 m knee wall; a narrow spot (BEGA 84693) aimed up under the slope and a downlight',
    room: {
      outline: [
        [0, 0],
        [5, 0],
        [5, 4],
        [0, 4],
      ],
      height: 2.5,
      slopes: [{ wall: 0, kneeHeight: 1, pitch: 40 }],
      reflectance: finishes,
    },
    luminaires: [lamp('spot', [2.5, 1.6, 3], 120), lamp('down', [1.2, 2.4, 2.8])],
    files: { spot: 'bega_84693_narrow_spot.ies', down: 'bega_50975_downlight_lm1995_crlf.ies' },
  },
  {
    name: 'chimney-breast',
    description: 'room 5 × 4 m, 2.5 m, a 1.4 × 0.5 m chimney breast on the north wall, two downlights (BEGA 50975)',
    room: {
      outline: [
        [0, 0],
        [1.8, 0],
        [1.8, 0.5],
        [3.2, 0.5],
        [3.2, 0],
        [5, 0],
        [5, 4],
        [0, 4],
      ],
      height: 2.5,
      reflectance: finishes,
    },
    luminaires: [lamp('down', [1, 2.4, 1]), lamp('down', [4, 2.4, 2.5])],
    files: { down: 'bega_50975_downlight_lm1995_crlf.ies' },
  },
];

/** Default samples and bounces at two texel sizes, and 4× the samples (to tell noise from bias). */
export const SHAPED_LADDER: readonly BenchQuality[] = [
  { texelSize: 0.1, samples: 64, bounces: 4 },
  { texelSize: 0.05, samples: 64, bounces: 4 },
  { texelSize: 0.1, samples: 256, bounces: 4 },
];

export interface ShapedBenchRow {
  scene: string;
  quality: BenchQuality;
  bakeMs: number;
  points: number;
  nearEdge: number;
  directRms: number;
  totalRms: number;
  totalMax: number;
  /** The same rung with `brightPatches: 0` (no patches on the atlas's charts): its bake time and total errors. */
  withoutPatches: { bakeMs: number; totalRms: number; totalMax: number };
}

export interface ShapedBenchScenePart {
  scene: ShapedBenchScene;
  patches: number;
  referenceMs: number;
  rows: ShapedBenchRow[];
}

/** The bench's shaped rooms; `ladder` (default SHAPED_LADDER) is what each is baked at (a shorter one for a quick measurement). */
export function runShapedRoomBench(baker: Baker, root: string, log: (line: string) => void, ladder: readonly BenchQuality[] = SHAPED_LADDER): ShapedBenchScenePart[] {
  const parts: ShapedBenchScenePart[] = [];
  for (const s of SHAPED_SCENES) {
    const files: Record<string, Photometry> = {};
    for (const [key, file] of Object.entries(s.files)) files[key] = parsePhotometry(readFileSync(join(root, 'public/ies', file)), file);
    const t0 = performance.now();
    const reference = solveRoomReference(s.room, s.luminaires, files, { patchSize: 0.25, openingCell: 0.05 });
    let referenceMs = performance.now() - t0;
    log(`${s.name}: room reference ${reference.patches.length} patches, ${Math.round(referenceMs)} ms`);
    const shape = normaliseRoom(s.room);
    const xs = shape.corners.map((c) => c[0]);
    const zs = shape.corners.map((c) => c[1]);
    const grey = { floor: 0.5, ceiling: 0.5, north: 0.5, south: 0.5, west: 0.5, east: 0.5 };
    const scene: BakeScene = {
      room: { width: Math.max(...xs) - Math.min(...xs), height: shape.height, depth: Math.max(...zs) - Math.min(...zs), reflectance: grey, shape },
      luminaires: s.luminaires.map((l) => ({ ...l, photometry: files[l.photometry], dimming: 1, color: [1, 1, 1] })),
    };
    const rows: ShapedBenchRow[] = [];
    for (const quality of ladder) {
      const measure = (brightPatches?: number) => {
        const settings = { ...quality, sourceSpacing: 0.05, ...(brightPatches === undefined ? {} : { brightPatches }) };
        baker.bake(scene, { ...settings, samples: 16, bounces: 1 });
        const started = performance.now();
        const { maps } = baker.bake(scene, settings);
        const bakeMs = performance.now() - started;
        const t1 = performance.now();
        // About one point per 0.1 m × 0.1 m whatever the texel size.
        const c = compareWithReference(scene, maps, reference, Math.max(1, Math.round(0.1 / quality.texelSize) ** 2));
        referenceMs += performance.now() - t1;
        const peak = Math.max(...c.points.map((p) => p.reference.total));
        return { bakeMs, c, direct: relativeErrors(c.points, 'direct', 0.01 * peak), total: relativeErrors(c.points, 'total', 0.01 * peak) };
      };
      const { bakeMs, c, direct, total } = measure();
      const without = measure(0);
      const withoutPatches = { bakeMs: without.bakeMs, totalRms: without.total.rms, totalMax: without.total.max };
      const row: ShapedBenchRow = { scene: s.name, quality, bakeMs, points: total.n, nearEdge: c.nearEdge, directRms: direct.rms, totalRms: total.rms, totalMax: total.max, withoutPatches };
      rows.push(row);
      log(
        `  texel ${quality.texelSize} m, ${quality.samples} samples: bake ${Math.round(bakeMs)} ms; direct RMS ${(100 * row.directRms).toFixed(2)} %, total RMS ${(100 * row.totalRms).toFixed(2)} %, worst ${(100 * row.totalMax).toFixed(1)} % (${row.points} points, ${row.nearEdge} near an edge); ` +
          `without chart patches ${Math.round(without.bakeMs)} ms, total RMS ${(100 * without.total.rms).toFixed(2)} %, worst ${(100 * without.total.max).toFixed(1)} %`,
      );
    }
    parts.push({ scene: s, patches: reference.patches.length, referenceMs, rows });
  }
  return parts;
}

/** The shaped-room rows as markdown (docs/benchmarks.md, "Rooms of any shape"). */
export function shapedRoomTables(parts: readonly ShapedBenchScenePart[]): string {
  const lines = referenceSceneTable(parts);
  lines.push('| scene | texel | samples | bounces | bake time | points (near an edge, left out) | direct RMS | total RMS | worst point | without chart patches: total RMS / worst | time / without |');
  lines.push('|---|---|---|---|---|---|---|---|---|---|---|');
  for (const p of parts) {
    for (const r of p.rows) {
      const w = r.withoutPatches;
      lines.push(
        `| ${r.scene} | ${r.quality.texelSize} m | ${r.quality.samples} | ${r.quality.bounces} | ${Math.round(r.bakeMs)} ms | ${r.points} (${r.nearEdge}) | ${percentCell(r.directRms)} | ${percentCell(r.totalRms)} | ${percentCell(r.totalMax)} | ${percentCell(w.totalRms)} / ${percentCell(w.totalMax)} | ${(r.bakeMs / w.bakeMs).toFixed(2)} |`,
      );
    }
  }
  return lines.join('\n');
}
