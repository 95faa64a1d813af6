import { expect, test } from '@playwright/test';
import { sceneFile, viewerStatus as status } from './helpers';

/**
 * The 3D view relights on its own GPU (docs/viewer.md, "Relighting on the GPU"): once the light of a
 * configuration is done and the eye holds, a light-scene crossfade and a dimming drag (one relight
 * per committed step) are combined in the view's WebGL context: `view3d().gpu` counts GPU relights,
 * no map is read back, and the CPU relight runs at most once, after the stream has settled. The
 * floor's statistics follow from the GPU reduction, in a box room and in an L (its floor in the atlas,
 * weighed by coverage); three's programs are compiled (compileAsync) before the first frame.
 * (The DMX stream: e2e/liveControl.spec.ts.)
 */
test.use({ viewport: { width: 1280, height: 800 } });

const BAKE = { timeout: 90_000, intervals: [250] };

test('a crossfade and a dimming drag are relit on the GPU: no map read back, floor statistics from the GPU', async ({ page }) => {
  await page.goto('/?quality=fast');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('preset-single').click();
  await expect.poll(async () => (await status(page)).bake.done, BAKE).toBe(true);
  const ids = (await sceneFile(page)).configuration.systems.flatMap((s) => s.rails.flatMap((r) => r.modules.map((m) => m.id)));
  await page.evaluate(() => window.luxbox!.recordScene('Day'));
  await page.evaluate((list) => list.forEach((moduleId, k) => window.luxbox!.runAction('setModuleDimming', { moduleId, dimming: k === 0 ? 0.1 : 0.4 })), ids);
  await page.evaluate(() => window.luxbox!.recordScene('Evening'));
  await expect.poll(async () => (await status(page)).bake.done, BAKE).toBe(true);
  expect(await page.evaluate(() => window.luxbox!.recall('Day', { fade: 0 }))).toEqual({ ok: true });
  await expect.poll(async () => (await status(page)).bake.done, BAKE).toBe(true);

  await page.getByTestId('tool-3d').click();
  await expect.poll(async () => (await status(page)).done, BAKE).toBe(true);
  await expect.poll(async () => (await status(page)).gpu?.cpuRelights ?? 0).toBeGreaterThan(0);
  const day = await status(page);
  expect(day.gpu).toMatchObject({ precision: 'half', mapReadbacks: 0 });
  // three's programs were compiled by compileAsync before the first frame was drawn (createCompileGate.ts).
  expect(day.gpu!.compiles.started).toBeGreaterThan(0);
  expect(day.gpu!.compiles.finishedAtFirstFrame).toBeGreaterThanOrEqual(1);
  expect(day.frames).toBeGreaterThan(0);

  // The crossfade (2 s): a relight per frame, each on the GPU but the last (the final look, shown on the CPU with its statistics).
  expect(await page.evaluate(() => window.luxbox!.recall('Evening', { fade: 2 }))).toEqual({ ok: true });
  await expect.poll(async () => (await status(page)).gpu!.gpuRelights, { timeout: 10_000 }).toBeGreaterThan(day.gpu!.gpuRelights + 1);
  const faded = await status(page);
  expect(faded.gpu!.mapReadbacks).toBe(0);
  expect(faded.gpu!.cpuRelights - day.gpu!.cpuRelights).toBeLessThanOrEqual(1);
  // Evening is darker.
  await expect.poll(async () => (await status(page)).floor!.avg, { timeout: 10_000 }).toBeLessThan(day.floor!.avg * 0.8);
  expect((await status(page)).gpu!.textureBytes).toBeGreaterThan(0);

  // The work plane on: its statistics from the CPU formula on the settled maps first.
  await page.getByTestId('plane-on').check();
  await expect.poll(async () => (await status(page)).plane?.source, { timeout: 30_000 }).toBe('cpu');
  const planeBefore = (await status(page)).plane!;
  // Every work-plane report seen from now on (sampled each animation frame in the page): the drag's come from the GPU reduction.
  await page.evaluate(() => {
    const w = window as unknown as { planeSeen: { source: string; avg: number; mapReadbacks: number }[] };
    w.planeSeen = [];
    const sample = () => {
      const s = window.luxbox!.view3d() as { plane: { source: string; avg: number } | null; gpu: { mapReadbacks: number } | null };
      const last = w.planeSeen[w.planeSeen.length - 1];
      if (s.plane && (!last || last.source !== s.plane.source || last.avg !== s.plane.avg)) w.planeSeen.push({ source: s.plane.source, avg: s.plane.avg, mapReadbacks: s.gpu?.mapReadbacks ?? -1 });
      if (w.planeSeen.length < 1000) requestAnimationFrame(sample);
    };
    requestAnimationFrame(sample);
  });

  // A dimming drag: ten steps, each committed (a relight each), none read back.
  const beforeDrag = await status(page);
  await page.getByText(/Dimming \(/).click();
  const dimmer = page.getByTestId(`dim-${ids[0]}`);
  await dimmer.focus();
  // A hand's pace: each step waits for its relight to be drawn, so the page's sampler sees the work
  // plane's GPU statistics of the drag (ten presses in one burst could settle before a frame showed them).
  for (let i = 0; i < 10; i++) {
    const relit = (await status(page)).gpu!.gpuRelights;
    await page.keyboard.press('ArrowRight');
    await expect.poll(async () => (await status(page)).gpu!.gpuRelights, { timeout: 10_000 }).toBeGreaterThan(relit);
  }
  await expect.poll(async () => (await status(page)).gpu!.gpuRelights, { timeout: 10_000 }).toBeGreaterThan(beforeDrag.gpu!.gpuRelights + 2);
  const dragged = await status(page);
  expect(dragged.gpu!.mapReadbacks).toBe(0);
  expect(dragged.groupBakes).toBe(beforeDrag.groupBakes);
  // Brighter than before the drag; the floor's statistics of the drag's relights come from the GPU reduction (16 bytes read after a fence).
  await expect.poll(async () => (await status(page)).gpu!.statsReadbacks, { timeout: 10_000 }).toBeGreaterThan(beforeDrag.gpu!.statsReadbacks);
  await expect.poll(async () => (await status(page)).floor!.avg, { timeout: 10_000 }).toBeGreaterThan(beforeDrag.floor!.avg * 1.05);
  expect((await status(page)).gpu!.mapReadbacks).toBe(0);
  // The work plane's statistics during the drag came from the GPU (no map read back), brighter than before it.
  const seen = await page.evaluate(() => (window as unknown as { planeSeen: { source: string; avg: number; mapReadbacks: number }[] }).planeSeen);
  const fromGpu = seen.filter((p) => p.source === 'gpu');
  expect(fromGpu.length).toBeGreaterThan(0);
  expect(fromGpu.every((p) => p.mapReadbacks === 0)).toBe(true);
  expect(Math.max(...fromGpu.map((p) => p.avg))).toBeGreaterThan(planeBefore.avg * 1.02);
});

test('a room of any shape: a dimming drag is relit on the GPU, its floor statistics from the atlas reduction, no map read back', async ({ page }) => {
  await page.goto('/?quality=fast');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await page.getByTestId('edit-room-shape').click();
  await page.getByTestId('room-preset-L').click();
  await page.getByTestId('room-shape-done').click();
  expect(await page.evaluate(() => window.luxbox!.runAction('placePreset', { presetId: 'single', x: 1.5, z: 1.5, rotation: 0 }))).toEqual({ ok: true });
  const ids = (await sceneFile(page)).configuration.systems.flatMap((s) => s.rails.flatMap((r) => r.modules.map((m) => m.id)));
  await page.getByTestId('tool-3d').click();
  await expect.poll(async () => (await status(page)).done, BAKE).toBe(true);
  await expect.poll(async () => (await status(page)).gpu?.cpuRelights ?? 0).toBeGreaterThan(0);
  const before = await status(page);
  await page.getByText(/Dimming \(/).click();
  const dimmer = page.getByTestId(`dim-${ids[0]}`);
  await dimmer.focus();
  for (let i = 0; i < 10; i++) await page.keyboard.press('ArrowLeft');
  await expect.poll(async () => (await status(page)).gpu!.gpuRelights, { timeout: 10_000 }).toBeGreaterThan(before.gpu!.gpuRelights + 2);
  // The floor in the atlas: its statistics of the drag's relights from the GPU reduction (16 bytes after a fence), none of a map.
  await expect.poll(async () => (await status(page)).gpu!.statsReadbacks, { timeout: 10_000 }).toBeGreaterThan(before.gpu!.statsReadbacks);
  await expect.poll(async () => (await status(page)).floor!.avg, { timeout: 10_000 }).toBeLessThan(before.floor!.avg * 0.95);
  expect((await status(page)).gpu!.mapReadbacks).toBe(0);
});
