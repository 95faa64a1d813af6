import { writeFileSync } from 'node:fs';
import { InputError } from '../inputError';
import { parseBakeCli } from '../node/bakeCliOptions';
import { ensureDisplay } from '../node/ensureDisplay';
import { renderImage } from '../node/renderImage';
import { loadRenderInput } from '../node/renderInput';
import { parseCameraSpec } from '../viewer/cameraPresets';

export const renderUsage =
  'render <config-or-scene.json> --out image.png [--camera eye|top|corner|<json>] [--width 960 --height 600] [--exposure EV] [--mode light|lux] [--samples N --bounces N --texel m]';

function intOption(name: string, value: string | undefined, fallback: number, min: number, max: number): number {
  if (value === undefined) return fallback;
  const n = Number(value);
  if (!Number.isInteger(n) || n < min || n > max) throw new InputError(`render: ${name} must be an integer in ${min}..${max}, got "${value}"`);
  return n;
}

/**
 * `luxbox render`: bake a configuration (scene-file JSON of the app) or a
 * lighting scene v1 and write a PNG as the 3D viewer shows it (docs/viewer.md).
 * --exposure is compensation in stops over the automatic exposure (0 = auto).
 */
export async function run(args: string[]): Promise<number> {
  const { positional, settings, options } = parseBakeCli('render', args, ['--out', '--camera', '--width', '--height', '--exposure', '--mode']);
  if (positional.length !== 1) throw new InputError(`render: expected one scene file, got ${positional.length} (usage: luxbox ${renderUsage})`);
  const out = options['--out'];
  if (!out) throw new InputError(`render: --out <image.png> is required (usage: luxbox ${renderUsage})`);
  const width = intOption('--width', options['--width'], 960, 16, 4096);
  const height = intOption('--height', options['--height'], 600, 16, 4096);
  const ev = options['--exposure'] === undefined ? 0 : Number(options['--exposure']);
  if (!Number.isFinite(ev) || Math.abs(ev) > 20) throw new InputError(`render: --exposure must be a number of stops in -20..20, got "${options['--exposure']}"`);
  const mode = options['--mode'] ?? 'light';
  if (mode !== 'light' && mode !== 'lux') throw new InputError(`render: --mode must be light or lux, got "${mode}"`);
  const input = loadRenderInput(positional[0]);
  const camera = parseCameraSpec(options['--camera'] ?? 'corner', input.scene.room);
  const reexit = ensureDisplay();
  if (reexit !== null) return reexit;
  const result = renderImage(input, { width, height, camera, exposureEv: ev, mode, settings });
  try {
    writeFileSync(out, result.png);
  } catch (error) {
    throw new InputError(`render: --out ${out}: cannot write (${(error as NodeJS.ErrnoException).code ?? 'error'})`);
  }
  const f = result.floor;
  process.stdout.write(
    `rendered ${positional[0]} → ${out} (${width}×${height}, bake ${Math.round(result.timings_ms.bake)} ms, render ${Math.round(result.timings_ms.render)} ms; floor Ē ${f.avg.toFixed(1)} lx, Emin ${f.min.toFixed(1)} lx, U0 ${f.u0.toFixed(2)})\n`,
  );
  return 0;
}
