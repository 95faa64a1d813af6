import { mkdir, writeFile } from 'node:fs/promises';
import { join } from 'node:path';
import type { EngineDriver, EngineName } from './engineDriver';

/** Floor statistics in lux as the app reports them (window.luxbox.view3d().floor). */
export interface FloorStats {
  avg: number;
  min: number;
  max: number;
  u0: number;
}

/** What one engine did with the scenario: the numbers compared across engines and the findings for docs/browsers.md. */
export interface EngineReport {
  engine: EngineName;
  userAgent: string;
  language: string;
  /** The page's default Intl locale (what `new Intl.NumberFormat()` resolves to). */
  intlLocale: string;
  /** UNMASKED_RENDERER_WEBGL where the engine exposes it, else RENDERER; the supported WebGL2 extensions. */
  webgl: { renderer: string; extensions: string[] };
  viewport: [number, number];
  /**
   * The header title's computed font stack, its rendered width (px), and the width the same text
   * would have in candidate fonts (canvas measureText): which face the engine really picked.
   */
  font: { family: string; titleWidth: number; candidates: Record<string, number> };
  /** The header's total price after placing the L-corner preset, as shown. */
  price: string;
  /** The room the form produced from the typed "5", "4", "2,8". */
  room: { width: number; depth: number; height: number };
  baked: FloorStats;
  dimmed: FloorStats;
  /** The floor's statistics in the lux-mode table as shown (Ē, Emin, Emax, U0). */
  floorRow: string;
  groupBakes: number;
  relightsOnly: number;
  /** Milliseconds from the 3D click to the first lit frame and to the finished bake. */
  firstLitMs: number;
  bakeMs: number;
  totalMs: number;
  screenshots: string[];
}

type Status = {
  open: boolean;
  lit: boolean;
  done: boolean;
  error: string | null;
  groupBakes: number;
  relightsOnly: number;
  frames: number;
  firstLitMs: number | null;
  floor: FloorStats | null;
};

type SceneFile = { configuration: { room: { width: number; depth: number; height: number }; systems: { id: string; rails: { modules: { id: string; dimming: number }[] }[] }[] } };

const sel = (testId: string) => `[data-testid="${testId}"]`;

/** Polls `read` until `ok` holds or the time is up; the error names what was awaited and the last value. */
export async function until<T>(what: string, read: () => Promise<T>, ok: (v: T) => boolean, timeoutMs = 30_000, intervalMs = 250): Promise<T> {
  const end = Date.now() + timeoutMs;
  let last: T | undefined;
  for (;;) {
    last = await read();
    if (ok(last)) return last;
    if (Date.now() > end) throw new Error(`${what}: not reached within ${timeoutMs} ms (last: ${JSON.stringify(last)})`);
    await new Promise((r) => setTimeout(r, intervalMs));
  }
}

function check(condition: boolean, engine: EngineName, message: string): void {
  if (!condition) throw new Error(`${engine}: ${message}`);
}

/**
 * One engine through the configurator as a user goes: room setup typed into the form, plan,
 * the L-corner preset from the side panel, 3D bake to completion at a pinned quality, relight
 * (one module dimmed to 0 with the keyboard on its slider), lux mode, and a scene-file round trip
 * (the file the app writes, opened again through the file input). Screenshots go to `outDir`.
 */
export async function runCrossEngineScenario(d: EngineDriver, baseUrl: string, outDir: string, quality: string, bakeTimeoutMs: number): Promise<EngineReport> {
  const t0 = Date.now();
  const { engine } = d;
  const status = () => d.evaluate<Status>('window.luxbox.view3d()');
  const config = () => d.evaluate<SceneFile>('JSON.parse(window.luxbox.getConfig())');

  await d.goto(`${baseUrl}/?quality=${quality}`);
  await until(
    `${engine}: room setup shown`,
    () => d.evaluate<boolean>(`!!document.querySelector('input[name="width"]') && !!window.luxbox`),
    (v) => v,
  );
  const env = await d.evaluate<Pick<EngineReport, 'userAgent' | 'language' | 'intlLocale' | 'webgl' | 'viewport'>>(`(() => {
    const gl = document.createElement('canvas').getContext('webgl2');
    return {
      userAgent: navigator.userAgent,
      language: navigator.language,
      intlLocale: new Intl.NumberFormat().resolvedOptions().locale,
      webgl: gl ? { renderer: String(gl.getParameter(gl.getExtension('WEBGL_debug_renderer_info') ? 0x9246 : gl.RENDERER)), extensions: gl.getSupportedExtensions() || [] } : { renderer: 'none', extensions: [] },
      viewport: [innerWidth, innerHeight],
    };
  })()`);
  check(env.webgl.renderer !== 'none', engine, 'no WebGL2 context');
  check(env.webgl.extensions.includes('EXT_color_buffer_float'), engine, `no EXT_color_buffer_float (float render targets) among ${env.webgl.extensions.join(', ')}`);

  // Room setup through the form: a decimal comma as many shoppers type it.
  await d.fill('input[name="width"]', '5');
  await d.fill('input[name="depth"]', '4');
  await d.fill('input[name="height"]', '2,8');
  await d.click('form.setup-card button[type="submit"]');
  await until(
    `${engine}: plan shown`,
    () => d.evaluate<boolean>(`!!document.querySelector('${sel('plan')}')`),
    (v) => v,
  );
  const room = (await config()).configuration.room;
  check(room.width === 5 && room.depth === 4 && room.height === 2.8, engine, `room from the form is ${JSON.stringify(room)}, expected 5 × 4 × 2.8 m`);

  await d.click(sel('preset-corner-l'));
  const placed = await until(`${engine}: L-corner placed`, config, (c) => c.configuration.systems.length === 1);
  const modules = placed.configuration.systems[0].rails.flatMap((r) => r.modules);
  const font = await d.evaluate<EngineReport['font']>(`(() => {
    const h = document.querySelector('.luxbox h1') || document.querySelector('h1');
    const r = document.createRange(); r.selectNodeContents(h);
    const ctx = document.createElement('canvas').getContext('2d');
    const width = (family) => { ctx.font = getComputedStyle(h).fontWeight + ' ' + getComputedStyle(h).fontSize + ' ' + family; return Math.round(ctx.measureText(h.textContent).width * 10) / 10; };
    return {
      family: getComputedStyle(h).fontFamily,
      titleWidth: Math.round(r.getBoundingClientRect().width * 10) / 10,
      candidates: { 'system-ui': width('system-ui'), 'DejaVu Sans': width('"DejaVu Sans"'), 'Liberation Sans': width('"Liberation Sans"') },
    };
  })()`);
  const price = await until(
    `${engine}: price shown`,
    () => d.evaluate<string>(`document.querySelector('${sel('header-total')}').textContent.trim()`),
    (p) => /\d/.test(p),
  );

  // 3D: bake to completion.
  const t3d = Date.now();
  await d.click(sel('tool-3d'));
  const baked = await until(`${engine}: bake done`, status, (s) => s.done || s.error !== null, bakeTimeoutMs, 500);
  check(baked.error === null, engine, `3D view error: ${baked.error}`);
  check(baked.lit && baked.floor !== null, engine, 'done but not lit');
  check(baked.groupBakes === modules.length, engine, `${baked.groupBakes} group bakes for ${modules.length} modules`);
  const bakeMs = Date.now() - t3d;
  const shots: string[] = [];
  const shot = async (name: string) => {
    const path = join(outDir, `${engine}-${name}.png`);
    await mkdir(outDir, { recursive: true });
    await d.screenshot(path);
    shots.push(path);
  };
  await shot('light');

  // Relight: the first module's dimmer to 0 with the keyboard (Home = the slider's minimum; committed on key up).
  const framesBefore = baked.frames;
  await d.click('details.viewer3d-modules > summary');
  await d.press(sel(`dim-${modules[0].id}`), 'Home');
  await until(`${engine}: module dimmed to 0`, config, (c) => c.configuration.systems[0].rails.flatMap((r) => r.modules)[0].dimming === 0, 10_000);
  await until(`${engine}: floor darker after the relight`, status, (s) => s.floor !== null && s.floor.avg < baked.floor!.avg * 0.97, 30_000);
  // The indirect light is re-solved in the background; the numbers compared are the settled ones.
  const dimmed = await until(`${engine}: re-solve after the relight done`, status, (s) => s.done, bakeTimeoutMs, 500);
  check(dimmed.groupBakes === baked.groupBakes, engine, `the relight started group bakes (${baked.groupBakes} → ${dimmed.groupBakes})`);
  check(dimmed.relightsOnly > baked.relightsOnly, engine, 'no relight counted');
  check(dimmed.frames > framesBefore, engine, 'no frame drawn after the relight');

  // Lux mode: legend and the floor row of the table.
  await d.click(sel('mode-lux'));
  await until(
    `${engine}: lux legend`,
    () => d.evaluate<boolean>(`!!document.querySelector('${sel('view3d-legend')}')`),
    (v) => v,
  );
  const floorRow = await until(
    `${engine}: floor row`,
    // The floor's column of the statistics table (a row per quantity: Ē, Emin, Emax, U0; IlluminanceTable.tsx).
    () => d.evaluate<string>(`['avg', 'min', 'max', 'u0'].map((k) => document.querySelector('[data-testid="stats-floor-' + k + '"]')?.textContent.trim() ?? '').join(' | ')`),
    (t) => t.split(' | ').every((v) => /\d/.test(v)),
  );
  await shot('lux');

  // Scene file round trip: the JSON the app saves, the system deleted, the file opened through the UI.
  const savedText = await d.evaluate<string>('window.luxbox.getConfig()');
  const savedPath = join(outDir, `${engine}.luxbox.json`);
  await mkdir(outDir, { recursive: true });
  await writeFile(savedPath, savedText);
  await d.click(sel('back-2d'));
  await until(
    `${engine}: back on the plan`,
    () => d.evaluate<boolean>(`!!document.querySelector('${sel('plan')}')`),
    (v) => v,
  );
  const removed = await d.evaluate<{ ok: boolean }>(`window.luxbox.runAction('deleteSystem', { systemId: ${JSON.stringify(placed.configuration.systems[0].id)} })`);
  check(removed.ok, engine, 'deleteSystem refused');
  check((await config()).configuration.systems.length === 0, engine, 'system still there after deleteSystem');
  await d.setInputFile(sel('open-file'), savedPath);
  const reopened = await until(
    `${engine}: saved file opened`,
    () => d.evaluate<string>('window.luxbox.getConfig()'),
    (t) => t === savedText,
    15_000,
  );
  check(reopened === savedText, engine, 'the reopened configuration differs from the saved one');

  return {
    engine,
    ...env,
    font,
    price,
    room,
    baked: baked.floor!,
    dimmed: dimmed.floor!,
    floorRow,
    groupBakes: dimmed.groupBakes,
    relightsOnly: dimmed.relightsOnly,
    firstLitMs: baked.firstLitMs ?? -1,
    bakeMs,
    totalMs: Date.now() - t0,
    screenshots: shots,
  };
}
