import { expect, test, type Page } from '@playwright/test';

test.use({ reducedMotion: 'reduce', viewport: { width: 1440, height: 900 } });

type Reflectances = Record<'floor' | 'ceiling' | 'north' | 'south' | 'west' | 'east', number | number[]>;

/** The room reflectances the baker would get, read through the embedding API. */
async function bakedReflectance(page: Page): Promise<Reflectances> {
  return page.evaluate(() => (window.luxbox!.getLightingScene() as { room: { reflectance: Reflectances } }).room.reflectance);
}

// Values from src/core/catalog/surface-finishes.json.
const SAGE = [0.402, 0.476, 0.335];
const SLATE = [0.089, 0.101, 0.12];

test('choose finishes on setup and in the Surfaces panel; undo, redo, reload keep them', async ({ page }) => {
  await page.goto('/');
  await page.evaluate(() => localStorage.clear());
  await page.reload();
  await page.getByTestId('setup-finish-walls').selectOption({ label: 'Sage green paint — reflects 45%' });
  await page.getByRole('button', { name: 'Start planning' }).click();
  await expect(page.getByTestId('plan')).toBeVisible();
  expect(await bakedReflectance(page)).toEqual({ floor: 0.2, ceiling: 0.8, north: SAGE, south: SAGE, west: SAGE, east: SAGE });

  // A dark floor from the side panel: one undoable action, the plan's floor takes its tint.
  const floor = page.getByTestId('finish-floor');
  await floor.selectOption('dark-slate');
  await expect.poll(async () => (await bakedReflectance(page)).floor).toEqual(SLATE);
  await expect(page.getByTestId('plan-floor')).toHaveAttribute('fill', '#e5e6e7');
  await expect(page.getByTestId('finish-walls')).toHaveValue('sage-green');

  await page.getByTestId('tool-undo').click();
  await expect.poll(async () => (await bakedReflectance(page)).floor).toBe(0.2);
  await expect(floor).toHaveValue('grey-carpet');
  await page.getByTestId('tool-redo').click();
  await expect.poll(async () => (await bakedReflectance(page)).floor).toEqual(SLATE);

  // One wall on its own: the walls picker says "Mixed".
  await page.getByText('Walls one by one').click();
  await page.getByTestId('finish-east').selectOption('white-paint');
  await expect.poll(async () => (await bakedReflectance(page)).east).toBe(0.8);
  await expect(page.getByTestId('finish-walls').locator('option:checked')).toHaveText('Mixed (per wall)');

  // Reload: the autosave restores the finishes.
  await page.reload();
  await expect(page.getByTestId('plan')).toBeVisible();
  expect(await bakedReflectance(page)).toEqual({ floor: SLATE, ceiling: 0.8, north: SAGE, south: SAGE, west: SAGE, east: 0.8 });
  await expect(page.getByTestId('finish-floor')).toHaveValue('dark-slate');
});
