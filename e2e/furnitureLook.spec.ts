import { mkdirSync } from 'node:fs';
import { expect, test, type Page } from '@playwright/test';
import { PNG } from 'pngjs';
import { viewerStatus as status } from './helpers';

/**
 * The furniture as a shopper meets it (issue 26): the library panel shows each item's thumbnail
 * from one sprite sheet drawn from the meshes (scripts/furnitureThumbnails.ts), and the furnished
 * living room in 3D. Screenshots at phone and desktop sizes go to test-results/furniture/ for review.
 */
test.use({ reducedMotion: 'reduce' });

const SIZES = {
  phone: { width: 375, height: 667 },
  desktop: { width: 1280, height: 800 },
} as const;

async function openDemo(page: Page, quality = 'balanced') {
  await page.goto(`/?quality=${quality}`);
  await page.getByRole('button', { name: 'Try the demo' }).click();
  await expect(page.getByTestId('plan')).toBeVisible();
}

test('the library shows a distinct cell of the sprite sheet for every item, and the sheet loads', async ({ page }) => {
  await page.setViewportSize(SIZES.desktop);
  await openDemo(page);
  const thumbnails = page.getByTestId('furniture-panel').locator('.furniture-thumbnail');
  const count = await thumbnails.count();
  expect(count).toBeGreaterThanOrEqual(12);
  const styles = await thumbnails.evaluateAll((els) => els.map((el) => ({ image: getComputedStyle(el).backgroundImage, position: getComputedStyle(el).backgroundPosition })));
  expect(new Set(styles.map((s) => s.position)).size).toBe(count);
  const url = styles[0].image.match(/url\("?([^")]+)"?\)/)![1];
  expect(new Set(styles.map((s) => s.image)).size).toBe(1);
  const response = await page.request.get(url);
  expect(response.ok()).toBe(true);
  const sheet = PNG.sync.read(await response.body());
  expect([sheet.width, sheet.height]).toEqual([96 * count, 96]);
  mkdirSync('test-results/furniture', { recursive: true });
  await page.getByTestId('furniture-panel').scrollIntoViewIfNeeded();
  await page.getByTestId('furniture-panel').screenshot({ path: 'test-results/furniture/library-desktop.png' });
});

for (const [name, viewport] of Object.entries(SIZES)) {
  test(`the furnished living room at ${name} size (for review)`, async ({ page }) => {
    test.setTimeout(420_000); // the furnished living room bakes in minutes on the software GPU
    await page.setViewportSize(viewport);
    await openDemo(page, 'fast');
    mkdirSync('test-results/furniture', { recursive: true });
    if (name === 'phone') {
      await page.getByTestId('panel-toggle').click();
      const panel = page.getByTestId('furniture-panel');
      await panel.scrollIntoViewIfNeeded();
      await page.screenshot({ path: 'test-results/furniture/library-phone.png' });
      await page.getByTestId('panel-toggle').click();
    }
    await page.screenshot({ path: `test-results/furniture/${name}-plan.png` });
    await page.getByTestId('tool-3d').click();
    await expect(page.getByTestId('view3d-canvas')).toBeVisible();
    await expect.poll(async () => (await status(page)).done, { timeout: 360_000, intervals: [250] }).toBe(true);
    await page.screenshot({ path: `test-results/furniture/${name}-3d.png` });
    await page.getByTestId('camera-eye').click();
    await expect.poll(async () => (await status(page)).frames).toBeGreaterThan(0);
    await page.waitForTimeout(500);
    await page.screenshot({ path: `test-results/furniture/${name}-eye.png` });
  });
}

test('the furnished dining room in 3D at desktop size (for review: chairs, table veneer)', async ({ page }) => {
  test.setTimeout(420_000);
  await page.setViewportSize(SIZES.desktop);
  await openDemo(page, 'fast');
  await page.getByTestId('room-dining-room').click();
  await expect.poll(async () => JSON.parse(await page.evaluate(() => window.luxbox!.getConfig())).configuration.room.width).toBe(5);
  await page.getByTestId('tool-3d').click();
  await expect(page.getByTestId('view3d-canvas')).toBeVisible();
  await expect.poll(async () => (await status(page)).done, { timeout: 360_000, intervals: [250] }).toBe(true);
  mkdirSync('test-results/furniture', { recursive: true });
  await page.screenshot({ path: 'test-results/furniture/dining-desktop-3d.png' });
  await page.getByTestId('camera-eye').click();
  await expect.poll(async () => (await status(page)).frames).toBeGreaterThan(0);
  await page.waitForTimeout(500);
  await page.screenshot({ path: 'test-results/furniture/dining-desktop-eye.png' });
});
