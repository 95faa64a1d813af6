import { existsSync, mkdirSync, statSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { InputError } from '../../core/inputError';
import { oneLine } from '../../core/untrustedJson';
import { parseCameraSpec } from '../../engines/view/cameraPresets';
import { EV100_MAX, EV100_MIN } from '../../engines/view/photographicExposure';
import { DEFAULT_ADAPTATION, formatAdaptation, parseAdaptation, type AdaptationSetting } from '../../engines/view/adaptationSetting';
import { CCT_MAX_K, CCT_MIN_K } from '../../core/photometry/cct';
import { parseBakeCli } from '../node/bakeCliOptions';
import { batchFolderNames } from '../node/batchFolderNames';
import { prepareGl } from '../node/prepareGl';
import { takeRenderCameras } from '../node/renderCameras';
import { createRenderSession } from '../node/renderImage';
import { loadRenderInputAsync } from '../node/renderInput';
import { RENDER_SUMMARY_FORMAT, type RenderSummary, type RenderSummaryImage } from '../node/renderSummary';
import { ALLOW_FLAG, cliReadableFolders } from '../node/cliReadableFolders';

export const renderUsage =
  'render <config-or-scene.json> [more.json …] --out image.png|<dir>/ [--camera eye|top|corner|<json>|eye,top,… (repeatable)] [--cameras cameras.json] [--width 960 --height 600] [--ev EV100 | --exposure stops] [--adapt eye|none|camera:<K>] [--mode light|lux] [--glare on|off] [--samples N --bounces N --texel m] [--gl vulkan|glx|auto] [--allow <folder>]';

function intOption(name: string, value: string | undefined, fallback: number, min: number, max: number): number {
  if (value === undefined) return fallback;
  const n = Number(value);
  if (!Number.isInteger(n) || n < min || n > max) throw new InputError(`render: ${name} must be an integer in ${min}..${max}, got "${value}"`);
  return n;
}

/** `--ev` (absolute EV100) or `--exposure` (stops over the automatic exposure), not both. */
function exposureOptions(options: Record<string, string>): { ev100: number | null; compensation: number } {
  const ev = options['--ev'];
  const comp = options['--exposure'];
  if (ev !== undefined && comp !== undefined) throw new InputError('render: give either --ev (absolute EV100) or --exposure (stops over auto exposure), not both');
  if (ev !== undefined) {
    const n = Number(ev);
    if (ev.trim() === '' || !Number.isFinite(n) || n < EV100_MIN || n > EV100_MAX) throw new InputError(`render: --ev must be an EV100 in ${EV100_MIN}..${EV100_MAX}, got "${ev}"`);
    return { ev100: n, compensation: 0 };
  }
  const n = comp === undefined ? 0 : Number(comp);
  if (!Number.isFinite(n) || Math.abs(n) > 20) throw new InputError(`render: --exposure must be a number of stops in -20..20, got "${comp}"`);
  return { ev100: null, compensation: n };
}

/** `--adapt eye|none|camera:<K>` (chromaticAdaptation.ts); default eye. */
function adaptationOption(value: string | undefined): AdaptationSetting {
  if (value === undefined) return DEFAULT_ADAPTATION;
  const parsed = parseAdaptation(value);
  if (!parsed) throw new InputError(`render: --adapt must be eye, none or camera:<K> with K in ${CCT_MIN_K}..${CCT_MAX_K}, got "${value}"`);
  return parsed;
}

const errorLine = (error: unknown) => oneLine(error instanceof Error ? error.message : String(error));

/**
 * `luxbox render`: bake a configuration (scene-file JSON of the app) or a
 * lighting scene and write a PNG as the 3D viewer shows it (docs/viewer.md).
 * Exposure: automatic (with --exposure stops of compensation) or absolute with
 * --ev EV100 (photographicExposure.ts), the same for every image of a batch;
 * chromatic adaptation with --adapt (eye by default, camera:<K> white balance, none).
 *
 * One scene and one camera write the file --out. Several scenes or cameras (or
 * --out ending in / or naming a folder) are a batch: one process, one GL context
 * (programs compiled for the first scene only), one bake per scene drawn from
 * every camera, images <scene>-<camera>.png and summary.json in the folder.
 * A scene that fails (unreadable, invalid, bake error) is reported on stderr
 * and in the summary, the others still render; the exit code is then 1.
 */
export async function run(args: string[]): Promise<number> {
  const { cameras, rest } = takeRenderCameras(args);
  const { positional, settings, options } = parseBakeCli('render', rest, ['--out', '--width', '--height', '--exposure', '--ev', '--adapt', '--mode', '--glare', '--gl', ALLOW_FLAG]);
  if (positional.length === 0) throw new InputError(`render: expected a scene file (usage: luxbox ${renderUsage})`);
  const out = options['--out'];
  if (!out) throw new InputError(`render: --out <image.png> is required (usage: luxbox ${renderUsage})`);
  const width = intOption('--width', options['--width'], 960, 16, 4096);
  const height = intOption('--height', options['--height'], 600, 16, 4096);
  const { ev100, compensation } = exposureOptions(options);
  const adaptation = adaptationOption(options['--adapt']);
  const mode = options['--mode'] ?? 'light';
  if (mode !== 'light' && mode !== 'lux') throw new InputError(`render: --mode must be light or lux, got "${mode}"`);
  // Veiling glare round bright sources (docs/viewer.md, "Glare"): on by default in light mode, never in lux mode.
  const glareOption = options['--glare'] ?? 'on';
  if (glareOption !== 'on' && glareOption !== 'off') throw new InputError(`render: --glare must be on or off, got "${glareOption}"`);
  const glare = glareOption === 'on';
  const batch = positional.length > 1 || cameras.length > 1 || /[/\\]$/.test(out) || (existsSync(out) && statSync(out).isDirectory());
  // A single render keeps the old contract: bad input is one line on stderr before any GL work.
  const single = batch ? null : await loadRenderInputAsync(positional[0], { within: cliReadableFolders(positional[0], options[ALLOW_FLAG]) });
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
  const started = performance.now();
  const images: RenderSummaryImage[] = [];
  const failed: RenderSummary['failed'] = [];
  const linkedAfterScene: RenderSummary['programs_linked_after_scene'] = [];
  const session = createRenderSession(width, height);
  try {
    for (const [i, path] of positional.entries()) {
      let input;
      let results;
      try {
        const loaded = single ?? (await loadRenderInputAsync(path, { within: cliReadableFolders(path, options[ALLOW_FLAG]) }));
        input = loaded;
        const room = loaded.scene.room;
        // The eye preset frames this scene's light (frameTheLight.ts), as the browser's does.
        const poses = cameras.map((c) => parseCameraSpec(c.spec, room, { scene: loaded.bakeScene, aspect: width / height }));
        // One bake per scene, drawn from every camera.
        results = session.renderViews(input, { width, height, camera: poses[0], exposureEv: compensation, ev100, mode, adaptation, glare, settings }, poses);
      } catch (error) {
        if (!batch) throw error;
        failed.push({ file: path, error: errorLine(error) });
        process.stderr.write(`luxbox render: ${path}: ${errorLine(error)}\n`);
        continue;
      }
      linkedAfterScene.push(session.programsLinked());
      cameras.forEach((camera, k) => {
        const result = results[k];
        const image = `${sceneNames[i]}-${camera.name}.png`;
        const file = batch ? join(out, image) : out;
        try {
          writeFileSync(file, result.png);
        } catch (error) {
          throw new InputError(`render: --out ${file}: cannot write (${(error as NodeJS.ErrnoException).code ?? 'error'})`);
        }
        const f = result.floor;
        images.push({
          file: path,
          scene: sceneNames[i],
          camera: camera.name,
          image,
          ev100: result.ev100,
          exposure: result.exposure,
          floor: { avg: f.avg, min: f.min, u0: f.u0 },
          bake_ms: k === 0 ? result.timings_ms.bake : 0,
          render_ms: result.timings_ms.render,
        });
        process.stdout.write(
          `rendered ${path} → ${file} (${width}×${height}, EV100 ${result.ev100.toFixed(2)}${ev100 === null ? ' auto' : ''}, bake ${Math.round(result.timings_ms.bake)} ms, render ${Math.round(result.timings_ms.render)} ms; floor Ē ${f.avg.toFixed(1)} lx, Emin ${f.min.toFixed(1)} lx, U0 ${f.u0.toFixed(2)})\n`,
        );
      });
    }
    if (batch) {
      const summary: RenderSummary = {
        format: RENDER_SUMMARY_FORMAT,
        width,
        height,
        mode,
        exposure: ev100 === null ? { mode: 'auto', compensation } : { mode: 'fixed', ev100 },
        adaptation: formatAdaptation(adaptation),
        cameras: cameras.map((c) => ({ name: c.name, spec: c.spec })),
        programs_linked: session.programsLinked(),
        programs_linked_after_scene: linkedAfterScene,
        total_ms: performance.now() - started,
        images,
        failed,
      };
      writeFileSync(join(out, 'summary.json'), JSON.stringify(summary, null, 2) + '\n');
      process.stdout.write(
        `${images.length} images of ${positional.length - failed.length}/${positional.length} scenes × ${cameras.length} cameras in ${out} (summary.json; programs linked: ${session.programsLinked().baker} baker, ${session.programsLinked().view} view)\n`,
      );
    }
  } finally {
    session.destroy();
  }
  return failed.length > 0 ? 1 : 0;
}
