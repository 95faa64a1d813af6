import { expect, test, type Page } from '@playwright/test';
import { PNG } from 'pngjs';
import { footprintsReady, sceneFile, zoomToModuleLevel, viewerStatus as status } from './helpers';

test.use({ reducedMotion: 'reduce', viewport: { width: 1440, height: 900 } });

const aimOf = async (page: Page, id: string) => (await sceneFile(page)).configuration.systems.flatMap((s) => s.rails.flatMap((r) => r.modules)).find((m) => m.id === id) as { aim?: { rotation: number; tilt: number } } | undefined;

/** Share of pixels whose RGB differs by more than 8 levels between two PNG screenshots of the same size. */
function changed(a: Buffer, b: Buffer): number {
  const x = PNG.sync.read(a);
  const y = PNG.sync.read(b);
  let n = 0;
  for (let i = 0; i < x.data.length; i += 4) if (Math.abs(x.data[i] - y.data[i]) + Math.abs(x.data[i + 1] - y.data[i + 1]) + Math.abs(x.data[i + 2] - y.data[i + 2]) > 24) n++;
  return n / (x.width * x.height);
}

// Issue #12, aiming (docs/aiming.md): aim at a tapped plan point, then the spotlight view: drag to pan and
// tilt, the image and the plan footprint follow, and the release rebakes that one module.
test('aim at from the plan, spotlight view drag: image and footprint follow, one group bake', async ({ page }) => {
  await page.goto('/?quality=fast');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-single').click();
  await footprintsReady(page);
  await zoomToModuleLevel(page);
  const moduleId = (await sceneFile(page)).configuration.systems[0].rails[0].modules[0].id;
  const moduleButton = page.getByTestId(`module-${moduleId}`).getByRole('button');
  await moduleButton.click();
  await expect(page.getByTestId('aim-values')).toHaveAttribute('data-tilt', '0');
  const footprint = page.locator(`[data-footprint-for="${moduleId}"]`);
  const straight = await footprint.evaluate((e) => e.outerHTML);

  // Aim at: a tap on the floor 150 px below the module in the plan.
  await page.getByTestId('aim-at').click();
  await expect(page.getByTestId('aim-at-status')).toBeVisible();
  const box = (await moduleButton.boundingBox())!;
  await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2 + 150);
  await expect.poll(async () => (await aimOf(page, moduleId))?.aim?.tilt ?? 0).toBeGreaterThan(10);
  await expect(page.getByTestId('aim-at-status')).toHaveCount(0);
  // The footprint is now the tilted cone on the floor (a polygon), not the straight-down shape.
  await expect.poll(() => footprint.evaluate((e) => e.outerHTML)).not.toBe(straight);
  expect(await footprint.evaluate((e) => e.tagName)).toBe('polygon');
  const plannedFootprint = await footprint.evaluate((e) => e.outerHTML);

  // 3D: the spotlight view of the selected spot.
  await page.getByTestId('tool-3d').click();
  await expect(page.getByTestId('view3d-canvas')).toBeVisible();
  await expect.poll(async () => (await status(page)).done, { timeout: 90_000, intervals: [250] }).toBe(true);
  const canvas = page.getByTestId('view3d-canvas');
  // The room from the orbit camera, lit with the aim so far.
  const before = await canvas.screenshot();
  const framesOrbit = (await status(page)).frames;
  await page.getByTestId('spotlight-view').click();
  await expect(page.getByTestId('spotlight-hint')).toBeVisible();
  await expect.poll(async () => (await status(page)).frames).toBeGreaterThan(framesOrbit);
  const spotFrames = (await status(page)).frames;
  const baked = await status(page);
  const aimBefore = (await aimOf(page, moduleId))!.aim!;

  // Drag up and to the left by mouse: more tilt, a turn.
  const c = (await canvas.boundingBox())!;
  await page.mouse.move(c.x + c.width / 2, c.y + c.height / 2);
  await page.mouse.down();
  for (let k = 1; k <= 10; k++) await page.mouse.move(c.x + c.width / 2 - 6 * k, c.y + c.height / 2 - 8 * k);
  await page.mouse.up();
  // The view followed the drag frame by frame (the preview).
  expect((await status(page)).frames).toBeGreaterThan(spotFrames + 3);
  // 80 px up at fov / height degrees per pixel (the narrow spot: fov 32°, 791 px): 3° more tilt.
  await expect.poll(async () => (await aimOf(page, moduleId))!.aim!.tilt).toBeGreaterThan(aimBefore.tilt + 2);
  expect((await aimOf(page, moduleId))!.aim!.rotation).not.toBe(aimBefore.rotation);
  // One module's basis rebaked, nothing else.
  await expect.poll(async () => (await status(page)).done, { timeout: 90_000, intervals: [250] }).toBe(true);
  expect((await status(page)).groupBakes).toBe(baked.groupBakes + 1);
  // Leaving the spotlight view: the orbit camera is back where it was, and the spot's light has moved.
  const framesDone = (await status(page)).frames;
  await page.getByTestId('spotlight-view').click();
  await expect.poll(async () => (await status(page)).frames).toBeGreaterThan(framesDone);
  const after = await canvas.screenshot();
  const moved = changed(before, after);
  console.info(`aiming e2e: ${(100 * moved).toFixed(2)} % of the orbit view's pixels changed`);
  expect(moved).toBeGreaterThan(0.003);
  // A camera preset leaves the spotlight view: the button and the presets follow the camera (issue #13).
  await page.getByTestId('spotlight-view').click();
  await expect(page.getByTestId('spotlight-view')).toHaveAttribute('aria-pressed', 'true');
  await expect(page.getByTestId('camera-corner')).toHaveAttribute('aria-pressed', 'false');
  await page.getByTestId('camera-top').click();
  await expect(page.getByTestId('spotlight-view')).toHaveText('Spotlight view');
  await expect(page.getByTestId('spotlight-view')).toHaveAttribute('aria-pressed', 'false');
  await expect(page.getByTestId('spotlight-hint')).toHaveCount(0);
  await expect(page.getByTestId('camera-top')).toHaveAttribute('aria-pressed', 'true');
  // Back in the plan the footprint followed the aim.
  await page.getByTestId('back-2d').click();
  await expect.poll(() => footprint.evaluate((e) => e.outerHTML)).not.toBe(plannedFootprint);
});
