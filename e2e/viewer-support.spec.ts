import { expect, test } from '@playwright/test';

test.use({ reducedMotion: 'reduce', viewport: { width: 1280, height: 800 } });

test('without WebGL2 the 3D toggle explains why, and the 2D planner keeps working', async ({ page }) => {
  // A device without WebGL2: getContext('webgl2') answers null, as such browsers do.
  await page.addInitScript(() => {
    const original = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (this: HTMLCanvasElement, kind: string, ...rest: unknown[]) {
      if (kind === 'webgl2') return null;
      return (original as (...a: unknown[]) => unknown).call(this, kind, ...rest);
    } as typeof original;
  });
  await page.goto('/');
  expect(await page.evaluate(() => window.luxbox!.runAction('placePreset', { presetId: 'single' }))).toEqual({ ok: true });
  const before = await page.evaluate(() => window.luxbox!.getConfig());
  await page.getByTestId('tool-3d').click();
  await expect(page.getByTestId('view3d-unsupported')).toContainText('no WebGL2');
  expect(await page.evaluate(() => (window.luxbox!.view3d() as { error: string | null }).error)).toMatch(/WebGL2/);
  // No 3D chunk was downloaded for nothing.
  const chunks = await page.evaluate(() =>
    performance
      .getEntriesByType('resource')
      .map((e) => e.name)
      .filter((n) => /View3D/.test(n)),
  );
  expect(chunks).toEqual([]);
  await page.getByRole('button', { name: 'Back to 2D plan' }).click();
  await expect(page.getByTestId('plan')).toBeVisible();
  expect(await page.evaluate(() => window.luxbox!.getConfig())).toBe(before);
  expect(await page.evaluate(() => window.luxbox!.runAction('placePreset', { presetId: 'single' }))).toMatchObject({ ok: expect.any(Boolean) });
});

test('the 3D view at phone size: panel below the image, bake completes', async ({ page }) => {
  await page.setViewportSize({ width: 390, height: 844 });
  await page.goto('/');
  await page.evaluate(() => window.luxbox!.runAction('placePreset', { presetId: 'single' }));
  await page.getByTestId('tool-3d').click();
  await expect.poll(async () => page.evaluate(() => (window.luxbox!.view3d() as { done: boolean }).done), { timeout: 90_000, intervals: [250] }).toBe(true);
  const canvas = await page.getByTestId('view3d-canvas').boundingBox();
  expect(canvas!.width).toBeGreaterThan(300);
  expect(canvas!.height).toBeGreaterThan(200);
  await page.screenshot({ path: 'test-results/viewer-phone.png' });
});
