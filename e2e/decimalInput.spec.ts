import { expect, test } from '@playwright/test';
import { sceneFile } from './helpers';

// Decimal input in the locale's format (issue 27, docs/i18n.md "Decimal input"): every number field
// shows the locale's decimal mark, and takes "2,8" and "2.8" alike. German on a touch phone, French
// and Italian on a desktop; the browser itself stays en-US, so nothing comes from its own locale.
const CASES = [
  { lang: 'de', device: { viewport: { width: 375, height: 667 }, hasTouch: true, isMobile: true } },
  { lang: 'fr', device: { viewport: { width: 1280, height: 800 } } },
  { lang: 'it', device: { viewport: { width: 1280, height: 800 } } },
] as const;

for (const { lang, device } of CASES) {
  test.describe(lang, () => {
    test.use({ ...device, reducedMotion: 'reduce' });

    test(`${lang}: the room setup, the room options and the on-plan fields show "2,8" and accept both marks`, async ({ page }) => {
      await page.goto(`/?lang=${lang}`);
      const field = (name: string) => page.locator(`.setup input[name="${name}"]`);
      await expect(field('height')).toHaveValue('2,8');
      await expect(field('width')).toHaveValue('5');
      // A point and a comma, each accepted; the room that opens is the one typed.
      await field('width').fill('6.5');
      await field('depth').fill('4,25');
      await field('height').fill('2,75');
      await expect(page.locator('.setup [role="alert"]')).toHaveCount(0);
      await page.locator('.setup button[type="submit"]').click();
      await expect(page.getByTestId('plan')).toBeVisible();
      expect((await sceneFile(page)).configuration.room).toMatchObject({ width: 6.5, depth: 4.25, height: 2.75 });

      // The room's options (nothing selected): the same sizes with the locale's mark.
      await page.getByTestId('tool-options').click();
      const options = page.getByTestId('options-panel');
      const roomFields = options.locator('input');
      await expect(roomFields).toHaveCount(3);
      await expect(roomFields.nth(0)).toHaveValue('6,50');
      await expect(roomFields.nth(2)).toHaveValue('2,75');
      await roomFields.nth(2).fill('2.8');
      await roomFields.nth(2).press('Enter');
      await expect(roomFields.nth(2)).toHaveValue('2,80');
      await roomFields.nth(1).fill('4,5');
      await roomFields.nth(1).press('Enter');
      await expect(roomFields.nth(1)).toHaveValue('4,50');
      expect((await sceneFile(page)).configuration.room).toMatchObject({ width: 6.5, depth: 4.5, height: 2.8 });
      // On the phone the drawer covers the bottom bar: its header toggle closes it (and the options with it).
      if (await page.getByTestId('panel-toggle').isVisible()) await page.getByTestId('panel-toggle').click();
      else await page.getByTestId('tool-options').click();
      await expect(options).toBeHidden();

      // A placed system's on-plan x field: "1,5" in, "1,50" shown; "2.25" in the same field works too.
      await page.evaluate(() => window.luxbox!.runAction('placePreset', { presetId: 'single' }));
      await page.getByTestId('tool-select').click();
      // On the phone the fields are folded behind one button (docs/planner.md, "On-plan fields on a phone").
      const unfold = page.locator('[data-testid^="fields-toggle-"]');
      if (await unfold.isVisible()) await unfold.click();
      const x = page.locator('[data-testid^="move-"] input').first();
      await expect(x).toHaveValue(/^\d+,\d\d$/);
      await x.fill('1,5');
      await x.press('Enter');
      await expect(x).toHaveValue('1,50');
      expect((await sceneFile(page)).configuration.systems[0].x).toBe(1.5);
      await x.fill('2.25');
      await x.press('Enter');
      await expect(x).toHaveValue('2,25');
      expect((await sceneFile(page)).configuration.systems[0].x).toBe(2.25);

      // The 3D view's work-plane height was a type=number field, which shows the browser's mark ("0.75" here).
      if (lang !== 'de') return;
      await page.getByTestId('tool-3d').click();
      const plane = page.getByTestId('plane-height');
      await expect(plane).toHaveValue('0,75');
      await plane.fill('0.85');
      await plane.press('Enter');
      await expect(plane).toHaveValue('0,85');
      await plane.fill('0,8');
      await plane.press('Enter');
      await expect(plane).toHaveValue('0,80');
    });
  });
}
