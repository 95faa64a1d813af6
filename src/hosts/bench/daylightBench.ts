/**
 * Daylight in `luxbox bench` (issue 30): three daylit rooms — the reference tests' box under a CIE
 * overcast sky, the same box under the CIE clear sky with the sun (the sun patch on the floor), the
 * L whose inner corner hides part of its window — each baked at every rung of DAYLIGHT_LADDER
 * (after an untimed warm-up bake) and compared with the independent daylight reference
 * (src/reference/solveDaylightReference.ts) at fully covered atlas texels of the room's surfaces
 * (daylightComparison.ts: points within 5 cm of an edge left out and counted). Error against run
 * time: the bake's wall time and, apart, its CPU direct-daylight pass.
 * `luxbox bench --daylight` runs this part alone and rewrites its own section of docs/benchmarks.md.
 */
import { glazingFrom } from '../../core/daylight/glazing';
import { CIE_CLEAR_SKY_TYPE, cieGeneralSky, cieOvercastSky, groundLuminance, type Sky } from '../../core/daylight/skies';
import { sunDirection } from '../../core/daylight/solarPosition';
import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import { normaliseRoom } from '../../core/room/normaliseRoom';
import type { RoomInput } from '../../core/room/roomInput';
import type { BakeScene } from '../../engines/bake/bakeScene';
import type { Baker } from '../../engines/bake/createBaker';
import { sunThroughWindow } from '../../reference/daylightDirect';
import { solveDaylightReference, type DaylightReferenceResult } from '../../reference/solveDaylightReference';
import type { BenchQuality } from './benchScenes';
import { compareDaylightWithReference } from './daylightComparison';
import type { MachineInfo } from './machineInfo';
import { relativeErrors } from './shapedRoomComparison';
import { daylightBox, daylightL } from './daylightBox';
import { percentCell, referenceSceneTable } from './referenceSceneTable';

export interface DaylightBenchScene {
  name: string;
  description: string;
  room: RoomInput;
  sky: Sky | null;
  sun: { direction: Vec3; normalIlluminance: number } | null;
}

const box = (): RoomInput => daylightBox();
const SUN = sunDirection(35, 200) as Vec3;

export const DAYLIGHT_SCENES: readonly DaylightBenchScene[] = [
  {
    name: 'box-overcast',
    description: 'box 5 × 4 × 2.8 m, 1.5 × 1.4 m double-glazed south window, CIE overcast sky 10 klx (a daylight-factor map)',
    room: box(),
    sky: cieOvercastSky(10_000),
    sun: null,
  },
  {
    name: 'box-sun',
    description: 'the same box, CIE clear sky (type 12) 15 klx and the sun at 35°, azimuth 200°, 70 klx normal (a sun patch on the floor and the west wall)',
    room: box(),
    sky: cieGeneralSky(CIE_CLEAR_SKY_TYPE, SUN, 15_000),
    sun: { direction: SUN, normalIlluminance: 70_000 },
  },
  {
    name: 'l-overcast',
    description: 'L 6 × 6 m (3 × 3 m notch), 2.6 m, a 2 × 1.8 m double-glazed window in the west wing partly hidden from the east wing by the inner corner; CIE overcast',
    room: daylightL(),
    sky: cieOvercastSky(10_000),
    sun: null,
  },
];

/** Coarse to fine texels at the default samples and bounces, and 4× the samples (to tell noise from bias). */
export const DAYLIGHT_LADDER: readonly BenchQuality[] = [
  { texelSize: 0.2, samples: 32, bounces: 4 },
  { texelSize: 0.1, samples: 64, bounces: 4 },
  { texelSize: 0.05, samples: 64, bounces: 4 },
  { texelSize: 0.1, samples: 256, bounces: 4 },
];

export interface DaylightBenchRow {
  scene: string;
  quality: BenchQuality;
  bakeMs: number;
  /** The CPU pass of the direct daylight (part of bakeMs). */
  directMs: number;
  points: number;
  nearEdge: number;
  /** Points within a texel of the sun patch's edge, left out (atSunPatchEdge). */
  sunEdge: number;
  directRms: number;
  directMax: number;
  totalRms: number;
  totalMax: number;
}

export interface DaylightBenchScenePart {
  scene: DaylightBenchScene;
  patches: number;
  referenceMs: number;
  rows: DaylightBenchRow[];
}

/** The bake scene of a bench room: its shape, grey box reflectances (the box's surfaces are the enclosure's sinks), the daylight with double glazing. */
function benchScene(s: DaylightBenchScene): BakeScene {
  const shape = normaliseRoom(s.room);
  const xs = shape.corners.map((c) => c[0]);
  const zs = shape.corners.map((c) => c[1]);
  const grey = { floor: 0.5, ceiling: 0.5, north: 0.5, south: 0.5, west: 0.5, east: 0.5 };
  const sunH = s.sun ? s.sun.normalIlluminance * Math.max(0, s.sun.direction[1]) : 0;
  return {
    room: { width: Math.max(...xs) - Math.min(...xs), height: shape.height, depth: Math.max(...zs) - Math.min(...zs), reflectance: grey, shape },
    luminaires: [],
    daylight: { sky: s.sky, sun: s.sun, groundLuminance: groundLuminance(s.sky?.horizontalIlluminance ?? 0, sunH, 0.2), glazing: new Map([[0, glazingFrom('double')]]) },
  };
}

/**
 * Comparison points about this far apart (m): the reference's exact direct daylight and final
 * gather cost about 0.2 s a point on the shared 2-core machine, so a 0.1 m grid made one rung of the
 * box take 25 minutes.
 */
const POINT_SPACING = 0.5;

/** Whether the sun reaches p through a window (the beam's own direction as the normal, so only where it leaves counts). */
function sunlit(reference: DaylightReferenceResult, p: Vec3): boolean {
  const sun = reference.daylight.sun;
  if (!sun) return false;
  return reference.daylight.windows.some((w) => sunThroughWindow(reference.daylight, w, p, [sun.direction[0], sun.direction[1], sun.direction[2]]) > 0);
}

/**
 * Points within a texel of the sun patch's edge (lit and unlit a texel apart along some axis): the
 * bake holds the patch's texel mean there, the reference a point value, so their ratio measures the
 * texel, not the bake's accuracy (the bake tests' rule, docs/daylight.md "The baker").
 */
function atSunPatchEdge(reference: DaylightReferenceResult, p: Vec3, texel: number): boolean {
  if (!reference.daylight.sun) return false;
  const lit = sunlit(reference, p);
  for (let a = 0; a < 3; a++) {
    for (const d of [-texel, texel]) {
      const q: Vec3 = [p[0], p[1], p[2]];
      q[a] += d;
      if (sunlit(reference, q) !== lit) return true;
    }
  }
  return false;
}

/** One rung: a warm-up bake, the timed bake, the comparison at about one point per POINT_SPACING². */
function measureRung(baker: Baker, s: DaylightBenchScene, scene: BakeScene, reference: DaylightReferenceResult, quality: BenchQuality): { row: DaylightBenchRow; compareMs: number } {
  baker.bake(scene, { ...quality, samples: 16, bounces: 1 });
  const started = performance.now();
  const { maps, report } = baker.bake(scene, quality);
  const bakeMs = performance.now() - started;
  const t1 = performance.now();
  const c = compareDaylightWithReference(scene, maps, reference, Math.max(1, Math.round(POINT_SPACING / quality.texelSize) ** 2));
  const points = c.points.filter((p) => !atSunPatchEdge(reference, p.point, quality.texelSize));
  const compareMs = performance.now() - t1;
  const peak = Math.max(...points.map((p) => p.reference.total));
  const direct = relativeErrors(points, 'direct', 0.01 * peak);
  const total = relativeErrors(points, 'total', 0.01 * peak);
  const row: DaylightBenchRow = {
    scene: s.name,
    quality,
    bakeMs,
    directMs: report.daylight?.directMs ?? 0,
    points: total.n,
    nearEdge: c.nearEdge,
    sunEdge: c.points.length - points.length,
    directRms: direct.rms,
    directMax: direct.max,
    totalRms: total.rms,
    totalMax: total.max,
  };
  return { row, compareMs };
}

/** The bench's daylit rooms; `ladder` (default DAYLIGHT_LADDER) is what each is baked at. */
export function runDaylightBench(baker: Baker, log: (line: string) => void, ladder: readonly BenchQuality[] = DAYLIGHT_LADDER): DaylightBenchScenePart[] {
  return DAYLIGHT_SCENES.map((s) => {
    const t0 = performance.now();
    const reference = solveDaylightReference(s.room, { sky: s.sky, sun: s.sun, groundReflectance: 0.2, glazing: { 0: glazingFrom('double') } }, { patchSize: 0.25 });
    let referenceMs = performance.now() - t0;
    log(`${s.name}: daylight reference ${reference.patches.length} patches, ${Math.round(referenceMs)} ms`);
    const scene = benchScene(s);
    const rows = ladder.map((quality) => {
      const { row, compareMs } = measureRung(baker, s, scene, reference, quality);
      referenceMs += compareMs;
      log(
        `  texel ${quality.texelSize} m, ${quality.samples} samples: bake ${Math.round(row.bakeMs)} ms (direct daylight ${Math.round(row.directMs)} ms); direct RMS ${(100 * row.directRms).toFixed(2)} %, total RMS ${(100 * row.totalRms).toFixed(2)} %, worst ${(100 * row.totalMax).toFixed(1)} % (${row.points} points, ${row.nearEdge} near an edge, ${row.sunEdge} at the sun patch's edge)`,
      );
      return row;
    });
    return { scene: s, patches: reference.patches.length, referenceMs, rows };
  });
}

/** The daylight rows as markdown (docs/benchmarks.md, "Daylight"). */
export function daylightTables(parts: readonly DaylightBenchScenePart[]): string {
  const lines = referenceSceneTable(parts);
  lines.push('| scene | texel | samples | bounces | bake time | of which direct daylight (CPU) | points (left out: near an edge, at the sun patch edge) | direct RMS / worst | total RMS | worst point |');
  lines.push('|---|---|---|---|---|---|---|---|---|---|');
  for (const p of parts) {
    for (const r of p.rows) {
      lines.push(
        `| ${r.scene} | ${r.quality.texelSize} m | ${r.quality.samples} | ${r.quality.bounces} | ${Math.round(r.bakeMs)} ms | ${Math.round(r.directMs)} ms | ${r.points} (${r.nearEdge}, ${r.sunEdge}) | ${percentCell(r.directRms)} / ${percentCell(r.directMax)} | ${percentCell(r.totalRms)} | ${percentCell(r.totalMax)} |`,
      );
    }
  }
  return lines.join('\n');
}

/** Markers of the section `luxbox bench --daylight` rewrites in docs/benchmarks.md. */
export const DAYLIGHT_MARKERS = ['<!-- luxbox bench daylight: start (generated) -->', '<!-- luxbox bench daylight: end -->'] as const;

/** The generated section: how it was measured, the machine, then the tables. */
export function daylightSection(parts: readonly DaylightBenchScenePart[], machine: MachineInfo): string {
  return `## Daylight: error against run time (\`luxbox bench --daylight\`)

Generated by \`xvfb-run -a node bin/luxbox.js bench --daylight\` (the full \`npm run bench\` runs the same
rooms and prints them in its tables); do not edit by hand. Each room is baked at every rung after an untimed
warm-up bake and compared with the independent daylight reference (src/reference/solveDaylightReference.ts,
0.25 m patches) at fully covered atlas texels of the room's surfaces, about one point per 0.5 m × 0.5 m,
points within 5 cm of an edge and within a texel of the sun patch's edge (where the bake holds the patch's
texel mean, the reference a point value) left out. Errors are relative, counted where the reference exceeds 1 % of the
room's peak; "direct daylight" is the baker's CPU pass of sky, ground and sun (docs/daylight.md), part of the bake time.

Machine: ${machine.cpuModel}, ${machine.cores} cores, ${machine.memoryGiB} GiB; ${machine.os}; Node ${machine.node};
GL ${machine.glVersion} (${machine.glRenderer}); ${machine.date.slice(0, 16).replace('T', ' ')} UTC.

${daylightTables(parts)}
`;
}
