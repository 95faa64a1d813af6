import { expect, test, type Page } from '@playwright/test';
import { PNG } from 'pngjs';
import { turbo } from '../src/engines/view/falseColorScale';
import { startFiveByFourRoom } from './helpers';

/**
 * The daylight-factor map on the 2D plan (issue 30; docs/daylight.md "The daylight-factor map on
 * the plan"): a 5 × 4 m room with a window, daylight on, a preset's rails on the plan, the plan's
 * Daylight factor toggle: the legend reads in %, the statistics show a mean between 0.1 and 20 %,
 * and on screen the cell next to the window is coded brighter (further along the legend's colour
 * scale) than the cell in the far corner. Screenshots in four languages on a phone, a tablet and a
 * desktop under test-results/daylight-plan for looking at.
 */
async function daylitRoom(page: Page) {
  await startFiveByFourRoom(page);
  const toggle = page.getByTestId('panel-toggle');
  const openPanel = async () => {
    if ((await toggle.isVisible()) && !(await page.getByRole('complementary').isVisible())) await toggle.click();
  };
  await openPanel();
  await page.getByTestId('edit-room-shape').click();
  await page.getByTestId('room-preset-rectangle').click();
  await page.getByTestId('room-wall-2').click();
  await page.getByTestId('room-add-window').click();
  await page.getByTestId('room-shape-done').click();
  await openPanel();
  if (!(await page.getByTestId('daylight-panel').isVisible())) await page.getByTestId('daylight-open').click();
  await page.getByTestId('daylight-on').check();
  await page.getByTestId('daylight-city').selectOption('Zurich');
  await page.getByTestId('daylight-june').click();
  if (await toggle.isVisible()) await toggle.click();
  // A preset's rails, so the map is seen under a real plan's drawing.
  await page.getByTestId('first-run-snake').click();
}

type Window = { outline: [number, number][]; wall: number; offset: number; width: number };

/** The room's outline and its first window, from the configuration the app holds. */
async function roomWindow(page: Page): Promise<Window> {
  const file = JSON.parse(await page.evaluate(() => window.luxbox!.getConfig()));
  const shape = file.configuration.room.shape;
  const w = shape.openings.find((o: { kind: string }) => o.kind === 'window');
  return { outline: shape.outline, wall: w.wall, offset: w.offset, width: w.width };
}

/** The legend position (0 … 1) whose turbo colour is nearest an on-screen pixel. */
function scalePosition([r, g, b]: number[]): number {
  let best = 0;
  let bestDistance = Infinity;
  for (let i = 0; i <= 1000; i++) {
    const c = turbo(i / 1000).map((v) => v * 255);
    const d = (c[0] - r) ** 2 + (c[1] - g) ** 2 + (c[2] - b) ** 2;
    if (d < bestDistance) [best, bestDistance] = [i / 1000, d];
  }
  return best;
}

/** Plan metres → page pixels through the plan's view transform (the SVG group's matrix) and the SVG's place on the page. */
async function planToPage(page: Page) {
  const box = (await page.getByTestId('plan-svg').boundingBox())!;
  const matrix = (await page.locator('[data-testid=plan-svg] > g').first().getAttribute('transform'))!;
  const [s, , , , ox, oy] = matrix.slice(7, -1).split(/\s+/).map(Number);
  return ([x, z]: [number, number]) => [box.x + ox + s * x, box.y + oy + s * z] as const;
}

test('the daylight-factor map on the plan: legend in %, statistics, brighter by the window', async ({ page }) => {
  test.setTimeout(45_000);
  await page.setViewportSize({ width: 1440, height: 900 });
  await daylitRoom(page);
  const dfToggle = page.getByTestId('df-plan-toggle');
  await dfToggle.click();
  await expect(dfToggle).toHaveAttribute('aria-pressed', 'true');
  const overlay = page.getByTestId('df-plan');
  await expect(overlay).toHaveAttribute('data-phase', 'ready', { timeout: 35_000 });
  const legend = overlay.getByTestId('view3d-legend');
  await expect(legend).toContainText('2 %');
  await expect(legend).toContainText('10 %');
  await expect(legend).not.toContainText('lx');
  const mean = Number(await overlay.getByTestId('df-mean').textContent());
  expect(mean).toBeGreaterThan(0.1);
  expect(mean).toBeLessThan(20);
  const min = Number(await overlay.getByTestId('df-min').textContent());
  expect(min).toBeLessThanOrEqual(mean);
  await expect(overlay.getByTestId('df-shareAbove2')).toContainText('%');

  // The cell by the window against the cell in the far corner, read from the screen.
  const layer = page.getByTestId('df-plan-layer');
  const [x, y, width, height] = await Promise.all(['data-x', 'data-y', 'data-width', 'data-height'].map(async (a) => Number(await layer.getAttribute(a))));
  const room = await roomWindow(page);
  const [a, b] = [room.outline[room.wall], room.outline[(room.wall + 1) % room.outline.length]];
  const length = Math.hypot(b[0] - a[0], b[1] - a[1]);
  const t = (room.offset + room.width / 2) / length;
  const centre: [number, number] = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
  const cell = 0.125;
  const clamp = (v: number, lo: number, hi: number) => Math.min(hi - cell, Math.max(lo + cell, v));
  const byWindow: [number, number] = [clamp(centre[0], x, x + width), clamp(centre[1], y, y + height)];
  const far: [number, number] = [centre[0] < x + width / 2 ? x + width - cell : x + cell, centre[1] < y + height / 2 ? y + height - cell : y + cell];
  const toPage = await planToPage(page);
  const shot = PNG.sync.read(await page.screenshot());
  const pixel = (p: [number, number]) => {
    const [px, py] = toPage(p).map(Math.round);
    const k = 4 * (py * shot.width + px);
    return [shot.data[k], shot.data[k + 1], shot.data[k + 2]];
  };
  const [near, corner] = [scalePosition(pixel(byWindow)), scalePosition(pixel(far))];
  console.info(`DF plan: mean ${mean} %, legend position by the window ${near}, in the far corner ${corner}`);
  expect(near).toBeGreaterThan(corner);

  // A window twice as wide, set in the room-shape editor (the card hidden meanwhile): the map follows, a brighter room, fitted below the card again.
  await page.getByTestId('edit-room-shape').click();
  await expect(overlay).toBeHidden();
  await page.getByTestId('room-opening-0').click();
  await page.getByTestId('room-opening-width').fill('3');
  await page.getByTestId('room-opening-width').press('Enter');
  await page.getByTestId('room-shape-done').click();
  await expect(overlay).toBeVisible();
  await expect.poll(async () => Number(await overlay.getByTestId('df-mean').textContent()), { timeout: 25_000, intervals: [250] }).toBeGreaterThan(1.3 * mean);
  await expect(overlay).toHaveAttribute('data-phase', 'ready');
  console.info(`DF plan, the window 3 m wide: mean ${await overlay.getByTestId('df-mean').textContent()} %`);
  const card = (await page.getByTestId('df-plan-card').boundingBox())!;
  expect((await layer.boundingBox())!.y).toBeGreaterThanOrEqual(card.y + card.height);

  // Off: the layer and the card go, the plan stays.
  await dfToggle.click();
  await expect(layer).toHaveCount(0);
  await expect(page.getByTestId('df-plan-card')).toHaveCount(0);
});

for (const [device, viewport] of [
  ['phone', { width: 390, height: 844 }],
  ['tablet', { width: 820, height: 1180 }],
  ['desktop', { width: 1440, height: 900 }],
] as const) {
  test(`the daylight-factor map on a ${device} in four languages (screenshots)`, async ({ page }) => {
    test.setTimeout(45_000);
    await page.setViewportSize(viewport);
    await daylitRoom(page);
    await page.getByTestId('df-plan-toggle').click();
    await expect(page.getByTestId('df-plan')).toHaveAttribute('data-phase', 'ready', { timeout: 30_000 });
    for (const language of ['en', 'de', 'fr', 'it']) {
      if (language !== 'en') {
        await page.getByTestId('language-switch').selectOption(language);
        await expect(page.locator('.app')).toHaveAttribute('lang', new RegExp(`^${language}`));
      }
      // The card stays inside the plan and leaves the zoom buttons free.
      const card = (await page.getByTestId('df-plan-card').boundingBox())!;
      const plan = (await page.getByTestId('plan').boundingBox())!;
      const zoom = (await page.getByTestId('zoom-in').boundingBox())!;
      expect(card.x + card.width).toBeLessThanOrEqual(Math.min(plan.x + plan.width, zoom.x));
      expect(card.y + card.height).toBeLessThanOrEqual(plan.y + plan.height);
      // ... and the room is fitted below it: the map starts under the card.
      const map = (await page.getByTestId('df-plan-layer').boundingBox())!;
      expect(map.y).toBeGreaterThanOrEqual(card.y + card.height);
      await page.screenshot({ path: `test-results/daylight-plan/${device}-${language}.png` });
    }
  });
}
