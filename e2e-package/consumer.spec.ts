// The packed package in a shop's pages (scripts/checkPackage.mjs builds them): a React app with
// <Luxbox> from `luxbox/react`, and a plain page with <luxbox-configurator> from the single-file
// script. Each mounts, places a preset, bakes in 3D and reads the bill of materials, which must
// equal what the repository's model gives (e2e-package/expectedBom.ts).
import { expect, test, type Page } from '@playwright/test';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

interface Bom {
  total: number;
  currency: string;
  lines: { count: number; article: string }[];
}
interface Instance {
  runAction(name: string, params: unknown): { ok: boolean };
  getBillOfMaterials(): Bom;
  view3d(): { done: boolean; floor: { avg: number } | null; error: string | null };
}
type Pages = Window & { shop?: { instance: Instance | null; errors: string[] }; elementPage?: { errors: string[]; boms: number } };

const expected: { total: number; currency: string; articles: string[] } = JSON.parse(readFileSync(join(process.env.LUXBOX_CONSUMER_DIR!, 'expected-bom.json'), 'utf8'));
const expectedTotal = `${expected.total.toFixed(2)} ${expected.currency}`;

function collectErrors(page: Page): string[] {
  const errors: string[] = [];
  page.on('pageerror', (e) => errors.push(e.message));
  // A failed request is recorded with its URL by the response handler; the console's line for it has none.
  page.on('console', (m) => {
    if (m.type() === 'error' && !m.text().startsWith('Failed to load resource')) errors.push(m.text());
  });
  page.on('response', (r) => {
    if (r.status() >= 400) errors.push(`${r.status()} ${r.url()}`);
  });
  return errors;
}

/** Opens the 3D view and waits for the progressive bake to finish ('fast' quality); returns the floor's mean illuminance. */
async function bakeIn3d(page: Page, status: () => Promise<ReturnType<Instance['view3d']>>): Promise<number> {
  await page.getByTestId('tool-3d').click();
  await expect(page.getByTestId('view3d-canvas')).toBeVisible();
  await expect.poll(async () => (await status()).done, { timeout: 150_000, intervals: [500] }).toBe(true);
  const done = await status();
  expect(done.error).toBeNull();
  return done.floor!.avg;
}

test('React app: <Luxbox> from luxbox/react mounts on the shop’s React, places a preset, bakes, and its bill of materials is the model’s', async ({ page }) => {
  const errors = collectErrors(page);
  await page.goto('/index.html');
  await expect(page.getByTestId('plan')).toBeVisible();
  // The German storefront (locale de-CH): the configurator's texts are German.
  await expect(page.getByTestId('tool-3d')).toContainText('3D-Ansicht');
  // Rendered by the shop's React (a React root marks its container), not by a bundled preact.
  expect(await page.evaluate(() => Object.keys(document.querySelector('.luxbox')!).some((k) => k.startsWith('__reactContainer$')))).toBe(true);

  await page.getByTestId('shop-place-single').click();
  await expect(page.getByTestId('shop-total')).toHaveText(expectedTotal);
  const bom = await page.evaluate(() => (window as Pages).shop!.instance!.getBillOfMaterials());
  expect(bom.lines.map((l) => `${l.count}×${l.article}`)).toEqual(expected.articles);

  const floorLux = await bakeIn3d(page, () => page.evaluate(() => (window as Pages).shop!.instance!.view3d()));
  expect(floorLux).toBeGreaterThan(0);
  expect(await page.evaluate(() => (window as Pages).shop!.errors)).toEqual([]);
  expect(errors).toEqual([]);
});

test('plain page: <luxbox-configurator> from the single-file script mounts on its own preact, places a preset, bakes, and its events carry the model’s bill of materials', async ({ page }) => {
  const errors = collectErrors(page);
  await page.goto('/element.html');
  await expect(page.getByTestId('plan')).toBeVisible();
  await expect(page.getByTestId('tool-3d')).toContainText('3D-Ansicht');
  // No React on this page: the script's own runtime (preact marks the container it renders into with __k).
  expect(await page.evaluate(() => '__k' in document.querySelector('.luxbox')!)).toBe(true);

  const placed = await page.evaluate(() => (document.getElementById('configurator') as unknown as { instance: Instance }).instance.runAction('placePreset', { presetId: 'single' }));
  expect(placed.ok).toBe(true);
  await expect(page.getByTestId('element-total')).toHaveText(expectedTotal);
  const bom = await page.evaluate(() => (document.getElementById('configurator') as unknown as { instance: Instance }).instance.getBillOfMaterials());
  expect(bom.lines.map((l) => `${l.count}×${l.article}`)).toEqual(expected.articles);

  const floorLux = await bakeIn3d(page, () => page.evaluate(() => (document.getElementById('configurator') as unknown as { instance: Instance }).instance.view3d()));
  expect(floorLux).toBeGreaterThan(0);
  expect(await page.evaluate(() => (window as Pages).elementPage!.errors)).toEqual([]);
  expect(errors).toEqual([]);
});
