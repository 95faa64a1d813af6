import { expect, test } from '@playwright/test';
import { footprintsReady, sceneFile, zoomToModuleLevel } from './helpers';

test.use({ reducedMotion: 'reduce', viewport: { width: 1440, height: 900 } });

// Issue #12, colour filters: pick a gel for a spot, see its colour and numbers, the price and the plan follow.
test('a spot takes a colour filter: readout, search, BOM line, plan tint, saved', async ({ page }) => {
  await page.goto('/');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-single').click();
  await footprintsReady(page);
  await zoomToModuleLevel(page);
  const moduleId = (await sceneFile(page)).configuration.systems[0].rails[0].modules[0].id;
  await page.getByTestId(`module-${moduleId}`).getByRole('button').click();
  const picker = page.getByTestId('filter-picker');
  await expect(picker).toBeVisible();
  await expect(picker.getByTestId('filter-readout')).toContainText('Unfiltered, 3000 K');
  await expect(picker.getByTestId('filter-none')).toHaveAttribute('aria-pressed', 'true');

  // Search narrows the list to the full CTO.
  await picker.getByTestId('filter-search').fill('204');
  await expect(picker.locator('[data-testid^="filter-lee-"]')).toHaveCount(1);
  await picker.getByTestId('filter-lee-204').click();
  await expect(picker.getByTestId('filter-lee-204')).toHaveAttribute('aria-pressed', 'true');
  await expect(picker.getByTestId('filter-readout')).toContainText('LEE 204 Full C.T. Orange');
  await expect(picker.getByTestId('filter-readout')).toContainText(/Transmission 62\.6%/);
  await expect(picker.getByTestId('filter-readout')).toContainText(/CCT 2,0\d\d K/);
  expect((await sceneFile(page)).configuration.systems[0].rails[0].modules[0]).toMatchObject({ filter: 'lee-204' });
  await expect(page.getByTestId('bom')).toContainText('LX-GEL-204');

  // The plan's footprint of that module takes the filtered light's colour.
  const swatch = await picker.getByTestId('filter-swatch').getAttribute('data-colour');
  await expect(page.locator(`[data-footprint-for="${moduleId}"]`)).toHaveAttribute('fill', swatch!);

  // No filter again.
  await picker.getByTestId('filter-none').click();
  expect('filter' in (await sceneFile(page)).configuration.systems[0].rails[0].modules[0]).toBe(false);
});

// The spectra are not part of the first screen (docs/colour-filters.md, "Two files"): a plan without
// filters never fetches them; a filter set through the embedding API fetches them, whenReady() waits
// for them, and the lighting scene then carries the filtered colour (LEE 106 Primary Red: red ≫ green).
test('the filter spectra load only when a filter is used; whenReady() before getLightingScene', async ({ page }) => {
  const spectraRequests: string[] = [];
  page.on('request', (r) => {
    if (/colour-filter-spectra|parseColourFilterSpectra/.test(r.url())) spectraRequests.push(r.url());
  });
  await page.goto('/');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-single').click();
  await footprintsReady(page);
  expect(spectraRequests).toEqual([]);
  const result = await page.evaluate(async () => {
    const lx = window.luxbox!;
    const moduleId = (JSON.parse(lx.getConfig()) as { configuration: { systems: { rails: { modules: { id: string }[] }[] }[] } }).configuration.systems[0].rails[0].modules[0].id;
    const set = lx.runAction('setModuleFilter', { moduleId, filter: 'lee-106' });
    await lx.whenReady();
    const scene = lx.getLightingScene() as { luminaires: { id?: string; color?: number[] }[] };
    return { set, color: scene.luminaires.find((l) => l.id === moduleId)?.color };
  });
  expect(result.set).toEqual({ ok: true });
  expect(spectraRequests.length).toBeGreaterThan(0);
  const [r, g] = result.color!;
  expect(r).toBeGreaterThan(10 * g);
});
