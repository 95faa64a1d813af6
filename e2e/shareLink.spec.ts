import { expect, test } from '@playwright/test';
import { sceneFile } from './helpers';

test.use({ reducedMotion: 'reduce' });

test('a share link restores the configuration in a fresh browser', async ({ page, browser }) => {
  await page.goto('/');
  await page.getByRole('button', { name: 'Try the demo' }).click();
  await page.getByTestId('preset-single').click();
  const original = await sceneFile(page);
  const link = await page.evaluate(() => window.luxbox!.getShareLink());
  expect(link).toContain('#c=');

  const other = await browser.newContext({ reducedMotion: 'reduce' });
  const p2 = await other.newPage();
  // Same server as the first page (the port follows LUXBOX_E2E_PORT).
  await p2.goto(link.replace(/^https?:\/\/[^/]+/, new URL(page.url()).origin));
  await expect(p2.getByTestId('plan')).toBeVisible();
  expect(await sceneFile(p2)).toEqual(original);
  // The link was consumed: the address bar no longer carries it.
  expect(await p2.evaluate(() => location.hash)).toBe('');
  await other.close();
});

test('a broken link shows a message and an empty valid room, and keeps the autosave', async ({ page }) => {
  await page.goto('/');
  await page.getByRole('button', { name: 'Try the demo' }).click();
  const saved = await page.evaluate(() => localStorage.getItem('luxbox.autosave.v1'));
  expect(saved).toContain('luxbox-configuration');

  await page.goto('/#c=this-is-not-a-configuration');
  await page.reload();
  const banner = page.getByTestId('banner');
  await expect(banner).toContainText('This link could not be opened');
  await expect(page.getByTestId('plan')).toBeVisible();
  const shown = await sceneFile(page);
  expect(shown.configuration.systems).toHaveLength(0);
  expect(await page.evaluate(() => localStorage.getItem('luxbox.autosave.v1'))).toBe(saved);

  await banner.getByRole('button', { name: 'Open my saved configuration' }).click();
  await expect(banner).toHaveCount(0);
  expect((await sceneFile(page)).configuration.systems).toHaveLength(1);
});

test('a foreign link (a lighting scene, not a configuration) is refused with a clear message', async ({ page }) => {
  const scene = JSON.stringify({ version: 1, room: { width: 5, height: 2.8, depth: 4 }, luminaires: [] });
  const encoded = Buffer.from(scene).toString('base64url');
  await page.goto(`/#c=${encoded}`);
  await expect(page.getByTestId('banner')).toContainText('lighting scene');
  expect((await sceneFile(page)).configuration.systems).toHaveLength(0);
  await expect(page.getByTestId('banner').getByRole('button', { name: 'Open my saved configuration' })).toHaveCount(0);
});
