import { PNG } from 'pngjs';
import type { ViewerStatus } from '../src/ui/viewer/viewerStatus';
import { expect, type Page } from '@playwright/test';

/** The running app's embedding API (window.luxbox), called in the page. */
export async function sceneFile(page: Page): Promise<{
  configuration: { room: { width: number; depth: number; height: number }; systems: { id: string; x: number; z: number; rotation: number; rails: { id: string; modules: { id: string; type: string; cct: number; dimming: number }[] }[] }[] };
}> {
  return JSON.parse(await page.evaluate(() => window.luxbox!.getConfig()));
}

export async function moduleCount(page: Page): Promise<number> {
  const f = await sceneFile(page);
  return f.configuration.systems.flatMap((s) => s.rails.flatMap((r) => r.modules)).length;
}

/** Waits until every module's measured footprint is drawn, so screenshots are stable. */
export async function footprintsReady(page: Page): Promise<void> {
  await expect(page.getByTestId('plan-svg')).toHaveAttribute('data-footprints', 'ready');
}

/** Clicks zoom-in until the plan shows the module level (at most 8 clicks). */
export async function zoomToModuleLevel(page: Page): Promise<void> {
  const plan = page.getByTestId('plan');
  for (let i = 0; i < 8; i++) {
    if ((await plan.getAttribute('data-level')) === 'module') return;
    const before = await plan.getAttribute('data-scale');
    await page.getByTestId('zoom-in').click();
    // The spring applies the new view on its next frame: wait for it before deciding again.
    await expect(plan).not.toHaveAttribute('data-scale', before ?? '');
  }
  await expect(plan).toHaveAttribute('data-level', 'module');
}

/** In-page handle installed by trackCanvases. */
export type CanvasTracking = { __detachedWebgl2: () => HTMLCanvasElement[] };

/**
 * Records every canvas the page creates from now on (call before `goto`): the baker's own canvas
 * is never attached to the document, so it is found only this way. In the page,
 * `window.__detachedWebgl2()` lists the detached canvases whose WebGL2 context is still alive,
 * oldest first (the support checks and the calibration lose theirs).
 */
export async function trackCanvases(page: Page): Promise<void> {
  await page.addInitScript(() => {
    const created: HTMLCanvasElement[] = [];
    (window as unknown as CanvasTracking).__detachedWebgl2 = () => created.filter((c) => !c.isConnected && c.getContext('webgl2') && !c.getContext('webgl2')!.isContextLost());
    const original = document.createElement.bind(document);
    document.createElement = ((tag: string, options?: ElementCreationOptions) => {
      const el = original(tag, options);
      if (tag.toLowerCase() === 'canvas') created.push(el as HTMLCanvasElement);
      return el;
    }) as typeof document.createElement;
  });
}

/** The 3D view's status as `window.luxbox.view3d()` reports it (bake progress, counters, quality). */
export function viewerStatus(page: Page): Promise<ViewerStatus> {
  return page.evaluate(() => window.luxbox!.view3d() as ViewerStatus);
}

/** Mean sRGB value (0..255) of a PNG screenshot. */
export function meanLevel(png: Buffer): number {
  const img = PNG.sync.read(png);
  let sum = 0;
  for (let i = 0; i < img.data.length; i += 4) sum += (img.data[i] + img.data[i + 1] + img.data[i + 2]) / 3;
  return sum / (img.width * img.height);
}

/** A fresh start (`?quality=fast`, nothing stored) on a 5 × 4 m room: the daylight specs' room before its window is drawn. */
export async function startFiveByFourRoom(page: Page): Promise<void> {
  await page.goto('/?quality=fast');
  await page.evaluate(() => localStorage.clear());
  await page.reload();
  await page.locator('input[name=width]').fill('5');
  await page.locator('input[name=depth]').fill('4');
  await page.getByRole('button', { name: 'Start planning' }).click();
}
