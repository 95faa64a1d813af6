import { expect, test, type Page } from '@playwright/test';
import { PNG } from 'pngjs';
import { viewerStatus as status, meanLevel } from './helpers';

// The 3D view's exposure (docs/viewer.md, "Exposure: automatic or a fixed EV100", "Exposure that compares"):
// automatic exposure adapts like an eye and holds while the light is only dimmed, so dimming every
// module makes the image darker; Re-adapt exposes it again; a locked EV100 holds too.
test.use({ reducedMotion: 'reduce', viewport: { width: 1280, height: 800 } });

/** Every module of the configuration to `dimming` through the embed API; waits for the relit floor. */
async function dimAll(page: Page, dimming: number, floorBelow: number): Promise<void> {
  await page.evaluate((d) => {
    const config = JSON.parse(window.luxbox!.getConfig());
    for (const system of config.configuration.systems) for (const rail of system.rails) for (const m of rail.modules) window.luxbox!.runAction('setModuleDimming', { moduleId: m.id, dimming: d });
  }, dimming);
  await expect.poll(async () => (await status(page)).floor!.avg, { timeout: 30_000 }).toBeLessThan(floorBelow);
  await expect.poll(async () => (await status(page)).done, { timeout: 60_000, intervals: [250] }).toBe(true);
}

test('auto exposure holds while dimming: 25 % looks darker; Re-adapt re-exposes it; a locked EV100 stays through more dimming', async ({ page }) => {
  await page.goto('/?quality=fast');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-corner-l').click();
  await page.getByTestId('tool-3d').click();
  const canvas = page.getByTestId('view3d-canvas');
  await expect(canvas).toBeVisible();
  await expect.poll(async () => (await status(page)).done, { timeout: 90_000, intervals: [250] }).toBe(true);
  const full = await status(page);
  const autoFull = meanLevel(await canvas.screenshot());
  expect(autoFull).toBeGreaterThan(25);
  const control = page.getByTestId('exposure-control');
  await expect(control).toHaveAttribute('data-ev100', 'auto');

  // Dimming is a relight: the eye stays adapted to the full room, so a quarter of the light looks darker under AUTO.
  await dimAll(page, 0.25, full.floor!.avg * 0.3);
  const autoDim = meanLevel(await canvas.screenshot());
  expect(autoDim).toBeLessThan(autoFull * 0.75);
  await expect(control).toHaveAttribute('data-ev100', 'auto');

  // Re-adapt: the view adapts to the dim room (slowly, τ = 0.4 s) up to about the full room's brightness.
  await page.getByTestId('exposure-readapt').click();
  await expect.poll(async () => meanLevel(await canvas.screenshot()), { timeout: 10_000 }).toBeGreaterThan(autoFull * 0.9);
  const readapted = meanLevel(await canvas.screenshot());

  // Lock at what the eye is adapted to now: the control shows the EV100 and keeps it through more dimming.
  await page.getByTestId('exposure-lock').click();
  await expect(control).not.toHaveAttribute('data-ev100', 'auto');
  const locked = Number(await control.getAttribute('data-ev100'));
  expect(locked).toBeGreaterThan(-1);
  expect(locked).toBeLessThan(12);
  await expect(page.getByTestId('exposure-ev100')).toBeVisible();
  const dimFloor = (await status(page)).floor!.avg;
  await dimAll(page, 0.0625, dimFloor * 0.3);
  expect(meanLevel(await canvas.screenshot())).toBeLessThan(readapted * 0.75);
  expect(Number(await control.getAttribute('data-ev100'))).toBe(locked);
});

test('?exposure=5 (the embed option exposure: 5): the 3D view opens locked at EV100 5', async ({ page }) => {
  await page.goto('/?quality=fast&exposure=5');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-corner-l').click();
  await page.getByTestId('tool-3d').click();
  await expect.poll(async () => (await status(page)).lit, { timeout: 90_000, intervals: [250] }).toBe(true);
  await expect(page.getByTestId('exposure-control')).toHaveAttribute('data-ev100', '5');
  await expect(page.getByTestId('exposure-ev100')).toHaveValue('5');
  expect(meanLevel(await page.getByTestId('view3d-canvas').screenshot())).toBeGreaterThan(10);
});

/** Mean of R − B over a PNG's pixels (how warm the picture is). */
function warmth(png: Buffer): number {
  const img = PNG.sync.read(png);
  let s = 0;
  for (let i = 0; i < img.data.length; i += 4) s += img.data[i] - img.data[i + 2];
  return s / (img.width * img.height);
}

test('?adapt=camera:3000 opens with camera white balance at 3000 K (neutral); None shows the physical orange, Eye a warm white between', async ({ page }) => {
  await page.goto('/?quality=fast&adapt=camera:3000');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-corner-l').click();
  await page.getByTestId('tool-3d').click();
  await expect.poll(async () => (await status(page)).lit, { timeout: 90_000, intervals: [250] }).toBe(true);
  const control = page.getByTestId('adaptation-control');
  await expect(control).toHaveAttribute('data-adapt', 'camera:3000');
  await expect(page.getByTestId('adapt-cct')).toHaveValue('3000');
  const canvas = page.getByTestId('view3d-canvas');
  const camera = warmth(await canvas.screenshot());
  await page.getByTestId('adapt-none').click();
  await expect(control).toHaveAttribute('data-adapt', 'none');
  await expect.poll(async () => warmth(await canvas.screenshot()), { timeout: 10_000 }).toBeGreaterThan(camera + 20);
  const none = warmth(await canvas.screenshot());
  await page.getByTestId('adapt-eye').click();
  await expect(control).toHaveAttribute('data-adapt', 'eye');
  await expect.poll(async () => warmth(await canvas.screenshot()), { timeout: 10_000 }).toBeLessThan(none - 10);
  expect(warmth(await canvas.screenshot())).toBeGreaterThan(camera);
});
