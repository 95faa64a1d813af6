import { expect, test, type Page } from '@playwright/test';
import { trackCanvases, type CanvasTracking, viewerStatus as status, meanLevel } from './helpers';

test.use({ reducedMotion: 'reduce', viewport: { width: 1280, height: 800 } });

/** `balanced` where a golden image is compared (the goldens were drawn at it); `fast` where the test compares the bake with itself. */
async function openCornerL(page: Page, quality: 'fast' | 'balanced' = 'balanced'): Promise<void> {
  // Configure in 2D through the UI: default room, then the L-corner preset from the side panel.
  await page.goto(`/?quality=${quality}`); // lux values at a fixed bake quality (docs/viewer.md, "Quality levels")
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-corner-l').click();
  await expect.poll(async () => JSON.parse(await page.evaluate(() => window.luxbox!.getConfig())).configuration.systems.length).toBe(1);
  await page.getByTestId('tool-3d').click();
  await expect(page.getByTestId('view3d-canvas')).toBeVisible();
  await expect.poll(async () => (await status(page)).done, { timeout: 90_000, intervals: [250] }).toBe(true);
}

test('2D preset → 3D bake → golden; dim relights without a rebake; back to 2D unchanged', async ({ page }) => {
  await openCornerL(page);
  const canvas = page.getByTestId('view3d-canvas');
  const baked = await status(page);
  expect(baked.lit).toBe(true);
  expect(baked.groupBakes).toBe(6); // one basis per module of the corner-l preset
  expect(baked.floor!.avg).toBeGreaterThan(50);

  const first = await canvas.screenshot();
  expect(meanLevel(first)).toBeGreaterThan(25); // not black
  // Golden: SwiftShader is deterministic; 1 % of pixels may differ by more than the per-pixel threshold.
  await expect(canvas).toHaveScreenshot('viewer-corner-l.png', { maxDiffPixelRatio: 0.01, threshold: 0.15 });

  // Render on demand: nothing is drawn while idle.
  const framesIdle = (await status(page)).frames;
  await page.waitForTimeout(600);
  expect((await status(page)).frames).toBe(framesIdle);

  // Dim the first module through the 3D view's dimmer: a relight, no bake.
  const before = JSON.parse(await page.evaluate(() => window.luxbox!.getConfig()));
  const moduleId: string = before.configuration.systems[0].rails[0].modules[0].id;
  await page.getByText(/Dimming \(6 modules\)/).click();
  const dimmer = page.getByTestId(`dim-${moduleId}`);
  await dimmer.focus();
  for (let i = 0; i < 20; i++) await page.keyboard.press('ArrowLeft'); // to 0 % in 5 % steps, committed on key up
  await expect.poll(async () => JSON.parse(await page.evaluate(() => window.luxbox!.getConfig())).configuration.systems[0].rails[0].modules[0].dimming).toBe(0);
  // Switching one of six modules off lowers the floor's average; the relit maps arrive without any new group bake.
  await expect.poll(async () => (await status(page)).floor!.avg, { timeout: 10_000 }).toBeLessThan(baked.floor!.avg * 0.97);
  const dimmed = await status(page);
  expect(dimmed.relightsOnly).toBeGreaterThan(baked.relightsOnly);
  expect(dimmed.groupBakes).toBe(baked.groupBakes);
  await expect.poll(async () => (await status(page)).frames).toBeGreaterThan(framesIdle);
  const second = await canvas.screenshot();
  expect(second.equals(first)).toBe(false);

  const afterDim = await page.evaluate(() => window.luxbox!.getConfig());
  expect(JSON.parse(afterDim).configuration.systems[0].rails[0].modules[0].dimming).toBe(0);

  // Back to 2D: the configuration is exactly what it was in 3D.
  await page.getByTestId('tool-3d').click();
  await expect(page.getByTestId('plan')).toBeVisible();
  expect(await page.evaluate(() => window.luxbox!.getConfig())).toBe(afterDim);
  expect((await status(page)).open).toBe(false);
});

test('lux mode shows a legend and floor statistics; context loss recovers without touching the configuration', async ({ page }) => {
  await openCornerL(page);
  await page.getByTestId('mode-lux').click();
  await expect(page.getByTestId('view3d-legend')).toBeVisible();
  await expect(page.getByTestId('stats-floor-avg')).toContainText(/\d/);
  await page.getByTestId('camera-top').click();
  await expect(page.getByTestId('view3d-canvas')).toHaveScreenshot('viewer-corner-l-lux-top.png', { maxDiffPixelRatio: 0.01, threshold: 0.15 });

  const config = await page.evaluate(() => window.luxbox!.getConfig());
  const frames = (await status(page)).frames;
  await page.evaluate(() => {
    const c = document.querySelector('[data-testid="view3d-canvas"]') as HTMLCanvasElement;
    const ext = c.getContext('webgl2')!.getExtension('WEBGL_lose_context')!;
    ext.loseContext();
    setTimeout(() => ext.restoreContext(), 200);
  });
  await expect.poll(async () => (await status(page)).contextLosses).toBe(1);
  await expect.poll(async () => (await status(page)).frames, { timeout: 20_000 }).toBeGreaterThan(frames);
  const shot = await page.getByTestId('view3d-canvas').screenshot();
  expect(meanLevel(shot)).toBeGreaterThan(25);
  expect(await page.evaluate(() => window.luxbox!.getConfig())).toBe(config);
});

test('losing the bake context rebakes every group after the restore; the configuration is untouched', async ({ page }) => {
  await trackCanvases(page);
  await openCornerL(page, 'fast');
  const config = await page.evaluate(() => window.luxbox!.getConfig());
  const before = await status(page);
  const lost = await page.evaluate(() => {
    const bake = (window as unknown as CanvasTracking).__detachedWebgl2().pop();
    if (!bake) return false;
    const ext = bake.getContext('webgl2')!.getExtension('WEBGL_lose_context')!;
    ext.loseContext();
    setTimeout(() => ext.restoreContext(), 200);
    return true;
  });
  expect(lost).toBe(true);
  await expect.poll(async () => (await status(page)).contextLosses).toBe(before.contextLosses + 1);
  // Rebaked from scratch: six more group bakes, and the bake runs to completion again.
  await expect.poll(async () => (await status(page)).groupBakes, { timeout: 30_000 }).toBe(before.groupBakes + 6);
  await expect.poll(async () => (await status(page)).done, { timeout: 90_000, intervals: [250] }).toBe(true);
  const after = await status(page);
  expect(after.floor!.avg).toBeCloseTo(before.floor!.avg, 0);
  expect(await page.evaluate(() => window.luxbox!.getConfig())).toBe(config);
});
