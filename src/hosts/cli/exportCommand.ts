import { basename } from 'node:path';
import { InputError } from '../../core/inputError';
import { exportRadiance } from '../../engines/radiance/exportRadiance';
import { parseBakeCli } from '../node/bakeCliOptions';
import { writeExportFiles } from '../node/radianceTools';
import { loadRenderInputAsync } from '../node/renderInput';
import { ALLOW_FLAG, cliReadableFolders } from '../node/cliReadableFolders';

export const exportUsage = 'export radiance <config-or-scene.json> --out <dir> [--near-field split|point] [--allow <folder>]';

/**
 * `luxbox export radiance`: a self-contained Radiance folder for a configuration (the app's
 * scene file) or a lighting scene (docs/radiance.md). No GL: it writes text only.
 */
export async function run(args: string[]): Promise<number> {
  const [format, ...rest] = args;
  if (format !== 'radiance') throw new InputError(`unknown format ${format === undefined ? '(none)' : `"${format}"`} (usage: luxbox ${exportUsage})`);
  const { positional, settings, options } = parseBakeCli('radiance', rest, ['--out', ALLOW_FLAG]);
  if (positional.length !== 1) throw new InputError(`radiance: expected one scene file (usage: luxbox ${exportUsage})`);
  const out = options['--out'];
  if (!out) throw new InputError(`radiance: --out <dir> is required (usage: luxbox ${exportUsage})`);
  const input = await loadRenderInputAsync(positional[0], { within: cliReadableFolders(positional[0], options[ALLOW_FLAG]) });
  const title = basename(positional[0]).replace(/\.json$/i, '');
  const files = exportRadiance(input.bakeScene, settings, title);
  writeExportFiles(out, files);
  process.stdout.write(`${out}: ${files.length} files (scene.rad, render.sh, README.md, ${files.filter((f) => f.path.endsWith('.dat')).length} distributions)\n`);
  return 0;
}
