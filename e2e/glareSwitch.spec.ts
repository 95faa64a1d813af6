import { expect, test, type Page } from '@playwright/test';
import { PNG } from 'pngjs';
import { viewerStatus as status } from './helpers';

test.use({ reducedMotion: 'reduce', viewport: { width: 1440, height: 900 } });

/**
 * The L-corner preset (six spots, no furniture: a short bake) in 3D, baked at a fixed quality:
 * `fast`, since the glare pass works on the drawn HDR image (the lamps' emitters) whatever the
 * maps' resolution; the test compares the picture with and without it in the same bake.
 */
async function openCornerL3d(page: Page): Promise<void> {
  await page.goto('/?quality=fast');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-corner-l').click();
  await expect.poll(async () => JSON.parse(await page.evaluate(() => window.luxbox!.getConfig())).configuration.systems.length).toBe(1);
  await page.getByTestId('tool-3d').click();
  await expect(page.getByTestId('view3d-canvas')).toBeVisible();
  await expect.poll(async () => (await status(page)).done, { timeout: 150_000, intervals: [250] }).toBe(true);
}

/** A canvas screenshot once drawing has stopped (render on demand: the frame counter holds still). */
async function settledShot(page: Page): Promise<Buffer> {
  let last = -1;
  await expect
    .poll(
      async () => {
        const f = (await status(page)).frames;
        const still = f === last;
        last = f;
        return still;
      },
      { timeout: 20_000, intervals: [400] },
    )
    .toBe(true);
  return page.getByTestId('view3d-canvas').screenshot();
}

/** Share of pixels whose R, G or B differs by more than 2 of 255 (same size images). */
function changedShare(a: Buffer, b: Buffer): number {
  const x = PNG.sync.read(a);
  const y = PNG.sync.read(b);
  let changed = 0;
  for (let i = 0; i < x.data.length; i += 4) {
    if (Math.max(Math.abs(x.data[i] - y.data[i]), Math.abs(x.data[i + 1] - y.data[i + 1]), Math.abs(x.data[i + 2] - y.data[i + 2])) > 2) changed++;
  }
  return changed / (x.width * x.height);
}

test('the glare switch: on by default, off changes the picture, on again restores it', async ({ page }) => {
  test.setTimeout(240_000);
  await openCornerL3d(page);
  const toggle = page.getByTestId('glare-toggle');
  await expect(toggle).toHaveAttribute('aria-pressed', 'true');
  const withGlare = await settledShot(page);

  const frames = (await status(page)).frames;
  await toggle.click();
  await expect(toggle).toHaveAttribute('aria-pressed', 'false');
  await expect.poll(async () => (await status(page)).frames).toBeGreaterThan(frames);
  const without = await settledShot(page);
  // The halo round the lamps goes: some pixels change, but glare is a veil round bright sources, not a new picture.
  const share = changedShare(withGlare, without);
  expect(share).toBeGreaterThan(0.001);
  expect(share).toBeLessThan(0.9);

  await toggle.click();
  await expect(toggle).toHaveAttribute('aria-pressed', 'true');
  const again = await settledShot(page);
  expect(changedShare(withGlare, again)).toBeLessThan(0.001);
});
