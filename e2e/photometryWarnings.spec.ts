import { readFileSync } from 'node:fs';
import { expect, test, type Page } from '@playwright/test';
import { footprintsReady, zoomToModuleLevel } from './helpers';

/**
 * Photometry warnings in the UI (issue 18, docs/planner.md): the catalog's own files have none,
 * so the narrow spot's file is served as a fixture whose stated lumens disagree with its
 * candela data (tests/fixtures/photometry/lumens_mismatch_60x.ies). The module options and the
 * 3D view show the warning as a small note; screenshots at phone and desktop size go to the
 * test's output folder (test-results/) for review, they are not goldens.
 */
const fixture = readFileSync(new URL('../tests/fixtures/photometry/lumens_mismatch_60x.ies', import.meta.url));
const WARNING = 'stated lumens 34 lm and integrated flux 2047 lm differ by 5921 % (ratio 60.21); the integrated flux of the candela data is used';

test.use({ reducedMotion: 'reduce' });

const SIZES = { phone: { width: 375, height: 667 }, desktop: { width: 1440, height: 900 } } as const;

async function singleWithOddSpot(page: Page) {
  await page.route('**/ies/bega_84693_narrow_spot.ies', (route) => route.fulfill({ status: 200, contentType: 'application/octet-stream', body: fixture }));
  await page.goto('/?expert=1'); // photometric data notes are an expert tool
  await page.getByRole('button', { name: 'Start planning' }).click();
  if (await page.getByRole('button', { name: 'Presets' }).isVisible()) await page.getByRole('button', { name: 'Presets' }).click();
  await page.getByTestId('preset-single').click();
  await expect(page.getByTestId('plan')).toBeVisible();
  await footprintsReady(page);
}

for (const [name, viewport] of Object.entries(SIZES)) {
  test(`a file's warnings in the module options and the 3D view at ${name} size`, async ({ page }, testInfo) => {
    await page.setViewportSize(viewport);
    await singleWithOddSpot(page);
    if (await page.getByRole('button', { name: 'Close', exact: true }).isVisible()) await page.getByRole('button', { name: 'Close', exact: true }).click();
    await zoomToModuleLevel(page);
    await page.locator('[data-testid^="module-"] button').first().click();
    const note = page.getByTestId('module-photometry-warnings');
    await expect(note).toBeVisible();
    await expect(page.getByRole('note', { name: 'Photometric data warnings' })).toHaveCount(1);
    // The file as the catalog names it (the module's data, whatever was served).
    await expect(note).toContainText('bega_84693_narrow_spot.ies');
    await expect(note.locator('li')).toHaveText([WARNING]);
    await note.scrollIntoViewIfNeeded();
    await page.screenshot({ path: testInfo.outputPath(`options-${name}.png`) });

    // On a phone the options are in the drawer, over the bottom bar: close it first.
    if (await page.getByRole('button', { name: 'Close', exact: true }).isVisible()) await page.getByRole('button', { name: 'Close', exact: true }).click();
    await page.getByTestId('tool-3d').click();
    const view = page.getByTestId('view3d-photometry-warnings');
    // Collapsed to one line under the controls; it opens to the text.
    await expect(view).toBeVisible();
    await expect(view.locator('summary')).toHaveText('⚠ Photometric data: 1 warning');
    await expect(view.locator('li')).toBeHidden();
    await expect.poll(() => page.evaluate(() => window.luxbox!.view3d().lit), { timeout: 90_000 }).toBe(true);
    await page.screenshot({ path: testInfo.outputPath(`view3d-${name}.png`) });
    await view.scrollIntoViewIfNeeded();
    await page.screenshot({ path: testInfo.outputPath(`view3d-collapsed-${name}.png`) });
    await view.locator('summary').click();
    await expect(view.locator('li')).toHaveText([WARNING]);
    await view.scrollIntoViewIfNeeded();
    await page.screenshot({ path: testInfo.outputPath(`view3d-note-${name}.png`) });
  });
}
