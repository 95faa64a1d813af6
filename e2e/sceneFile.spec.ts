import { readFile } from 'node:fs/promises';
import { expect, test } from '@playwright/test';
import { strFromU8, unzipSync } from 'fflate';
import { sceneFile } from './helpers';

test.use({ reducedMotion: 'reduce' });

test('Save file, New room, Open file restores the configuration; Undo returns to the empty room', async ({ page }) => {
  await page.goto('/');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-single').click();
  const original = await sceneFile(page);
  expect(original.configuration.systems).toHaveLength(1);

  const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId('save-file').click()]);
  expect(download.suggestedFilename()).toBe('luxbox-5x4x2.8.luxbox.json');
  const savedPath = await download.path();
  const savedText = await readFile(savedPath, 'utf8');
  // Pretty-printed and the same document the embedding API returns.
  expect(savedText).toContain('\n  "format": "luxbox-configuration"');
  expect(JSON.parse(savedText)).toEqual(original);

  await page.getByRole('button', { name: 'New room' }).click();
  await page.getByRole('button', { name: 'Start planning' }).click();
  const empty = await sceneFile(page);
  expect(empty.configuration.systems).toHaveLength(0);

  await page.getByTestId('open-file').setInputFiles(savedPath);
  await expect(page.getByTestId('status-line')).toContainText('Opened');
  expect(await sceneFile(page)).toEqual(original);

  await page.getByTestId('tool-undo').click();
  expect(await sceneFile(page)).toEqual(empty);
});

test('a corrupt or foreign file is refused with a message naming it; the configuration is unchanged', async ({ page }) => {
  await page.goto('/');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-single').click();
  const before = await sceneFile(page);
  const full = JSON.stringify(before, null, 2);
  const banner = page.getByTestId('banner');

  await page.getByTestId('open-file').setInputFiles({ name: 'truncated.luxbox.json', mimeType: 'application/json', buffer: Buffer.from(full.slice(0, 200)) });
  await expect(banner).toContainText('“truncated.luxbox.json” is not valid JSON');
  expect(await sceneFile(page)).toEqual(before);
  await banner.getByRole('button', { name: 'Dismiss message' }).click();
  await expect(banner).toHaveCount(0);

  await page.getByTestId('open-file').setInputFiles({ name: 'package.json', mimeType: 'application/json', buffer: Buffer.from('{"name":"shop","version":"1.0.0"}') });
  await expect(banner).toContainText('“package.json” is not a luxbox configuration');
  expect(await sceneFile(page)).toEqual(before);
  // Nothing was added to the history: Undo still removes the placed preset.
  await page.getByTestId('tool-undo').click();
  expect((await sceneFile(page)).configuration.systems).toHaveLength(0);
});

test('Open file… is reachable by keyboard and 44 px tall in the phone drawer', async ({ page }) => {
  await page.setViewportSize({ width: 375, height: 667 });
  await page.goto('/');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByRole('button', { name: 'Presets' }).click();
  const save = page.getByTestId('save-file');
  const open = page.locator('label.file-button');
  for (const el of [save, open]) {
    await el.scrollIntoViewIfNeeded();
    const box = await el.boundingBox();
    expect(box?.height ?? 0).toBeGreaterThanOrEqual(44);
    expect(box?.width ?? 0).toBeGreaterThanOrEqual(44);
  }
  await save.focus();
  await page.keyboard.press('Tab');
  await expect(page.getByTestId('open-file')).toBeFocused();
  // Space on the focused input opens the browser's file chooser.
  const [chooser] = await Promise.all([page.waitForEvent('filechooser', { timeout: 10_000 }), page.keyboard.press('Space')]);
  expect(chooser.isMultiple()).toBe(false);
});

test('Download for Radiance: a zip with the scene, one light per module, the distributions and render.sh', async ({ page }) => {
  await page.goto('/?expert=1'); // the Radiance download is an expert tool (docs/embedding.md, option `expert`)
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-single').click();
  const before = await sceneFile(page);
  const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId('download-radiance').click()]);
  expect(download.suggestedFilename()).toBe('luxbox-5x4x2.8-radiance.zip');
  const files = unzipSync(new Uint8Array(await readFile(await download.path())));
  const rad = strFromU8(files['luxbox-5x4x2.8-radiance/scene.rad']);
  // The single-rail preset: three spots, each a light of its own; every file the scene names is there.
  expect(rad.match(/ light lum\d+_light/g)).toHaveLength(3);
  for (const dat of rad.matchAll(/corr (\S+) source\.cal/g)) expect(files[`luxbox-5x4x2.8-radiance/${dat[1]}`]).toBeDefined();
  expect(strFromU8(files['luxbox-5x4x2.8-radiance/render.sh'])).toContain('oconv scene.rad > scene.oct');
  await expect(page.getByTestId('status-line')).toContainText('Saved luxbox-5x4x2.8-radiance.zip');
  expect(await sceneFile(page)).toEqual(before);
});
