import { expect, test, type Page } from '@playwright/test';
import { startFiveByFourRoom } from './helpers';

/**
 * Daylight for the shopper (issue 30, docs/daylight.md "The shopper's daylight"): two windows in a
 * living room, daylight on in Zurich, 10:00 on 21 June and then 17:00 on 21 December. Checked on
 * what the running app gives the baker (getLightingScene): the sky and the sun at the clock time
 * with summer time; where the sun's beam through the south window lands on the floor at 10:00 in
 * June (inside the room, worked out here from the sun's position the panel shows and the window's
 * rectangle, parallel rays); and no sky after sunset in December, so no sun patch at all. The city
 * and the date in the UI language (München, 21. Juni); day, month and year each one action (31
 * December → February: the 28th). Then the panel and the 3D view's mode buttons
 * on a 360 px phone, a tablet and a desktop, in English, German, French and Italian, nothing wider
 * than the panel (screenshots for looking at, written under test-results/daylight).
 */
interface Scene {
  room: { width: number; depth: number; height: number };
  daylight?: { sky?: { type: string; sun: { timeZone: number; hours: number; month: number; day: number } }; transmittance: Record<string, unknown> };
}
interface Opening {
  wall: number;
  kind: string;
  offset: number;
  width: number;
  sill: number;
  height: number;
}

const scene = async (page: Page): Promise<Scene> => (await page.evaluate(() => window.luxbox!.getLightingScene())) as Scene;
const openings = async (page: Page): Promise<Opening[]> => JSON.parse(await page.evaluate(() => window.luxbox!.getConfig())).configuration.room.shape.openings;

async function livingRoom(page: Page) {
  await startFiveByFourRoom(page);
  await openDrawer(page);
  await page.getByTestId('edit-room-shape').click();
  await page.getByTestId('room-preset-rectangle').click();
  // The south wall (wall 2 of the rectangle, z = 4 m) and the west wall (wall 3) get a window each.
  for (const wall of [2, 3]) {
    await page.getByTestId(`room-wall-${wall}`).click();
    await page.getByTestId('room-add-window').click();
  }
  await page.getByTestId('room-shape-done').click();
  expect((await openings(page)).map((o) => [o.wall, o.kind])).toEqual([
    [2, 'window'],
    [3, 'window'],
  ]);
}

/** Opens the side panel where it is a drawer (phones and tablets). */
async function openDrawer(page: Page) {
  const toggle = page.getByTestId('panel-toggle');
  if ((await toggle.isVisible()) && !(await page.getByRole('complementary').isVisible())) await toggle.click();
  await expect(page.getByRole('complementary')).toBeVisible();
}

/** Opens the side panel's Daylight section. */
async function openDaylight(page: Page) {
  await openDrawer(page);
  if (!(await page.getByTestId('daylight-panel').isVisible())) await page.getByTestId('daylight-open').click();
  await expect(page.getByTestId('daylight-panel')).toBeVisible();
}

async function setTime(page: Page, time: string) {
  const [h, m] = time.split(':').map(Number);
  await page.getByTestId('daylight-time').fill(String(h * 60 + m));
  // The output writes the clock in the UI locale ("05:00 PM" in en-US); data-time is the model's "HH:MM".
  await expect(page.getByTestId('daylight-time-value')).toHaveAttribute('data-time', time);
}

test.describe('desktop', () => {
  test.use({ reducedMotion: 'reduce', viewport: { width: 1440, height: 900 } });

  test('two windows, 10:00 on 21 June: the sun patch falls inside; 17:00 on 21 December: the sun has set', async ({ page }) => {
    await livingRoom(page);
    await openDaylight(page);
    await page.getByTestId('daylight-on').check();
    await page.getByTestId('daylight-city').selectOption('Zurich');
    await page.getByTestId('daylight-june').click();
    await setTime(page, '10:00');
    const june = await scene(page);
    expect(june.daylight!.sky).toMatchObject({ type: 'cie-clear', sun: { timeZone: 2, hours: 10, month: 6, day: 21 } });
    const sun = page.getByTestId('daylight-sun');
    const elevation = Number(await sun.getAttribute('data-elevation'));
    const azimuth = Number(await sun.getAttribute('data-azimuth'));
    // NOAA for Zurich at 08:00 UTC on 21 June: about 50° up in the south-east (a sanity band, not the algorithm's test).
    expect(elevation).toBeGreaterThan(40);
    expect(elevation).toBeLessThan(60);
    expect(azimuth).toBeGreaterThan(100);
    expect(azimuth).toBeLessThan(140);
    // The beam through the south window's centre, followed back to the floor along the sun's direction
    // (x east, z south; toward the sun [cos e sin A, sin e, −cos e cos A]): it lands inside the room.
    const south = (await openings(page))[0];
    const { width, depth } = june.room;
    const rad = Math.PI / 180;
    const s = [Math.cos(elevation * rad) * Math.sin(azimuth * rad), Math.sin(elevation * rad), -Math.cos(elevation * rad) * Math.cos(azimuth * rad)];
    // Wall 2 runs from (W, D) to (0, D): its offset is measured from x = W.
    const window = [width - south.offset - south.width / 2, south.sill + south.height / 2, depth];
    const t = window[1] / s[1];
    const patch = [window[0] - t * s[0], window[2] - t * s[2]];
    expect(s[2]).toBeGreaterThan(0);
    expect(patch[0]).toBeGreaterThan(0);
    expect(patch[0]).toBeLessThan(width);
    expect(patch[1]).toBeGreaterThan(0);
    expect(patch[1]).toBeLessThan(depth);
    await expect(sun).not.toContainText('below the horizon');

    await page.getByTestId('daylight-december').click();
    await setTime(page, '17:00');
    await expect(sun).toContainText('below the horizon');
    expect(Number(await sun.getAttribute('data-elevation'))).toBeLessThan(0);
    const december = await scene(page);
    // After sunset nothing of daylight is baked: no sky, so no sun patch; the windows are still windows.
    expect(december.daylight?.sky).toBeUndefined();
    expect((await openings(page)).filter((o) => o.kind === 'window')).toHaveLength(2);
    // Undo takes back the slider's one action (17:00): a drag of the slider is one step.
    await page.getByTestId('tool-undo').click();
    await expect(page.getByTestId('daylight-time-value')).toHaveAttribute('data-time', '10:00');
  });
});

test.describe('languages', () => {
  test.use({ reducedMotion: 'reduce', viewport: { width: 1440, height: 900 } });

  test('the city and the date follow the UI language: Munich, June 21 → München, 21. Juni → Monaco di Baviera, 21 giugno', async ({ page }) => {
    test.setTimeout(30_000);
    await livingRoom(page);
    await openDaylight(page);
    const city = page.getByTestId('daylight-city');
    await city.selectOption('Munich');
    await page.getByTestId('daylight-june').click();
    const date = page.getByTestId('daylight-date-text');
    const selected = () => city.evaluate((s: HTMLSelectElement) => s.selectedOptions[0].textContent);
    expect(await selected()).toBe('Munich');
    await expect(date).toContainText('June');
    await expect(date).toContainText('2026');
    for (const [language, cityName, day, month] of [
      ['de', 'München', '21. Juni', 'Juni'],
      ['fr', 'Munich', '21 juin', 'juin'],
      ['it', 'Monaco di Baviera', '21 giugno', 'giugno'],
    ] as const) {
      await page.getByTestId('language-switch').selectOption(language);
      await expect(page.locator('.app')).toHaveAttribute('lang', new RegExp(`^${language}`));
      await expect(date).toContainText(day);
      await expect(page.getByTestId('daylight-june')).toHaveText(day);
      expect(await selected()).toBe(cityName);
      expect(await page.getByTestId('daylight-month').evaluate((s: HTMLSelectElement) => s.selectedOptions[0].textContent)).toBe(month);
    }
    // The stored city is the list's key whatever the language shows.
    const daylight = async () => JSON.parse(await page.evaluate(() => window.luxbox!.getConfig())).configuration.daylight;
    expect((await daylight()).place).toEqual({ city: 'Munich' });
    // Day, month and year each one action: 31 December, then February keeps the month's last day, then another year.
    await page.getByTestId('daylight-december').click();
    await page.getByTestId('daylight-day').selectOption('31');
    await expect.poll(async () => (await daylight()).date).toBe('2026-12-31');
    await page.getByTestId('daylight-month').selectOption('2');
    await expect.poll(async () => (await daylight()).date).toBe('2026-02-28');
    await expect(date).toContainText('28 febbraio 2026');
    await page.getByTestId('daylight-year').fill('2030');
    await page.getByTestId('daylight-year').press('Enter');
    await expect.poll(async () => (await daylight()).date).toBe('2030-02-28');
  });
});

/** Fails when anything inside the element is wider than the element shows (cut off or scrolled sideways). */
async function expectNoOverflow(page: Page, testId: string) {
  const overflowing = await page.getByTestId(testId).evaluate((root) => {
    const box = root.getBoundingClientRect();
    const out: string[] = [];
    for (const el of [root, ...root.querySelectorAll('*')]) {
      const r = el.getBoundingClientRect();
      // Screen-reader-only text is clipped to a pixel on purpose.
      if (r.width === 0 || el.classList.contains('sr-only')) continue;
      if (r.left < box.left - 0.5 || r.right > box.right + 0.5 || el.scrollWidth > el.clientWidth + 1) out.push(`${el.tagName}.${el.className}: ${(el.textContent ?? '').slice(0, 40)}`);
    }
    return out;
  });
  expect(overflowing).toEqual([]);
}

for (const [name, viewport] of [
  ['phone', { width: 360, height: 780 }],
  ['tablet', { width: 820, height: 1180 }],
  ['desktop', { width: 1440, height: 900 }],
] as const) {
  test(`the daylight panel and the 3D view's mode buttons on a ${name}, in four languages`, async ({ page }) => {
    await page.setViewportSize(viewport);
    await livingRoom(page);
    for (const language of ['en', 'de', 'fr', 'it']) {
      if (language !== 'en') {
        await page.getByTestId('language-switch').selectOption(language);
        await expect(page.locator('.app')).toHaveAttribute('lang', new RegExp(`^${language}`));
      }
      await openDaylight(page);
      if (language === 'en') await page.getByTestId('daylight-on').check();
      await page.getByTestId('daylight-panel').scrollIntoViewIfNeeded();
      await expectNoOverflow(page, 'daylight-panel');
      await page.screenshot({ path: `test-results/daylight/${name}-${language}.png` });
    }
    // The 3D view's mode row with its Daylight factor button ("Tageslichtquotient"), in each language.
    const toggle = page.getByTestId('panel-toggle');
    if ((await toggle.isVisible()) && (await page.getByRole('complementary').isVisible())) await toggle.click();
    await page.getByTestId('tool-3d').click();
    const mode = page.getByTestId('mode-daylight-factor');
    for (const language of ['it', 'fr', 'de', 'en']) {
      await page.getByTestId('language-switch').selectOption(language);
      await expect(page.locator('.app')).toHaveAttribute('lang', new RegExp(`^${language}`));
      await mode.scrollIntoViewIfNeeded();
      const row = mode.locator('xpath=..');
      const [rowBox, buttons] = await row.evaluate((r) => [r.getBoundingClientRect().toJSON(), [...r.children].map((c) => c.getBoundingClientRect().toJSON())]);
      for (const b of buttons) expect(b.right).toBeLessThanOrEqual(Math.min(rowBox.right, viewport.width) + 0.5);
      await page.screenshot({ path: `test-results/daylight/${name}-${language}-3d.png` });
    }
    if (name !== 'phone') return;
    // On the phone, the mode itself in German: its statistics table's long labels (Tageslichtquotient …) stay inside it.
    await page.getByTestId('language-switch').selectOption('de');
    await mode.click();
    await expect(page.getByTestId('df-stats')).toBeVisible();
    await expect.poll(async () => (await page.getByTestId('df-mean').textContent())?.trim() ?? '–').not.toBe('–');
    await page.getByTestId('df-stats').scrollIntoViewIfNeeded();
    await expectNoOverflow(page, 'df-stats');
    await page.screenshot({ path: `test-results/daylight/${name}-de-df.png` });
  });
}
