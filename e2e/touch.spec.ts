import { expect, test } from '@playwright/test';
import { footprintsReady } from './helpers';

// A tablet with a touch screen; springs skipped so each gesture lands at once.
test.use({ viewport: { width: 1024, height: 768 }, hasTouch: true, reducedMotion: 'reduce' });

test('pinch zooms about the fingers, taps select, and controls keep their size at every zoom', async ({ page }) => {
  await page.goto('/');
  await page.getByRole('button', { name: 'Try the demo' }).tap();
  await footprintsReady(page);
  const plan = page.getByTestId('plan');
  const box = (await plan.boundingBox())!;
  const scale0 = Number(await plan.getAttribute('data-scale'));

  // Two fingers 100 px apart spread to 300 px apart about the same centre: 3× zoom.
  const cdp = await page.context().newCDPSession(page);
  const cx = box.x + box.width / 2;
  const cy = box.y + box.height / 2;
  const fingers = (d: number) => [
    { x: cx - d / 2, y: cy, id: 0 },
    { x: cx + d / 2, y: cy, id: 1 },
  ];
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: fingers(100) });
  for (let d = 120; d <= 300; d += 20) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: fingers(d) });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await expect.poll(async () => Number(await plan.getAttribute('data-scale')) / scale0).toBeGreaterThan(2.7);
  expect(Number(await plan.getAttribute('data-scale')) / scale0).toBeLessThan(3.3);
  await expect(plan).toHaveAttribute('data-level', 'module');

  // Every on-plan control is a touch target of at least 44 px, the same size at two zooms.
  const plus = page.locator('[data-testid^="plus-"] button').first();
  const size1 = (await plus.boundingBox())!;
  expect(size1.width).toBeGreaterThanOrEqual(44);
  expect(size1.height).toBeGreaterThanOrEqual(44);
  // Zoom in another 28 % about the button itself so it stays on screen.
  await page.mouse.move(size1.x + size1.width / 2, size1.y + size1.height / 2);
  await page.mouse.wheel(0, -100);
  await expect.poll(async () => Number(await plan.getAttribute('data-scale')) / scale0).toBeGreaterThan(3.5);
  const size2 = (await plus.boundingBox())!;
  expect(size2.width).toBeCloseTo(size1.width, 1);
  expect(size2.height).toBeCloseTo(size1.height, 1);

  // A tap on a module's type button selects it and opens its settings (no hover needed).
  // Controls outside the visible plan are not drawn; pick a module button that is on screen.
  const tapped = await page.evaluate((b) => {
    for (const el of document.querySelectorAll<HTMLElement>('[data-testid^="module-"]')) {
      const r = el.getBoundingClientRect();
      if (r.left >= b.x && r.top >= b.y && r.right <= b.x + b.width && r.bottom <= b.y + b.height) return el.dataset.testid!.slice('module-'.length);
    }
    return '';
  }, box);
  if (tapped) await page.getByTestId(`module-${tapped}`).getByRole('button').tap();
  expect(tapped).not.toBe('');
  await expect(page.getByTestId('options-panel')).toContainText('Colour temperature');
  await expect(page.getByTestId(`module-${tapped}`).getByRole('button')).toHaveAttribute('aria-pressed', 'true');
});
