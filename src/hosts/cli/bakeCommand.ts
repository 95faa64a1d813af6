import { join } from 'node:path';
import { InputError } from '../../core/inputError';
import { parseBakeCli } from '../node/bakeCliOptions';
import { batchFolderNames } from '../node/batchFolderNames';
import { createSceneBaker } from '../node/bakeSceneFile';
import { loadLightingSceneFileAsync, type LoadedLightingScene } from '../node/loadLightingSceneFile';
import { prepareGl } from '../node/prepareGl';
import { sceneWarnings } from '../node/sceneWarnings';
import { shapedRoomReport } from '../node/bakeSummary';
import { daylightReport } from '../node/daylightReport';
import { writeBakeOutput, type SceneObjectsOutput } from '../node/writeBakeOutput';
import { resolveBakeSettings } from '../../engines/bake/bakeSettings';
import { ALLOW_FLAG, cliReadableFolders } from '../node/cliReadableFolders';

export const bakeUsage = 'bake <scene.json> [more.json …] --out <dir> [--samples N --bounces N --texel m --blur texels --seed N --no-tail --gl vulkan|glx|auto --allow <folder>]';

/** The scene's objects with their ids, mesh paths, triangle counts and units, for report.json and objects.json. */
function objectsOutput(loaded: LoadedLightingScene): SceneObjectsOutput {
  const objects = loaded.scene.objects ?? [];
  return {
    objects,
    ids: (loaded.bakeScene.objects ?? []).map((o) => o.id),
    sources: objects.map((o) => {
      const imported = loaded.meshes.get(o.mesh);
      return { mesh: o.mesh, triangles: imported?.triangleCount ?? 0, units: imported?.units ?? 'm', ...(imported ? { orientation: imported.orientation } : {}) };
    }),
  };
}

/**
 * `luxbox bake`: one scene writes its files into --out (docs/scene-format.md);
 * several scenes are baked in one process on one GL context (each shader
 * compiled once for the whole batch), each into --out/<scene name>/.
 * Every scene file is read and checked before the first bake starts.
 */
export async function run(args: string[]): Promise<number> {
  const { positional, settings: given, options } = parseBakeCli('bake', args, ['--out', '--gl', ALLOW_FLAG]);
  if (positional.length === 0) throw new InputError(`expected a scene file (usage: luxbox ${bakeUsage})`);
  const out = options['--out'];
  if (!out) throw new InputError(`--out <dir> is required (usage: luxbox ${bakeUsage})`);
  // Checked before any scene file is read, and passed on resolved (the baker does not check again).
  const settings = resolveBakeSettings(given);
  const { exit, backend } = prepareGl(options['--gl']);
  if (exit !== null) return exit;

  const loaded: LoadedLightingScene[] = [];
  for (const p of positional) loaded.push(await loadLightingSceneFileAsync(p, { within: cliReadableFolders(p, options[ALLOW_FLAG]) }));
  // Suspicious-but-readable photometry (docs/photometry.md, "Warnings"): in each
  // report.json, and once per line on stderr (nothing on stderr when there are none).
  const warnings = loaded.map((scene, i) => sceneWarnings(scene, positional[i]));
  for (const line of new Set(warnings.flat())) process.stderr.write(`luxbox bake: warning: ${line}\n`);
  const folders = positional.length === 1 ? [out] : batchFolderNames(positional).map((name) => join(out, name));
  const started = performance.now();
  const sceneBaker = createSceneBaker();
  try {
    loaded.forEach((scene, i) => {
      const before = sceneBaker.programCount();
      const { maps, report } = sceneBaker.bake(scene, settings);
      const compiled = sceneBaker.programCount() - before;
      // Windows with a sky: the daylight numbers (daylightReport.ts; its further bakes run after the scene's own is counted).
      const daylight = daylightReport(scene.scene, scene.bakeScene, maps, report, settings, (s) => sceneBaker.bakeScene(s, settings));
      writeBakeOutput(
        folders[i],
        positional[i],
        maps,
        report,
        {
          gl: backend,
          batch: { index: i, of: positional.length, programsCompiled: compiled },
          warnings: warnings[i],
          // A room of any shape: its floor area and surfaces from the geometry (issue 29).
          ...(scene.scene.room.shape ? { room: shapedRoomReport(scene.scene.room.shape) } : {}),
          ...(daylight ? { daylight } : {}),
        },
        objectsOutput(scene),
      );
      // Covered atlas texels count too: a room of any shape is all atlas (its six box surfaces are one-texel sinks).
      const texels = report.totalTexels + (report.objects ?? []).reduce((n, o) => n + o.texels, 0);
      process.stdout.write(`baked ${positional[i]} → ${folders[i]} (${texels} texels, ${report.bouncesComputed} bounces, ${Math.round(report.timings_ms.total)} ms, ${compiled} programs compiled, gl ${backend})\n`);
    });
  } finally {
    sceneBaker.destroy();
  }
  if (positional.length > 1) {
    process.stdout.write(`batch: ${positional.length} scenes in ${Math.round(performance.now() - started)} ms, ${sceneBaker.programCount()} programs compiled in all\n`);
  }
  return 0;
}
