import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { InputError } from '../../core/inputError';
import { parseBakeCli } from '../node/bakeCliOptions';
import { batchFolderNames } from '../node/batchFolderNames';
import { prepareGl } from '../node/prepareGl';
import { createRenderSession } from '../node/renderImage';
import { loadRenderInput } from '../node/renderInput';
import { parseCameraSpec } from '../../engines/view/cameraPresets';

export const renderUsage =
  'render <config-or-scene.json> [more.json …] --out image.png|<dir> [--camera eye|top|corner|<json>|eye,top,…] [--width 960 --height 600] [--exposure EV] [--mode light|lux] [--samples N --bounces N --texel m] [--gl vulkan|glx|auto]';

function intOption(name: string, value: string | undefined, fallback: number, min: number, max: number): number {
  if (value === undefined) return fallback;
  const n = Number(value);
  if (!Number.isInteger(n) || n < min || n > max) throw new InputError(`render: ${name} must be an integer in ${min}..${max}, got "${value}"`);
  return n;
}

/** `--camera`: one JSON pose, or one or more comma-separated names/presets. */
function cameraSpecs(spec: string): { name: string; spec: string }[] {
  const trimmed = spec.trim();
  if (trimmed.startsWith('{')) return [{ name: 'camera', spec: trimmed }];
  const names = trimmed.split(',').map((s) => s.trim()).filter(Boolean);
  if (names.length === 0) throw new InputError('render: --camera needs a preset name or JSON');
  return [...new Set(names)].map((name) => ({ name, spec: name }));
}

/**
 * `luxbox render`: bake a configuration (scene-file JSON of the app) or a
 * lighting scene and write a PNG as the 3D viewer shows it (docs/viewer.md).
 * --exposure is compensation in stops over the automatic exposure (0 = auto).
 * One scene and one camera write the file --out; several scenes or cameras
 * render in one process on one GL context (shaders compiled once) into the
 * folder --out as <scene>-<camera>.png, one bake per scene.
 */
export async function run(args: string[]): Promise<number> {
  const { positional, settings, options } = parseBakeCli('render', args, ['--out', '--camera', '--width', '--height', '--exposure', '--mode', '--gl']);
  if (positional.length === 0) throw new InputError(`render: expected a scene file (usage: luxbox ${renderUsage})`);
  const out = options['--out'];
  if (!out) throw new InputError(`render: --out <image.png> is required (usage: luxbox ${renderUsage})`);
  const width = intOption('--width', options['--width'], 960, 16, 4096);
  const height = intOption('--height', options['--height'], 600, 16, 4096);
  const ev = options['--exposure'] === undefined ? 0 : Number(options['--exposure']);
  if (!Number.isFinite(ev) || Math.abs(ev) > 20) throw new InputError(`render: --exposure must be a number of stops in -20..20, got "${options['--exposure']}"`);
  const mode = options['--mode'] ?? 'light';
  if (mode !== 'light' && mode !== 'lux') throw new InputError(`render: --mode must be light or lux, got "${mode}"`);
  const inputs = positional.map((p) => loadRenderInput(p));
  const cameras = cameraSpecs(options['--camera'] ?? 'corner');
  // Check every camera against every room before the first bake.
  const poses = inputs.map((input) => cameras.map((c) => parseCameraSpec(c.spec, input.scene.room)));
  const batch = inputs.length > 1 || cameras.length > 1;
  const sceneNames = batchFolderNames(positional);
  const { exit } = prepareGl(options['--gl']);
  if (exit !== null) return exit;
  if (batch) {
    try {
      mkdirSync(out, { recursive: true });
    } catch (error) {
      throw new InputError(`render: --out ${out}: cannot create the folder (${(error as NodeJS.ErrnoException).code ?? 'error'})`);
    }
  }
  const session = createRenderSession(width, height);
  try {
    inputs.forEach((input, i) => {
      // One bake per scene, drawn from every camera.
      const results = session.renderViews(input, { width, height, camera: poses[i][0], exposureEv: ev, mode, settings }, poses[i]);
      cameras.forEach((camera, k) => {
        const result = results[k];
        const file = batch ? join(out, `${sceneNames[i]}-${camera.name}.png`) : out;
        try {
          writeFileSync(file, result.png);
        } catch (error) {
          throw new InputError(`render: --out ${file}: cannot write (${(error as NodeJS.ErrnoException).code ?? 'error'})`);
        }
        const f = result.floor;
        process.stdout.write(
          `rendered ${positional[i]} → ${file} (${width}×${height}, bake ${Math.round(result.timings_ms.bake)} ms, render ${Math.round(result.timings_ms.render)} ms; floor Ē ${f.avg.toFixed(1)} lx, Emin ${f.min.toFixed(1)} lx, U0 ${f.u0.toFixed(2)})\n`,
        );
      });
    });
  } finally {
    session.destroy();
  }
  return 0;
}
