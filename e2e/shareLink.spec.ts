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

// Issue #27, "Share": a copy button with a short confirmation, and the system share sheet where the browser has one.
test.describe('copy and share the link', () => {
  test.use({ permissions: ['clipboard-read', 'clipboard-write'] });

  test('desktop, English: Copy puts the link on the clipboard and says so', async ({ page }) => {
    await page.goto('/');
    await page.getByRole('button', { name: 'Try the demo' }).click();
    await page.getByTestId('share').click();
    const link = await page.getByTestId('share-link').inputValue();
    expect(link).toContain('#c=');
    // No Web Share API in desktop Chromium here: no Share… button.
    await expect(page.getByTestId('share-native')).toHaveCount(0);
    await page.evaluate(() => navigator.clipboard.writeText('something else'));
    await page.getByTestId('share-copy').click();
    await expect(page.getByTestId('share-status')).toHaveText('Link copied.');
    expect(await page.evaluate(() => navigator.clipboard.readText())).toBe(link);
  });

  test('phone with touch, German: one tap on Link teilen opens the share sheet with the link; Teilen… again', async ({ browser }) => {
    const context = await browser.newContext({ viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true, permissions: ['clipboard-read', 'clipboard-write'] });
    const page = await context.newPage();
    // A phone's Web Share API, recorded (headless Chromium on Linux has none).
    await page.addInitScript(() => {
      const calls: ShareData[] = [];
      (window as unknown as { shareCalls: ShareData[] }).shareCalls = calls;
      Object.defineProperty(navigator, 'share', { value: async (data: ShareData) => void calls.push(data), configurable: true });
    });
    await page.goto('/?lang=de');
    await page.getByRole('button', { name: 'Demo ausprobieren' }).click();
    await page.getByRole('button', { name: 'Vorlagen', exact: true }).click();
    // One tap on "Link teilen" opens the share sheet with the link (issue 27); Teilen… opens it again.
    await page.getByTestId('share').tap();
    const link = await page.getByTestId('share-link').inputValue();
    expect(await page.evaluate(() => (window as unknown as { shareCalls: ShareData[] }).shareCalls)).toEqual([{ url: link }]);
    await page.getByTestId('share-native').tap();
    await expect(page.getByTestId('share-status')).toHaveText('Link geteilt.');
    expect(await page.evaluate(() => (window as unknown as { shareCalls: ShareData[] }).shareCalls)).toEqual([{ url: link }, { title: 'Meine Lichtplanung', url: link }]);
    await page.getByTestId('share-copy').tap();
    await expect(page.getByTestId('share-status')).toHaveText('Link kopiert.');
    await context.close();
  });
});
