import { expect, test, type Page } from '@playwright/test';
import { startFiveByFourRoom, viewerStatus as status } from './helpers';

/**
 * The 3D view's daylight-factor mode (issue 30; docs/viewer.md "Daylight factor"): a 5 × 4 m room
 * with a window in the south wall, daylight on, the 3D view at fast quality, then the
 * Daylight factor button: the legend reads in %, the statistics table shows the work plane's DF,
 * and `view3d().daylightFactor` reports numbers a daylit room has (mean between 0.1 and 20 %,
 * min ≤ mean, U0 = min / mean, a share in 0 … 1). Light leaves the mode. Screenshots for looking at
 * under test-results/daylight-factor.
 */
async function daylitRoom(page: Page) {
  await startFiveByFourRoom(page);
  const toggle = page.getByTestId('panel-toggle');
  if ((await toggle.isVisible()) && !(await page.getByRole('complementary').isVisible())) await toggle.click();
  await page.getByTestId('edit-room-shape').click();
  await page.getByTestId('room-preset-rectangle').click();
  await page.getByTestId('room-wall-2').click();
  await page.getByTestId('room-add-window').click();
  await page.getByTestId('room-shape-done').click();
  if ((await toggle.isVisible()) && !(await page.getByRole('complementary').isVisible())) await toggle.click();
  if (!(await page.getByTestId('daylight-panel').isVisible())) await page.getByTestId('daylight-open').click();
  await page.getByTestId('daylight-on').check();
  await page.getByTestId('daylight-city').selectOption('Zurich');
  await page.getByTestId('daylight-june').click();
  if (await toggle.isVisible()) await toggle.click();
  await page.getByTestId('tool-3d').click();
  await expect(page.getByTestId('view3d-canvas')).toBeVisible();
}

type DaylightFactor = { mean: number; min: number; max: number; u0: number; shareAbove2: number; points: number } | null;
const daylightFactor = async (page: Page) => (await status(page)).daylightFactor as DaylightFactor;

for (const [name, viewport] of [
  ['desktop', { width: 1440, height: 900 }],
  ['phone', { width: 390, height: 844 }],
] as const) {
  test(`daylight factor in the 3D view on a ${name}: legend in %, the work plane's DF`, async ({ page }) => {
    test.setTimeout(45_000);
    await page.setViewportSize(viewport);
    await daylitRoom(page);
    const mode = page.getByTestId('mode-daylight-factor');
    await mode.scrollIntoViewIfNeeded();
    await mode.click();
    await expect(mode).toHaveAttribute('aria-pressed', 'true');
    await expect.poll(() => daylightFactor(page), { timeout: 30_000, intervals: [250] }).not.toBeNull();
    const df = (await daylightFactor(page))!;
    expect(df.points).toBeGreaterThan(50);
    expect(df.mean).toBeGreaterThan(0.1);
    expect(df.mean).toBeLessThan(20);
    expect(df.min).toBeLessThanOrEqual(df.mean);
    expect(df.u0).toBeCloseTo(df.min / df.mean, 9);
    expect(df.shareAbove2).toBeGreaterThanOrEqual(0);
    expect(df.shareAbove2).toBeLessThanOrEqual(1);
    const legend = page.getByTestId('view3d-legend');
    await expect(legend).toContainText('2 %');
    await expect(legend).toContainText('10 %');
    await expect(legend).not.toContainText('lx');
    await expect(page.getByTestId('df-mean')).toHaveText(df.mean.toFixed(2));
    await page.screenshot({ path: `test-results/daylight-factor/${name}.png` });
    // Light leaves the mode: the panel's light again, the lux table back.
    await page.getByRole('button', { name: 'Light', exact: true }).click();
    await expect(mode).toHaveAttribute('aria-pressed', 'false');
    await expect.poll(() => daylightFactor(page)).toBeNull();
    await expect(page.getByTestId('df-stats')).toHaveCount(0);
  });
}
