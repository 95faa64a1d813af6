import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { readFile } from 'node:fs/promises';
import { strFromU8, unzipSync } from 'fflate';
import { tmpdir } from 'node:os';
import { join, normalize } from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import { gldfBytes, linearSpec, MAPPING_TEXT, pendantSpec, trackSpotSpec } from '../tests/core/gldf/buildGldf';
import { sceneFile } from './helpers';

// A catalog folder made by `luxbox catalog import` from the three test GLDF products (tests/core/gldf/buildGldf.ts)
// loads in the app like the demo's (docs/gldf.md): `?catalog=` hands its JSON to the embedding API's `catalog`
// option and its folder to `assetBase`. The folder lives in a temp directory, served to the page by route(),
// so nothing is generated into public/.

let folder = '';

test.beforeAll(() => {
  const dir = mkdtempSync(join(tmpdir(), 'luxbox-e2e-gldf-'));
  const write = (name: string, bytes: Uint8Array | string): string => {
    writeFileSync(join(dir, name), bytes);
    return join(dir, name);
  };
  folder = join(dir, 'shop');
  const r = spawnSync(
    process.execPath,
    [
      'bin/luxbox.js',
      'catalog',
      'import',
      write('track-spot.gldf', gldfBytes(trackSpotSpec())),
      write('pendant.gldf', gldfBytes(pendantSpec())),
      write('linear.gldf', gldfBytes(linearSpec())),
      '--into',
      'src/core/catalog/default-catalog.json',
      '--assets',
      'public',
      '--mapping',
      write('mapping.json', MAPPING_TEXT),
      '--out',
      folder,
    ],
    { encoding: 'utf8' },
  );
  expect(r.stderr).toBe('');
  expect(r.status).toBe(0);
});

test.afterAll(() => {
  if (folder) rmSync(join(folder, '..'), { recursive: true, force: true });
});

/** Serves the catalog folder under /gldf-shop/ and lists what was asked for. */
async function serveFolder(page: Page): Promise<string[]> {
  const served: string[] = [];
  // By path: the page's own URL names the folder in its query.
  await page.route(
    (url) => url.pathname.startsWith('/gldf-shop/'),
    async (route) => {
      const path = normalize(decodeURIComponent(new URL(route.request().url()).pathname.replace(/^\/gldf-shop\//, '')));
      const file = join(folder, path);
      if (path.startsWith('..') || !existsSync(file)) return route.fulfill({ status: 404, body: 'not found' });
      served.push(path);
      await route.fulfill({ body: readFileSync(file), contentType: path.endsWith('.json') ? 'application/json' : 'text/plain' });
    },
  );
  return served;
}

test('an imported GLDF catalog folder: a track spot on the rail in German, priced in the BOM, lit in 3D by its own photometry', async ({ page }) => {
  const served = await serveFolder(page);
  const warnings: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'warning') warnings.push(m.text());
  });
  await page.goto('/?catalog=/gldf-shop/catalog.json&lang=de&quality=balanced');
  await page.getByRole('button', { name: 'Planung beginnen' }).click();
  await page.getByTestId('preset-single').click();
  const railId = (await sceneFile(page)).configuration.systems[0].rails[0].id;
  const added = await page.evaluate((id) => window.luxbox!.runAction('addModule', { railId: id, type: 'track-spot' }), railId);
  expect(added).toMatchObject({ ok: true });

  // The plan draws it as its L3D body's outline from above (the convex hull; docs/gldf.md "L3D in the plan"), loaded from the folder.
  const spotId = (await sceneFile(page)).configuration.systems[0].rails[0].modules.find((m) => m.type === 'track-spot')!.id;
  const symbol = page.locator(`[data-module-id="${spotId}"][data-module-outline="model"]`);
  await expect(symbol).toHaveCount(1);
  // A hull of the yoke, head and barn door: more than the rectangle's four corners.
  expect((await symbol.getAttribute('points'))!.trim().split(/\s+/).length).toBeGreaterThan(4);

  // The GLDF's German Locale texts name the module; the mapping's price and the article number the import made.
  const bom = page.getByTestId('bom');
  await expect(bom).toContainText('Schienenstrahler, Mittlerer Spot, 3000 K');
  const line = await page.evaluate(() => window.luxbox!.getBillOfMaterials().lines.find((l) => l.article === 'LTL-TS-M-3000'));
  expect(line).toMatchObject({ count: 1, unitPrice: 189 });
  await expect(bom.locator('tr', { hasText: 'Schienenstrahler, Mittlerer Spot, 3000 K' })).toContainText('189,00');

  // 3D: the bake runs with the imported photometry, fetched from the folder (assetBase).
  await page.getByTestId('tool-3d').click();
  await expect.poll(() => page.evaluate(() => window.luxbox!.view3d().lit), { timeout: 90_000, intervals: [250] }).toBe(true);
  expect(served).toContain('catalog.json');
  expect(served).toContain('ies/track-spot-medium.ldt');
  // Its L3D body (catalog `model`), fetched from the folder and read: no "drawn as its kind" fallback.
  expect(served).toContain('geo/track-spot.l3d');
  expect(warnings.filter((w) => w.includes('luminaire body'))).toEqual([]);
  // What was baked: the lighting scene names the imported beam's photometry and its rated flux.
  const scene = await page.evaluate(() => JSON.stringify(window.luxbox!.getLightingScene()));
  expect(scene).toContain('"ies/track-spot-medium.ldt"');
});

test('Download for Radiance writes the imported spot’s L3D body as polygons of a grey plastic', async ({ page }) => {
  await serveFolder(page);
  await page.goto('/?catalog=/gldf-shop/catalog.json&lang=en&expert=1');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-single').click();
  const railId = (await sceneFile(page)).configuration.systems[0].rails[0].id;
  expect(await page.evaluate((id) => window.luxbox!.runAction('addModule', { railId: id, type: 'track-spot' }), railId)).toMatchObject({ ok: true });
  const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId('download-radiance').click()]);
  const files = unzipSync(new Uint8Array(await readFile(await download.path())));
  const rad = strFromU8(files[Object.keys(files).find((f) => f.endsWith('/scene.rad'))!]);
  expect(rad).toContain('void plastic luminaire_body');
  // The test spot: 156 triangles less the 24 of the head's bottom cap (tests/engines/radiance/bodiesRad.test.ts).
  expect(rad.match(/^luminaire_body polygon /gm)).toHaveLength(132);
});

test('the demo shop page (embed.html) opens the same folder with ?catalog=: the imported spot in its bill of materials, drawn as its L3D outline', async ({ page }) => {
  const served = await serveFolder(page);
  await page.goto('/embed.html?catalog=/gldf-shop/catalog.json');
  await expect.poll(() => page.evaluate(() => window.shopDemo?.instance !== null && window.shopDemo?.instance !== undefined)).toBe(true);
  await page.evaluate(() => window.shopDemo!.instance!.whenReady());
  expect(await page.evaluate(() => window.shopDemo!.instance!.runAction('placePreset', { presetId: 'single' }))).toMatchObject({ ok: true });
  const railId = await page.evaluate(() => JSON.parse(window.shopDemo!.instance!.getConfig()).configuration.systems[0].rails[0].id as string);
  expect(await page.evaluate((id) => window.shopDemo!.instance!.runAction('addModule', { railId: id, type: 'track-spot' }), railId)).toMatchObject({ ok: true });
  const line = await page.evaluate(() => window.shopDemo!.instance!.getBillOfMaterials().lines.find((l) => l.article === 'LTL-TS-M-3000'));
  expect(line).toMatchObject({ count: 1, unitPrice: 189 });
  expect(served).toContain('catalog.json');
  await expect(page.locator('[data-module-outline="model"]')).toHaveCount(1);
  expect(served).toContain('geo/track-spot.l3d');
});
