import { readFileSync } from 'node:fs';
import { basename } from 'node:path';
import { z } from 'zod';
import { InputError } from '../../core/inputError';
import type { Vec3 } from '../../core/model/lightingScene';
import { nearestSurface } from '../../engines/bake/nearestSurface';
import { probeScene } from '../../engines/bake/probeMaps';
import { parseBakeCli } from '../node/bakeCliOptions';
import { bakeLoadedScene } from '../node/bakeSceneFile';
import { resolveBakeSettings } from '../../engines/bake/bakeSettings';
import { prepareGl } from '../node/prepareGl';
import { loadLightingSceneFile, parseJsonText } from '../node/loadLightingSceneFile';
import { describeIssues } from '../../core/model/untrustedJson';

export const probeUsage = 'probe <scene.json> <points.json> [--samples N --bounces N --texel m --gl vulkan|glx|auto]';

/** Probe points must lie on a surface, within this distance (metres). */
export const PROBE_TOLERANCE = 0.01;

// Strict (issue 18): an unknown or misspelt field is refused, not ignored.
const pointsSchema = z.strictObject({
  points: z.array(z.tuple([z.number(), z.number(), z.number()]).refine((p) => p.every(Number.isFinite), 'must be finite numbers')),
});

/** `luxbox probe`: bake, then print {total, direct, indirect} lux at the given surface points. */
export async function run(args: string[]): Promise<number> {
  const { positional, settings, options } = parseBakeCli('probe', args, ['--gl']);
  if (positional.length !== 2) throw new InputError(`expected a scene file and a points file (usage: luxbox ${probeUsage})`);
  const [scenePath, pointsPath] = positional;
  const source = basename(pointsPath);
  let text: string;
  try {
    text = readFileSync(pointsPath, 'utf8');
  } catch (error) {
    throw new InputError(`${source}: cannot read ${pointsPath} (${(error as NodeJS.ErrnoException).code ?? 'error'})`);
  }
  const parsed = pointsSchema.safeParse(parseJsonText(text, source));
  if (!parsed.success) {
    const issue = parsed.error.issues[0];
    // `points.json: pointz: unknown field 'pointz' (did you mean 'points'?)`, before any "points is missing".
    if (parsed.error.issues.some((i) => i.code === 'unrecognized_keys')) throw new InputError(`${source}: ${describeIssues(parsed.error.issues, ['points'])}`);
    const path = issue.path.map((k) => (typeof k === 'number' ? `[${k}]` : `.${String(k)}`)).join('').replace(/^\./, '');
    throw new InputError(`${source}: ${path ? `${path}: ` : ''}${issue.path.length ? issue.message : 'expected { "points": [[x, y, z], ...] }'}`);
  }
  resolveBakeSettings(settings);
  const loaded = loadLightingSceneFile(scenePath);
  const room = loaded.scene.room;
  const points = parsed.data.points as Vec3[];
  points.forEach((p, i) => {
    const { surface, distance } = nearestSurface(room, p);
    if (distance > PROBE_TOLERANCE) {
      throw new InputError(
        `${source}: points[${i}]: [${p.join(', ')}] is ${distance.toPrecision(3)} m from the nearest surface (${surface}); probe points must lie within ${PROBE_TOLERANCE} m of a surface`,
      );
    }
  });
  const { exit } = prepareGl(options['--gl']);
  if (exit !== null) return exit;
  const { maps } = bakeLoadedScene(loaded, settings);
  // Direct light exactly at each point (CPU), indirect from the maps.
  const values = probeScene(loaded.bakeScene, maps, settings, points);
  const result = { total: values.map((v) => v.total), direct: values.map((v) => v.direct), indirect: values.map((v) => v.indirect) };
  process.stdout.write(JSON.stringify(result) + '\n');
  return 0;
}
