import { expect, test, type Page } from '@playwright/test';
import { PNG } from 'pngjs';
import { meanLevel, sceneFile } from './helpers';

/**
 * Light scenes in the browser (docs/light-scenes.md): record two scenes in the panel, GO with a 1 s
 * fade (the plan's module levels pass through intermediate values to the end state), Space and
 * Shift+Space, and a share link that keeps the scenes.
 */

const levelOf = (page: Page, id: string) => page.locator(`[data-module-id="${id}"]`).first().getAttribute('data-level');

test('record two scenes, GO with a 1 s fade, plan levels fade, Space / Shift+Space, share link keeps scenes', async ({ page, browser }) => {
  await page.goto('/');
  await page.getByRole('button', { name: 'Try the demo' }).click();
  await page.getByTestId('preset-single').click();
  const modules = (await sceneFile(page)).configuration.systems.flatMap((s) => s.rails.flatMap((r) => r.modules));
  expect(modules.length).toBeGreaterThan(1);
  const first = modules[0].id;
  const panel = page.getByTestId('scene-panel');

  // "Day": everything as placed (full level).
  await panel.getByTestId('scene-name').fill('Day');
  await panel.getByTestId('scene-record').click();
  // "Evening": every module at 20 %.
  await page.evaluate(
    (ids) => ids.forEach((moduleId) => window.luxbox!.runAction('setModuleDimming', { moduleId, dimming: 0.2 })),
    modules.map((m) => m.id),
  );
  await panel.getByTestId('scene-name').fill('Evening');
  await panel.getByTestId('scene-record').click();
  await expect(panel.getByTestId('scene-row')).toHaveCount(2);
  const fade = panel.getByTestId('scene-fade-input').nth(1);
  await fade.fill('1');
  await fade.press('Enter');
  await expect
    .poll(() => page.evaluate(() => window.luxbox!.scenes().map((s) => [s.name, s.fade])))
    .toEqual([
      ['Day', 3],
      ['Evening', 1],
    ]);

  // Back to Day at once; the plan shows full level.
  expect(await page.evaluate(() => window.luxbox!.recall('Day', { fade: 0 }))).toEqual({ ok: true });
  await expect.poll(() => levelOf(page, first)).toBe('1.000');

  // Every level the plan shows for the first module, recorded from now on.
  await page.evaluate((id) => {
    const seen: string[] = [];
    (window as unknown as { __levels: string[] }).__levels = seen;
    new MutationObserver(() => {
      const v = document.querySelector(`[data-module-id="${id}"]`)?.getAttribute('data-level');
      if (v && seen[seen.length - 1] !== v) seen.push(v);
    }).observe(document.querySelector('[data-testid="plan-svg"]')!, { attributes: true, subtree: true, attributeFilter: ['data-level'] });
  }, first);
  const go = panel.getByTestId('scene-go');
  await expect(go).toHaveText('GO: Evening');
  await go.click();
  await expect.poll(() => levelOf(page, first)).toBe('0.200');
  const seen = (await page.evaluate(() => (window as unknown as { __levels: string[] }).__levels)).map(Number);
  // The fade passed through levels between the two scenes, falling monotonically.
  expect(seen.filter((v) => v > 0.2 && v < 1).length).toBeGreaterThan(0);
  for (let i = 1; i < seen.length; i++) expect(seen[i]).toBeLessThanOrEqual(seen[i - 1]);
  expect(seen[seen.length - 1]).toBe(0.2);

  // Shift+Space = BACK (Day, 3 s), Space = GO (Evening), with focus on no field.
  await page.evaluate(() => (document.activeElement as HTMLElement | null)?.blur());
  await page.keyboard.press('Shift+Space');
  await expect.poll(() => page.evaluate(() => window.luxbox!.scenes().find((s) => s.current)?.name)).toBe('Day');
  await expect.poll(() => levelOf(page, first), { timeout: 15_000 }).toBe('1.000');
  await page.keyboard.press('Space');
  await expect.poll(() => page.evaluate(() => window.luxbox!.scenes().find((s) => s.current)?.name)).toBe('Evening');
  await expect.poll(() => levelOf(page, first)).toBe('0.200');
  // GO at the last scene does not wrap round to the first, as a console stops at the end of its cue
  // list: the button says why (aria-disabled with the reason as its title) and Space says it in the panel.
  await expect(go).toHaveAttribute('aria-disabled', 'true');
  await expect(go).toHaveAttribute('title', 'Evening is the last scene: GO stops at the end of the list');
  await page.keyboard.press('Space');
  await expect(panel.getByTestId('scene-note')).toHaveText('Evening is the last scene: GO stops at the end of the list');
  expect(await page.evaluate(() => window.luxbox!.scenes().find((s) => s.current)?.name)).toBe('Evening');
  await expect(panel.getByTestId('scene-back')).toHaveAttribute('aria-disabled', 'false');
  // Space while typing in a field types a space.
  await panel.getByTestId('scene-name').fill('Late');
  await panel.getByTestId('scene-name').press('Space');
  await expect(panel.getByTestId('scene-name')).toHaveValue('Late ');

  // A share link opened in a fresh browser keeps the scenes.
  const link = await page.evaluate(() => window.luxbox!.getShareLink());
  const other = await browser.newContext();
  const p2 = await other.newPage();
  await p2.goto(link.replace(/^https?:\/\/[^/]+/, new URL(page.url()).origin));
  await expect(p2.getByTestId('plan')).toBeVisible();
  expect(await p2.evaluate(() => window.luxbox!.scenes().map((s) => [s.name, s.fade]))).toEqual([
    ['Day', 3],
    ['Evening', 1],
  ]);
  await expect(p2.getByTestId('scene-row')).toHaveCount(2);
  await other.close();
});

test('in 3D a crossfade between two solved scenes is relights only: frames drawn, no group bake, no indirect solve', async ({ page }) => {
  type Status = { lit: boolean; frames: number; bake: { done: boolean; groupBakes: number; indirectSolves: number } };
  const status = (): Promise<Status> => page.evaluate(() => window.luxbox!.view3d() as unknown as Status);
  const BAKE = { timeout: 90_000, intervals: [250] };
  await page.goto('/?quality=fast');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-single').click();
  await expect.poll(async () => (await status()).bake.done, BAKE).toBe(true);
  const ids = (await sceneFile(page)).configuration.systems.flatMap((s) => s.rails.flatMap((r) => r.modules.map((m) => m.id)));
  await page.evaluate(() => window.luxbox!.recordScene('Day'));
  await page.evaluate((list) => list.forEach((moduleId, k) => window.luxbox!.runAction('setModuleDimming', { moduleId, dimming: k === 0 ? 0.1 : 0.4 })), ids);
  await page.evaluate(() => window.luxbox!.recordScene('Evening'));
  // Evening's light is solved in the background; Day's solution is kept, so going back solves nothing.
  await expect.poll(async () => (await status()).bake.done, BAKE).toBe(true);
  const solved = (await status()).bake;
  expect(await page.evaluate(() => window.luxbox!.recall('Day', { fade: 0 }))).toEqual({ ok: true });
  await expect.poll(async () => (await status()).bake.done, BAKE).toBe(true);
  expect((await status()).bake).toMatchObject({ groupBakes: solved.groupBakes, indirectSolves: solved.indirectSolves });

  await page.getByTestId('tool-3d').click();
  await expect.poll(async () => (await status()).lit, BAKE).toBe(true);
  const canvas = page.getByTestId('view3d-canvas');
  const dayLevel = meanLevel(await canvas.screenshot());
  const before = await status();
  expect(await page.evaluate(() => window.luxbox!.recall('Evening', { fade: 1 }))).toEqual({ ok: true });
  const after = await status();
  // Frames were drawn during the fade (a relight each), and nothing was baked or solved.
  expect(after.frames).toBeGreaterThan(before.frames + 2);
  expect(after.bake).toMatchObject({ groupBakes: before.bake.groupBakes, indirectSolves: before.bake.indirectSolves, done: true });
  // Under automatic exposure the eye stays adapted to Day (a crossfade is a relight): Evening looks darker (docs/viewer.md, "Exposure that compares").
  await expect(page.getByTestId('exposure-control')).toHaveAttribute('data-ev100', 'auto');
  await expect.poll(async () => meanLevel(await canvas.screenshot()), { timeout: 10_000 }).toBeLessThan(dayLevel * 0.8);
});

test('A/B compare in 3D: two recorded scenes side by side at one exposure, each half darker under Evening than under Day', async ({ page }) => {
  type Status = { lit: boolean; compare: { exposureA: number; exposureB: number; split: number } | null; bake: { done: boolean } };
  const status = (): Promise<Status> => page.evaluate(() => window.luxbox!.view3d() as unknown as Status);
  const BAKE = { timeout: 90_000, intervals: [250] };
  await page.goto('/?quality=fast');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-single').click();
  await expect.poll(async () => (await status()).bake.done, BAKE).toBe(true);
  const ids = (await sceneFile(page)).configuration.systems.flatMap((s) => s.rails.flatMap((r) => r.modules.map((m) => m.id)));
  await page.evaluate(() => window.luxbox!.recordScene('Day'));
  await page.evaluate((list) => list.forEach((moduleId) => window.luxbox!.runAction('setModuleDimming', { moduleId, dimming: 0.2 })), ids);
  await page.evaluate(() => window.luxbox!.recordScene('Evening'));
  await expect.poll(async () => (await status()).bake.done, BAKE).toBe(true);

  await page.getByTestId('tool-3d').click();
  await expect.poll(async () => (await status()).lit, BAKE).toBe(true);
  await page.getByTestId('compare-toggle').click();
  const a = page.getByTestId('compare-a');
  const b = page.getByTestId('compare-b');
  await expect(a.locator('option:checked')).toHaveText('Day');
  await expect(b.locator('option:checked')).toHaveText('Evening');
  const canvas = page.getByTestId('view3d-canvas');
  /** Mean level of the canvas's left and right thirds (between the scene names and the wipe slider). */
  const halves = async () => {
    const png = PNG.sync.read(await canvas.screenshot());
    const mean = (x0: number, x1: number) => {
      let s = 0;
      let n = 0;
      for (let y = Math.round(png.height * 0.2); y < Math.round(png.height * 0.7); y++) {
        for (let x = Math.round(png.width * x0); x < Math.round(png.width * x1); x++) {
          const i = (y * png.width + x) * 4;
          s += (png.data[i] + png.data[i + 1] + png.data[i + 2]) / 3;
          n++;
        }
      }
      return s / n;
    };
    return { left: mean(0.05, 0.4), right: mean(0.6, 0.95) };
  };
  await expect.poll(async () => (await status()).compare?.split).toBe(0.5);
  const dayEvening = await halves();
  const first = (await status()).compare!;
  expect(first.exposureA).toBe(first.exposureB);
  // Swapped: Evening left, Day right.
  await a.selectOption({ label: 'Evening' });
  await b.selectOption({ label: 'Day' });
  await expect(page.getByTestId('compare-wipe-overlay')).toContainText('A · Evening');
  await expect.poll(async () => (await halves()).left, { timeout: 10_000 }).toBeLessThan(dayEvening.left * 0.8);
  const eveningDay = await halves();
  // The same half of the picture, the same exposure: Evening (20 %) darker than Day on both sides.
  expect(eveningDay.right).toBeGreaterThan(dayEvening.right * 1.25);
  const second = (await status()).compare!;
  expect(second.exposureA).toBe(second.exposureB);
  expect(second.exposureA).toBe(first.exposureA);
  // Off: the configuration's own light again, no compare drawn.
  await page.getByTestId('compare-toggle').click();
  await expect.poll(async () => (await status()).compare).toBeNull();
});
