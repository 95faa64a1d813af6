import { test, expect } from '@playwright/test';

test('the built app shows its first screen', async ({ page }) => {
  await page.goto('/');
  await expect(page.getByRole('heading', { name: 'luxbox' })).toBeVisible();
});
