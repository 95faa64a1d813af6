import { mkdir, readFile, writeFile } from 'node:fs/promises';
import { join } from 'node:path';
import { PNG } from 'pngjs';
import { until } from './crossEngineScenario';
import type { EngineDriver } from './engineDriver';
import { furnishedSceneFile, GOLDEN_CAMERAS, GOLDEN_QUALITY, type GoldenCamera, type GoldenRoom } from './furnishedGoldens';
import { cropImage } from './imageDifference';

/** One view of a furnished room as an engine drew it: the canvas's pixels, and what the bake took. */
export interface FurnishedView {
  room: GoldenRoom;
  camera: GoldenCamera;
  /** The 3D canvas cut out of the viewport's screenshot. */
  image: PNG;
  /** Written here (for review and for LUXBOX_UPDATE_GOLDENS). */
  path: string;
  bakeMs: number;
}

type Status = { done: boolean; error: string | null; frames: number; bake: { groupBakes: number } };

const sleep = (ms: number) => new Promise((r) => setTimeout(r, ms));

/**
 * Frames are drawn on demand, and while the eye adaptation moves after a camera cut (at most
 * ~10 τ = 4 s, eyeAdaptation.ts): the picture is settled once no frame was drawn for a while.
 */
async function settled(status: () => Promise<Status>): Promise<void> {
  let last = (await status()).frames;
  for (let quiet = 0; quiet < 3;) {
    await sleep(400);
    const frames = (await status()).frames;
    quiet = frames === last ? quiet + 1 : 0;
    last = frames;
  }
}

/**
 * Opens each furnished room through the embedding API (setConfig with the scene file the app
 * writes), bakes it at GOLDEN_QUALITY, and takes the canvas from the eye and corner cameras
 * (the panel's preset buttons). The page is opened once; each room is a new picture (a new
 * bake, the exposure adapted again).
 */
export async function captureFurnishedViews(d: EngineDriver, baseUrl: string, outDir: string, rooms: readonly GoldenRoom[], bakeTimeoutMs: number): Promise<FurnishedView[]> {
  const status = () => d.evaluate<Status>('window.luxbox.view3d()');
  await d.goto(`${baseUrl}/?quality=${GOLDEN_QUALITY}&demo`);
  await until(
    `${d.engine}: app started`,
    () => d.evaluate<boolean>('!!window.luxbox && !!document.querySelector(\'[data-testid="tool-3d"]\')'),
    (v) => v,
    30_000,
  );
  await mkdir(outDir, { recursive: true });
  const views: FurnishedView[] = [];
  for (const room of rooms) {
    const t0 = Date.now();
    // A new room bakes new groups: done counts only after the service's counter moved (the previous room's done is stale).
    const before = (await status()).bake.groupBakes;
    await d.evaluate<boolean>(`(window.luxbox.setConfig(${JSON.stringify(furnishedSceneFile(room))}), true)`);
    if (!(await d.evaluate<boolean>('!!document.querySelector(\'[data-testid="view3d-canvas"]\')'))) await d.click('[data-testid="tool-3d"]');
    const baked = await until(`${d.engine}: ${room} baked`, status, (s) => (s.done && s.bake.groupBakes > before) || s.error !== null, bakeTimeoutMs, 500);
    if (baked.error !== null) throw new Error(`${d.engine}: ${room}: 3D view error: ${baked.error}`);
    const bakeMs = Date.now() - t0;
    for (const camera of GOLDEN_CAMERAS) {
      await d.click(`[data-testid="camera-${camera}"]`);
      await settled(status);
      const rect = await d.evaluate<{ x: number; y: number; width: number; height: number; ratio: number }>(
        `(() => { const r = document.querySelector('[data-testid="view3d-canvas"]').getBoundingClientRect(); return { x: Math.round(r.x), y: Math.round(r.y), width: Math.round(r.width), height: Math.round(r.height), ratio: devicePixelRatio }; })()`,
      );
      if (rect.ratio !== 1) throw new Error(`${d.engine}: device pixel ratio ${rect.ratio}, the goldens are taken at 1`);
      const shot = join(outDir, `${d.engine}-${room}-${camera}-page.png`);
      await d.screenshot(shot);
      const image = cropImage(PNG.sync.read(await readFile(shot)), rect);
      const path = join(outDir, `${d.engine}-${room}-${camera}.png`);
      await writeFile(path, PNG.sync.write(image));
      views.push({ room, camera, image, path, bakeMs });
    }
  }
  return views;
}
