import { readFileSync } from 'node:fs';
import { expect, test, type Page } from '@playwright/test';

/**
 * A room of any shape arriving at startup (issue 29; docs/architecture.md "The room-shape chunk"):
 * the shape's model is a lazy chunk, so the configurator waits for it before it opens a saved or
 * shared configuration with a shape; the shopper's room opens shaped, never refused or as a box,
 * and the autosave keeps it. A box room never fetches the chunk.
 */
const SHAPED = readFileSync('tests/fixtures/formats/configuration-v9.luxbox.json', 'utf8');
const shape = JSON.parse(SHAPED).configuration.room.shape as { outline: [number, number][]; openings: unknown[] };

const shownRoom = async (page: Page) => JSON.parse(await page.evaluate(() => window.luxbox!.getConfig())).configuration.room;
const chunkFetched = (page: Page) => page.evaluate(() => performance.getEntriesByType('resource').some((r) => /roomShapeChunk/.test(r.name)));

test.use({ reducedMotion: 'reduce', viewport: { width: 1440, height: 900 } });

test('a shaped room in the autosave opens shaped and stays saved', async ({ page }) => {
  await page.goto('/');
  await page.evaluate((text) => {
    localStorage.clear();
    localStorage.setItem('luxbox.autosave.v1', text);
  }, SHAPED);
  await page.reload();
  await expect(page.getByTestId('plan')).toBeVisible();
  await expect.poll(async () => (await shownRoom(page)).shape?.outline).toEqual(shape.outline);
  await expect(page.getByTestId('plan-svg').locator('[data-opening-kind]')).toHaveCount(shape.openings.length);
  expect(await chunkFetched(page)).toBe(true);
  // The autosave still holds the shape (nothing overwrote it while the chunk loaded).
  const saved = JSON.parse((await page.evaluate(() => localStorage.getItem('luxbox.autosave.v1')))!);
  expect(saved.configuration.room.shape.outline).toEqual(shape.outline);
});

test('a share link with a shaped room opens shaped', async ({ page }) => {
  // A fresh context: no autosave. (A hash change on an open page is no new start.)
  const encoded = Buffer.from(JSON.stringify(JSON.parse(SHAPED)), 'utf8').toString('base64url');
  await page.goto(`/#c=${encoded}`);
  await expect(page.getByTestId('plan')).toBeVisible();
  await expect.poll(async () => (await shownRoom(page)).shape?.outline).toEqual(shape.outline);
  await expect(page.getByTestId('plan-svg').locator('[data-opening-kind]')).toHaveCount(shape.openings.length);
  await expect(page.getByTestId('banner')).toHaveCount(0);
});

test('a box room never fetches the room-shape chunk', async ({ page }) => {
  await page.goto('/');
  await page.evaluate(() => localStorage.clear());
  await page.reload();
  await page.locator('input[name=width]').fill('5');
  await page.locator('input[name=depth]').fill('4');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await expect(page.getByTestId('plan')).toBeVisible();
  expect(await chunkFetched(page)).toBe(false);
});

test('a share link of version 1 (its steps ride in the same chunk) opens as the frozen expected file', async ({ page }) => {
  const link = readFileSync('tests/fixtures/formats/share-link-v1.txt', 'utf8').trim();
  const expected = JSON.parse(readFileSync('tests/fixtures/formats/expected/share-link-v1.luxbox.json', 'utf8'));
  await page.goto(`/#c=${link}`);
  await expect(page.getByTestId('plan')).toBeVisible();
  await expect.poll(async () => JSON.parse(await page.evaluate(() => window.luxbox!.getConfig())).configuration.systems.length).toBe(expected.configuration.systems.length);
  expect(JSON.parse(await page.evaluate(() => window.luxbox!.getConfig()))).toEqual(expected);
  expect(await chunkFetched(page)).toBe(true);
});
