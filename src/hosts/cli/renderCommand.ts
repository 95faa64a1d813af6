import { existsSync, mkdirSync, statSync, writeFileSync } from 'node:fs';
import { basename, join } from 'node:path';
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
import { createRenderSession, type RenderResult, type RenderSession } from '../node/renderImage';
import { loadRenderInputAsync, type RenderInput } from '../node/renderInput';
import { DATE_FLAG, daylightTimeOptions, TIME_FLAG, type DaylightTime } from '../node/daylightTimeOverride';
import { renderInputAtTime } from '../node/renderDaylightTime';
import { RENDER_SUMMARY_FORMAT, type RenderSummary, type RenderSummaryImage } from '../node/renderSummary';
import { ALLOW_FLAG, cliReadableFolders } from '../node/cliReadableFolders';

export const renderUsage =
  'render <config-or-scene.json> [more.json …] --out image.png|<dir>/ [--camera eye|top|corner|<json>|eye,top,… (repeatable)] [--cameras cameras.json] [--width 960 --height 600] [--ev EV100 | --exposure stops] [--adapt eye|none|camera:<K>] [--mode light|lux] [--glare on|off] [--date YYYY-MM-DD] [--time HH:MM] [--samples N --bounces N --texel m] [--gl vulkan|glx|auto] [--allow <folder>]';

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

const renderHelp = `luxbox ${renderUsage}

  --out image.png | dir/   one scene and one camera write the file; several (or a folder) a batch: <scene>-<camera>.png and summary.json
  --camera, --cameras      eye (default), top, corner or a pose {"position": [x,y,z], "target": [x,y,z], "fov": deg}; repeatable, or a file
  --ev, --exposure         absolute EV100, or stops over the automatic exposure
  --adapt                  eye (default), none, camera:<K> white balance
  --mode, --glare          light (default) or lux false colour; veiling glare on (default) or off
  --date YYYY-MM-DD        daylight scenes (windows and a sky with a sun, docs/daylight.md): the sun on that day
  --time HH:MM[:SS]        ... and at that clock time of the sun's time zone (shop images at a time of day);
                           the rest of the scene's sky (place, zone, type) stays; a clear sky needs the sun up;
                           a configuration's daylight is moved as the Daylight panel moves it (HH:MM; its
                           city's summer time; after sunset the windows show the night sky)
  --samples, --bounces, --texel, --gl, --allow   as for bake`;

/** Everything `luxbox render` reads from its flags, checked before any scene is read. */
interface RenderCli {
  positional: string[];
  cameras: ReturnType<typeof takeRenderCameras>['cameras'];
  out: string;
  width: number;
  height: number;
  ev100: number | null;
  compensation: number;
  adaptation: AdaptationSetting;
  mode: 'light' | 'lux';
  glare: boolean;
  settings: ReturnType<typeof parseBakeCli>['settings'];
  when: DaylightTime | null;
  allow: string | undefined;
  gl: string | undefined;
  batch: boolean;
}

function parseRenderCli(args: string[]): RenderCli {
  const { cameras, rest } = takeRenderCameras(args);
  const { positional, settings, options } = parseBakeCli('render', rest, ['--out', '--width', '--height', '--exposure', '--ev', '--adapt', '--mode', '--glare', '--gl', ALLOW_FLAG, DATE_FLAG, TIME_FLAG]);
  if (positional.length === 0) throw new InputError(`render: expected a scene file (usage: luxbox ${renderUsage})`);
  const out = options['--out'];
  if (!out) throw new InputError(`render: --out <image.png> is required (usage: luxbox ${renderUsage})`);
  const mode = options['--mode'] ?? 'light';
  if (mode !== 'light' && mode !== 'lux') throw new InputError(`render: --mode must be light or lux, got "${mode}"`);
  // Veiling glare round bright sources (docs/viewer.md, "Glare"): on by default in light mode, never in lux mode.
  const glare = options['--glare'] ?? 'on';
  if (glare !== 'on' && glare !== 'off') throw new InputError(`render: --glare must be on or off, got "${glare}"`);
  return {
    positional,
    cameras,
    out,
    width: intOption('--width', options['--width'], 960, 16, 4096),
    height: intOption('--height', options['--height'], 600, 16, 4096),
    ...exposureOptions(options),
    adaptation: adaptationOption(options['--adapt']),
    mode,
    glare: glare === 'on',
    settings,
    when: daylightTimeOptions(options),
    allow: options[ALLOW_FLAG],
    gl: options['--gl'],
    batch: positional.length > 1 || cameras.length > 1 || /[/\\]$/.test(out) || (existsSync(out) && statSync(out).isDirectory()),
  };
}

/** A scene as `render` draws it: read, its sun moved by --date/--time. */
async function loadForRender(cli: RenderCli, path: string): Promise<RenderInput> {
  const input = await loadRenderInputAsync(path, { within: cliReadableFolders(path, cli.allow) });
  return renderInputAtTime(input, cli.when, basename(path));
}

/** What a batch collects while it renders. */
interface RenderRun {
  cli: RenderCli;
  session: RenderSession;
  sceneNames: string[];
  images: RenderSummaryImage[];
  failed: RenderSummary['failed'];
  linkedAfterScene: RenderSummary['programs_linked_after_scene'];
}

/** Write one camera's image of scene `i` and note it. */
function writeImage(run: RenderRun, i: number, camera: RenderCli['cameras'][number], result: RenderResult, first: boolean): void {
  const { cli } = run;
  const path = cli.positional[i];
  const image = `${run.sceneNames[i]}-${camera.name}.png`;
  const file = cli.batch ? join(cli.out, image) : cli.out;
  try {
    writeFileSync(file, result.png);
  } catch (error) {
    throw new InputError(`render: --out ${file}: cannot write (${(error as NodeJS.ErrnoException).code ?? 'error'})`);
  }
  const f = result.floor;
  run.images.push({
    file: path,
    scene: run.sceneNames[i],
    camera: camera.name,
    image,
    ev100: result.ev100,
    exposure: result.exposure,
    floor: { avg: f.avg, min: f.min, u0: f.u0 },
    bake_ms: first ? result.timings_ms.bake : 0,
    render_ms: result.timings_ms.render,
  });
  process.stdout.write(
    `rendered ${path} → ${file} (${cli.width}×${cli.height}, EV100 ${result.ev100.toFixed(2)}${cli.ev100 === null ? ' auto' : ''}, bake ${Math.round(result.timings_ms.bake)} ms, render ${Math.round(result.timings_ms.render)} ms; floor Ē ${f.avg.toFixed(1)} lx, Emin ${f.min.toFixed(1)} lx, U0 ${f.u0.toFixed(2)})\n`,
  );
}

/** Bake scene `i` once and draw it from every camera; in a batch a failing scene is noted and skipped. */
async function renderScene(run: RenderRun, i: number, single: RenderInput | null): Promise<void> {
  const { cli } = run;
  const path = cli.positional[i];
  let results: RenderResult[];
  try {
    const input = single ?? (await loadForRender(cli, path));
    // The eye preset frames this scene's light (frameTheLight.ts), as the browser's does.
    const poses = cli.cameras.map((c) => parseCameraSpec(c.spec, input.scene.room, { scene: input.bakeScene, aspect: cli.width / cli.height }));
    const options = { width: cli.width, height: cli.height, camera: poses[0], exposureEv: cli.compensation, ev100: cli.ev100, mode: cli.mode, adaptation: cli.adaptation, glare: cli.glare, settings: cli.settings };
    results = run.session.renderViews(input, options, poses);
  } catch (error) {
    if (!cli.batch) throw error;
    run.failed.push({ file: path, error: errorLine(error) });
    process.stderr.write(`luxbox render: ${path}: ${errorLine(error)}\n`);
    return;
  }
  run.linkedAfterScene.push(run.session.programsLinked());
  cli.cameras.forEach((camera, k) => writeImage(run, i, camera, results[k], k === 0));
}

function writeSummary(run: RenderRun, started: number): void {
  const { cli, session } = run;
  const summary: RenderSummary = {
    format: RENDER_SUMMARY_FORMAT,
    width: cli.width,
    height: cli.height,
    mode: cli.mode,
    exposure: cli.ev100 === null ? { mode: 'auto', compensation: cli.compensation } : { mode: 'fixed', ev100: cli.ev100 },
    adaptation: formatAdaptation(cli.adaptation),
    cameras: cli.cameras.map((c) => ({ name: c.name, spec: c.spec })),
    programs_linked: session.programsLinked(),
    programs_linked_after_scene: run.linkedAfterScene,
    total_ms: performance.now() - started,
    images: run.images,
    failed: run.failed,
  };
  writeFileSync(join(cli.out, 'summary.json'), JSON.stringify(summary, null, 2) + '\n');
  const n = cli.positional.length;
  process.stdout.write(
    `${run.images.length} images of ${n - run.failed.length}/${n} scenes × ${cli.cameras.length} cameras in ${cli.out} (summary.json; programs linked: ${session.programsLinked().baker} baker, ${session.programsLinked().view} view)\n`,
  );
}

/**
 * `luxbox render`: bake a configuration (scene-file JSON of the app) or a
 * lighting scene and write a PNG as the 3D viewer shows it (docs/viewer.md).
 * Exposure: automatic (with --exposure stops of compensation) or absolute with
 * --ev EV100 (photographicExposure.ts), the same for every image of a batch;
 * chromatic adaptation with --adapt (eye by default, camera:<K> white balance, none).
 * Daylight scenes with their sky and sun; --date and --time move the sun (docs/daylight.md).
 *
 * One scene and one camera write the file --out. Several scenes or cameras (or
 * --out ending in / or naming a folder) are a batch: one process, one GL context
 * (programs compiled for the first scene only), one bake per scene drawn from
 * every camera, images <scene>-<camera>.png and summary.json in the folder.
 * A scene that fails (unreadable, invalid, bake error) is reported on stderr
 * and in the summary, the others still render; the exit code is then 1.
 */
export async function run(args: string[]): Promise<number> {
  if (args.includes('--help') || args.includes('-h')) {
    process.stdout.write(renderHelp + '\n');
    return 0;
  }
  const cli = parseRenderCli(args);
  // A single render keeps the old contract: bad input is one line on stderr before any GL work.
  const single = cli.batch ? null : await loadForRender(cli, cli.positional[0]);
  const { exit } = prepareGl(cli.gl);
  if (exit !== null) return exit;
  if (cli.batch) {
    try {
      mkdirSync(cli.out, { recursive: true });
    } catch (error) {
      throw new InputError(`render: --out ${cli.out}: cannot create the folder (${(error as NodeJS.ErrnoException).code ?? 'error'})`);
    }
  }
  const started = performance.now();
  const session = createRenderSession(cli.width, cli.height);
  const state: RenderRun = { cli, session, sceneNames: batchFolderNames(cli.positional), images: [], failed: [], linkedAfterScene: [] };
  try {
    for (let i = 0; i < cli.positional.length; i++) await renderScene(state, i, single);
    if (cli.batch) writeSummary(state, started);
  } finally {
    session.destroy();
  }
  return state.failed.length > 0 ? 1 : 0;
}
