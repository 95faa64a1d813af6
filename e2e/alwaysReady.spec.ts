import { expect, test, type Page } from '@playwright/test';
import { trackCanvases, type CanvasTracking, viewerStatus as status } from './helpers';

/**
 * The 3D view is always ready (issue #15, docs/viewer.md "Always ready: the bake service"): the
 * bake service outlives the view, bakes 2D changes in the background and pauses in a hidden tab.
 * An empty room with the single-rail preset (three spots) so each bake takes seconds on
 * SwiftShader; quality pinned to 'balanced' (?quality=) so the level does not depend on the machine.
 *
 * "Immediate" is asserted without timing: the first lit frame is the view's first frame
 * (firstLitFrame 1), so the view waited for no bake slice, and the counters did not move.
 */
test.use({ reducedMotion: 'reduce', viewport: { width: 1024, height: 768 } });

const config = async (page: Page) => JSON.parse(await page.evaluate(() => window.luxbox!.getConfig())).configuration;
const BAKE = { timeout: 90_000, intervals: [250] };

async function singleRail(page: Page) {
  await page.goto('/?quality=balanced');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-single').click();
  await expect.poll(async () => (await config(page)).systems.length).toBe(1);
}

async function open3d(page: Page) {
  await page.getByTestId('tool-3d').click();
  await expect(page.getByTestId('view3d-canvas')).toBeVisible();
  await expect.poll(async () => (await status(page)).lit, BAKE).toBe(true);
}

async function back2d(page: Page) {
  await page.getByTestId('tool-3d').click();
  await expect(page.getByTestId('plan')).toBeVisible();
  expect((await status(page)).open).toBe(false);
}

test('2D → 3D → 2D → 3D without a change bakes nothing and opens lit on its first frame', async ({ page }) => {
  await singleRail(page);
  // Baked in the background while the plan is on screen: three modules.
  await expect.poll(async () => (await status(page)).bake.done, BAKE).toBe(true);
  const baked = await status(page);
  expect(baked.open).toBe(false);
  expect(baked.bake).toMatchObject({ running: false, paused: false, quality: 'balanced', groupBakes: 3 });

  await open3d(page);
  const first = await status(page);
  expect(first.firstLitFrame).toBe(1);
  expect(first.done).toBe(true);
  expect(first.floor!.avg).toBeGreaterThan(0);
  const framesBefore = (await status(page)).frames;
  await back2d(page);
  await open3d(page);
  const second = await status(page);
  // The same display, kept hidden behind the plan (its frame count runs on), not a rebuilt one.
  expect(second.frames).toBeGreaterThan(framesBefore);
  // Nothing baked across the toggles: no group bake, no indirect solve.
  expect(second.bake.groupBakes).toBe(baked.bake.groupBakes);
  expect(second.bake.indirectSolves).toBe(baked.bake.indirectSolves);
  expect(second.firstLitFrame).toBe(1);
  expect(second.done).toBe(true);
  // The same light as before the toggles (the same maps, not a rebake).
  expect(second.floor!.avg).toBe(first.floor!.avg);
  await expect(page.getByTestId('view3d-progress')).toHaveCount(0);
});

test('a change made in 2D while 3D is closed is baked in the background; 3D opens on the finished light', async ({ page }) => {
  await singleRail(page);
  await expect.poll(async () => (await status(page)).bake.done, BAKE).toBe(true);
  await open3d(page);
  const before = await status(page);
  await back2d(page);

  // The shopper moves the rail in the plan: its three modules are new groups.
  const system = (await config(page)).systems[0];
  expect(await page.evaluate(({ id, x, z }) => window.luxbox!.runAction('moveSystem', { systemId: id, x, z }), { id: system.id, x: system.x - 0.8, z: system.z })).toEqual({ ok: true });
  await expect.poll(async () => (await status(page)).bake.groupBakes, BAKE).toBe(before.bake.groupBakes + 3);
  await expect.poll(async () => (await status(page)).bake.done, BAKE).toBe(true);
  const baked = await status(page);
  expect(baked.open).toBe(false);

  await open3d(page);
  const after = await status(page);
  expect(after.done).toBe(true);
  expect(after.firstLitFrame).toBe(1);
  expect(after.bake.groupBakes).toBe(baked.bake.groupBakes);
  expect(after.bake.indirectSolves).toBe(baked.bake.indirectSolves);
  // The moved rail lights another part of the floor: its statistics changed.
  expect(after.floor!.max).not.toBe(before.floor!.max);
});

test('a hidden tab does not bake; visible again, the bake resumes and finishes', async ({ page }) => {
  await singleRail(page);
  await expect.poll(async () => (await status(page)).bake.done, BAKE).toBe(true);
  const setHidden = (hidden: boolean) =>
    page.evaluate((h) => {
      Object.defineProperty(document, 'hidden', { configurable: true, get: () => h });
      Object.defineProperty(document, 'visibilityState', { configurable: true, get: () => (h ? 'hidden' : 'visible') });
      document.dispatchEvent(new Event('visibilitychange'));
    }, hidden);

  await setHidden(true);
  expect((await status(page)).bake).toMatchObject({ paused: true, running: false });
  const system = (await config(page)).systems[0];
  expect(await page.evaluate(({ id, x, z }) => window.luxbox!.runAction('moveSystem', { systemId: id, x, z }), { id: system.id, x: system.x + 0.6, z: system.z })).toEqual({ ok: true });
  const still = (await status(page)).bake;
  // Counters stay still however long the tab stays hidden (sampled over two seconds).
  for (let i = 0; i < 4; i++) {
    await page.waitForTimeout(500);
    expect((await status(page)).bake).toEqual(still);
  }
  expect(still.done).toBe(false);

  await setHidden(false);
  await expect.poll(async () => (await status(page)).bake.done, BAKE).toBe(true);
  const resumed = (await status(page)).bake;
  expect(resumed).toMatchObject({ paused: false, running: false, groupBakes: still.groupBakes + 3 });
});

test('with no level chosen, a calibration picks one and is kept per renderer', async ({ page }) => {
  await page.goto('/');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-single').click();
  await expect.poll(async () => (await status(page)).bake.groupBakes, BAKE).toBe(3);
  const cached = JSON.parse((await page.evaluate(() => localStorage.getItem('luxbox.calibration')))!);
  expect(cached.msPerTexelSample).toBeGreaterThan(0);
  expect(typeof cached.renderer).toBe('string');
  expect(['fast', 'balanced', 'best']).toContain((await status(page)).bake.quality);
  expect(await page.evaluate(() => localStorage.getItem('luxbox.quality'))).toBeNull();
});

test('the quality control switches the level, rebakes, and the choice is kept for the next visit', async ({ page }) => {
  await singleRail(page);
  await open3d(page);
  await expect(page.getByTestId('quality-balanced')).toHaveAttribute('aria-pressed', 'true');
  const before = await status(page);
  await page.getByTestId('quality-fast').click();
  await expect(page.getByTestId('quality-fast')).toHaveAttribute('aria-pressed', 'true');
  await expect(page.getByTestId('quality-balanced')).toHaveAttribute('aria-pressed', 'false');
  // A fresh engine at the fast level bakes the three modules again.
  await expect.poll(async () => (await status(page)).bake.groupBakes, BAKE).toBe(before.bake.groupBakes + 3);
  await expect.poll(async () => (await status(page)).done, BAKE).toBe(true);
  expect((await status(page)).bake.quality).toBe('fast');
  expect(await page.evaluate(() => localStorage.getItem('luxbox.quality'))).toBe('fast');

  // The next visit (no pin) starts at the stored level, without a calibration; a ?quality= pin wins over it.
  await page.goto('/');
  await expect(page.getByTestId('plan')).toBeVisible();
  await expect.poll(async () => (await status(page)).bake.groupBakes, BAKE).toBeGreaterThan(0);
  expect((await status(page)).bake.quality).toBe('fast');
  expect(await page.evaluate(() => localStorage.getItem('luxbox.calibration'))).toBeNull();
  await page.goto('/?quality=best');
  await expect(page.getByTestId('plan')).toBeVisible();
  expect((await status(page)).bake.quality).toBe('best');
});

test('an embedded configurator bakes in the background too, and destroy() releases its bake context', async ({ page }) => {
  await trackCanvases(page);
  await page.goto('/embed.html');
  await page.getByTestId('host-action-single').click();
  await expect.poll(() => page.evaluate(() => window.shopDemo!.instance!.view3d().bake.groupBakes), BAKE).toBe(3);
  const live = () => page.evaluate(() => (window as unknown as CanvasTracking).__detachedWebgl2().length);
  // The bake context is the one detached WebGL2 canvas still alive (the support checks and the calibration lose theirs).
  expect(await live()).toBe(1);
  await page.getByTestId('toggle-configurator').click();
  expect(await page.evaluate(() => window.shopDemo!.instance)).toBeNull();
  expect(await live()).toBe(0);
});
