import { mkdirSync } from 'node:fs';
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { InputError } from '../inputError';
import { SURFACE_NAMES } from '../model/lightingScene';
import { luxOf } from '../bake/bakedMaps';
import { parseBakeCli } from '../node/bakeCliOptions';
import { bakeSceneFile } from '../node/bakeSceneFile';
import { reportJson } from '../node/bakeSummary';
import { ensureDisplay } from '../node/ensureDisplay';
import { falseColorPng } from '../node/falseColorPng';
import { writePfm } from '../node/writePfm';

export const bakeUsage = 'bake <scene.json> --out <dir> [--samples N --bounces N --texel m --blur texels --seed N --no-tail]';

/**
 * `luxbox bake`: writes report.json, per surface <name>.direct/.indirect/.total.pfm
 * (RGB lux) and <name>.png (false colour of total lux, one scale for all six).
 */
export async function run(args: string[]): Promise<number> {
  const { positional, settings, options } = parseBakeCli('bake', args, ['--out']);
  if (positional.length !== 1) throw new InputError(`expected one scene file, got ${positional.length} (usage: luxbox ${bakeUsage})`);
  const out = options['--out'];
  if (!out) throw new InputError(`--out <dir> is required (usage: luxbox ${bakeUsage})`);
  const reexit = ensureDisplay();
  if (reexit !== null) return reexit;

  const { maps, report } = bakeSceneFile(positional[0], settings);
  const started = performance.now();
  try {
    mkdirSync(out, { recursive: true });
  } catch (error) {
    throw new InputError(`--out ${out}: cannot create the folder (${(error as NodeJS.ErrnoException).code ?? 'error'})`);
  }
  // One colour scale for all surfaces: the 99.5th percentile of total lux, so a
  // lamp touching a wall does not turn every other surface dark blue.
  const all = SURFACE_NAMES.flatMap((n) => Array.from(luxOf(maps[n].total))).sort((a, b) => a - b);
  const scaleMax = all.length ? all[Math.min(all.length - 1, Math.floor(all.length * 0.995))] : 1;
  for (const name of SURFACE_NAMES) {
    const m = maps[name];
    const { width, height } = m.layout;
    writePfm(join(out, `${name}.direct.pfm`), width, height, m.direct);
    writePfm(join(out, `${name}.indirect.pfm`), width, height, m.indirect);
    writePfm(join(out, `${name}.total.pfm`), width, height, m.total);
    writeFileSync(join(out, `${name}.png`), falseColorPng(luxOf(m.total), width, height, scaleMax));
  }
  const json = reportJson(positional[0], maps, report);
  json.timings_ms = { ...json.timings_ms, write: performance.now() - started } as typeof json.timings_ms;
  writeFileSync(join(out, 'report.json'), JSON.stringify({ ...json, png_scale_max_lux: scaleMax }, null, 2) + '\n');
  process.stdout.write(`baked ${positional[0]} → ${out} (${report.totalTexels} texels, ${report.bouncesComputed} bounces, ${Math.round(report.timings_ms.total)} ms)\n`);
  return 0;
}
