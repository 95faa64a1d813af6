import { basename } from 'node:path';
import { z } from 'zod/mini';
import { InputError } from '../../core/inputError';
import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import { nearestSurface } from '../../engines/bake/nearestSurface';
import { parseBakeCli } from '../node/bakeCliOptions';
import { createProbe } from '../node/createProbe';
import { bakeLoadedScene, createSceneBaker } from '../node/bakeSceneFile';
import { resolveBakeSettings } from '../../engines/bake/bakeSettings';
import { prepareGl } from '../node/prepareGl';
import { loadLightingSceneFileAsync, parseJsonText } from '../node/loadLightingSceneFile';
import { describeIssues } from '../../core/zodIssues';
import { ALLOW_FLAG, cliReadableFolders } from '../node/cliReadableFolders';
import { INPUT_LIMITS } from '../../core/untrustedJson';
import { readRegularFile } from '../node/readRegularFile';
import { safeParseInEnglish } from '../../core/zodEnglish';
import { checkShapedProbePoints, probeShapedRoom, type ShapedProbePoint, type ShapedProbeResult } from '../node/createShapedRoomProbe';
import { DATE_FLAG, daylightTimeOptions, TIME_FLAG, withDaylightTime } from '../node/daylightTimeOverride';
import { daylightBakeInput } from '../../engines/bake/daylight/daylightBakeInput';
import { encloseShapedRoom } from '../../engines/bake/shapedRoom/encloseShapedRoom';
import type { BakeScene } from '../../engines/bake/bakeScene';

export const probeUsage =
  'probe <scene.json> <points.json> [--samples N --bounces N --texel m --gl vulkan|glx|auto --allow <folder>] [--date YYYY-MM-DD --time HH:MM (daylight: the sun at another day or time)] (points [x, y, z] on a surface or [x, y, z, nx, ny, nz])';

/** Probe points must lie on a surface (or, with a normal, inside the room), within this distance (metres). */
export const PROBE_TOLERANCE = 0.01;

const finiteNumbers = (p: number[]) => p.every(Number.isFinite);
// Strict (issue 18): an unknown or misspelt field is refused, not ignored.
const pointsSchema = z.strictObject({
  points: z.array(
    z
      .union([z.tuple([z.number(), z.number(), z.number()]), z.tuple([z.number(), z.number(), z.number(), z.number(), z.number(), z.number()])], {
        error: 'must be [x, y, z] (a point on a surface) or [x, y, z, nx, ny, nz] (a point and a normal)',
      })
      .check(z.refine(finiteNumbers, 'must be finite numbers')),
  ),
});

const AXES = ['x', 'y', 'z'];

/**
 * `luxbox probe`: bake, then print {total, direct, indirect} lux at the given points: `[x, y, z]`
 * on a room surface, or `[x, y, z, nx, ny, nz]` on the plane with that normal anywhere in the room
 * (docs/scene-format.md, "Probe points").
 */
export async function run(args: string[]): Promise<number> {
  const { positional, settings, options } = parseBakeCli('probe', args, ['--gl', ALLOW_FLAG, DATE_FLAG, TIME_FLAG]);
  if (positional.length !== 2) throw new InputError(`expected a scene file and a points file (usage: luxbox ${probeUsage})`);
  const [scenePath, pointsPath] = positional;
  const source = basename(pointsPath);
  let text: string;
  try {
    text = new TextDecoder('utf-8').decode(readRegularFile(pointsPath, { maxBytes: INPUT_LIMITS.maxTextLength }));
  } catch (error) {
    if (!(error instanceof InputError)) throw error;
    throw new InputError(`${source}: cannot read ${pointsPath} (${error.message})`);
  }
  const parsed = safeParseInEnglish(pointsSchema, parseJsonText(text, source));
  if (!parsed.success) {
    const issue = parsed.error.issues[0];
    // `points.json: pointz: unknown field 'pointz' (did you mean 'points'?)`, before any "points is missing".
    if (parsed.error.issues.some((i) => i.code === 'unrecognized_keys')) throw new InputError(`${source}: ${describeIssues(parsed.error.issues, ['points'])}`);
    const path = issue.path
      .map((k) => (typeof k === 'number' ? `[${k}]` : `.${String(k)}`))
      .join('')
      .replace(/^\./, '');
    throw new InputError(`${source}: ${path ? `${path}: ` : ''}${issue.path.length ? issue.message : 'expected { "points": [[x, y, z], ...] }'}`);
  }
  // Checked before the scene file is read, and passed on resolved to the bake and the probe.
  const resolved = resolveBakeSettings(settings);
  const loaded = withDaylightTime(await loadLightingSceneFileAsync(scenePath, { within: cliReadableFolders(scenePath, options[ALLOW_FLAG]) }), daylightTimeOptions(options), 'probe', basename(scenePath));
  const room = loaded.scene.room;
  if (room.shape) return probeShapedScene(loaded, room.shape, parsed.data.points, resolved, options['--gl'], source);
  const dims = [room.width, room.height, room.depth];
  const points = parsed.data.points.map((p, i): { point: Vec3; normal?: Vec3 } => {
    const point: Vec3 = [p[0], p[1], p[2]];
    if (p.length === 3) {
      const { surface, distance } = nearestSurface(room, point);
      if (distance > PROBE_TOLERANCE) {
        throw new InputError(`${source}: points[${i}]: [${p.join(', ')}] is ${distance.toPrecision(3)} m from the nearest surface (${surface}); probe points must lie within ${PROBE_TOLERANCE} m of a surface`);
      }
      return { point };
    }
    for (let a = 0; a < 3; a++) {
      if (point[a] < -PROBE_TOLERANCE || point[a] > dims[a] + PROBE_TOLERANCE) {
        throw new InputError(`${source}: points[${i}]: ${AXES[a]} = ${point[a]} m is outside the room (0..${dims[a]} m)`);
      }
    }
    const length = Math.hypot(p[3], p[4], p[5]);
    if (!(length > 1e-9)) throw new InputError(`${source}: points[${i}]: the normal [${p.slice(3).join(', ')}] has no direction`);
    return { point, normal: [p[3] / length, p[4] / length, p[5] / length] };
  });
  const { exit } = prepareGl(options['--gl']);
  if (exit !== null) return exit;
  const { maps } = bakeLoadedScene(loaded, resolved);
  // Direct light exactly at each point (CPU, objects occluding); indirect from the maps, or gathered from them at a point with a normal.
  const probe = createProbe(loaded.bakeScene, maps, resolved);
  const values = points.map(({ point, normal }) => (normal ? probe.atPlane(point, normal) : probe.atSurface(point)));
  process.stdout.write(JSON.stringify(columns(values)) + '\n');
  return 0;
}

/**
 * `luxbox probe` in a room of any shape (lighting scene version 3): a point [x, y, z] must lie on a
 * surface of roomSurfaces (within PROBE_TOLERANCE, not in an opening), a point with a normal inside
 * the room (outline, floor to ceiling and slopes); checked before the bake. Then the room is baked
 * (its surfaces are atlas charts) and probed there (createShapedRoomProbe.ts).
 */
function probeShapedScene(
  loaded: Awaited<ReturnType<typeof loadLightingSceneFileAsync>>,
  shape: NonNullable<typeof loaded.scene.room.shape>,
  raw: readonly number[][],
  resolved: ReturnType<typeof resolveBakeSettings>,
  gl: string | undefined,
  source: string,
): number {
  const points = raw.map((p): ShapedProbePoint => {
    const point: Vec3 = [p[0], p[1], p[2]];
    if (p.length === 3) return { point };
    const length = Math.hypot(p[3], p[4], p[5]);
    return { point, normal: length > 1e-9 ? [p[3] / length, p[4] / length, p[5] / length] : [0, 0, 0] };
  });
  points.forEach(({ normal }, i) => {
    if (normal && normal.every((c) => c === 0)) throw new InputError(`${source}: points[${i}]: the normal [${raw[i].slice(3).join(', ')}] has no direction`);
  });
  checkShapedProbePoints(shape, points, PROBE_TOLERANCE, source);
  const { exit } = prepareGl(gl);
  if (exit !== null) return exit;
  const sceneBaker = createSceneBaker();
  try {
    const probeScene = (scene: BakeScene): ShapedProbeResult[] => probeShapedRoom(scene, sceneBaker.bakeScene(scene, resolved).maps, resolved, points, PROBE_TOLERANCE);
    const values = probeScene(loaded.bakeScene);
    const result: Record<string, unknown> = columns(values);
    // Windows with a sky or a sun: the daylight alone too (the scene baked again without its luminaires, when it has any).
    if (daylightBakeInput(loaded.bakeScene, encloseShapedRoom(loaded.bakeScene))) {
      result.daylight = columns(loaded.bakeScene.luminaires.length === 0 ? values : probeScene({ ...loaded.bakeScene, luminaires: [] }));
    }
    process.stdout.write(JSON.stringify(result) + '\n');
  } finally {
    sceneBaker.destroy();
  }
  return 0;
}

/** Per-point results as the output's columns. */
function columns(values: readonly { total: number; direct: number; indirect: number }[]): { total: number[]; direct: number[]; indirect: number[] } {
  return { total: values.map((v) => v.total), direct: values.map((v) => v.direct), indirect: values.map((v) => v.indirect) };
}
