import { expect, test, type Page } from '@playwright/test';

/**
 * Editing the room's shape in the plan (issue 29, docs/planner.md "Rooms of any shape"): a shopper
 * turns the room into an L, types a wall's length, adds a door, a window and a slope, and the plan
 * draws them; an edit that breaks a room rule or would leave a rail outside is refused with its reason.
 */
interface Shape {
  outline: [number, number][];
  slopes: { wall: number; kneeHeight: number; pitch: number }[];
  openings: { wall: number; kind: string; offset: number; width: number }[];
}
const room = async (page: Page): Promise<{ width: number; depth: number; shape?: Shape }> => JSON.parse(await page.evaluate(() => window.luxbox!.getConfig())).configuration.room;

async function startRoom(page: Page, width: string, depth: string) {
  await page.goto('/');
  await page.evaluate(() => localStorage.clear());
  await page.reload();
  await page.locator('input[name=width]').fill(width);
  await page.locator('input[name=depth]').fill(depth);
  await page.getByRole('button', { name: 'Start planning' }).click();
  await expect(page.getByTestId('plan')).toBeVisible();
}

/** Types a value into one of the sheet's fields and commits it (Enter). */
async function typeInto(page: Page, testId: string, value: string) {
  const field = page.getByTestId(testId);
  await field.fill(value);
  await field.press('Enter');
}

test.describe('desktop', () => {
  test.use({ reducedMotion: 'reduce', viewport: { width: 1440, height: 900 } });

  test('an L with a typed wall, a door, a window and a slope; refused edits say why', async ({ page }) => {
    await startRoom(page, '6', '5');
    await page.getByTestId('edit-room-shape').click();
    await page.getByTestId('room-preset-L').click();
    await expect(page.getByTestId('room-corner-5')).toBeVisible();
    expect((await room(page)).shape?.outline).toEqual([
      [0, 0],
      [6, 0],
      [6, 3],
      [3.6, 3],
      [3.6, 5],
      [0, 5],
    ]);

    // The north wall measured with a tape: 7 m. The east side moves out with it.
    await page.getByTestId('room-wall-0').click();
    await typeInto(page, 'room-wall-length', '7');
    await expect(page.getByTestId('room-wall-0')).toHaveText('7.00');
    expect((await room(page)).width).toBe(7);

    // A door in the south wall of the narrow wing, a window in the west wall, a slope over the north side.
    await page.getByTestId('room-wall-4').click();
    await page.getByTestId('room-add-door').click();
    await page.getByTestId('room-wall-5').click();
    await page.getByTestId('room-add-window').click();
    await page.getByTestId('room-wall-0').click();
    await page.getByTestId('room-add-slope').click();
    await expect(page.getByTestId('room-slope-fields')).toBeVisible();
    const shape = (await room(page)).shape!;
    expect(shape.openings.map((o) => [o.wall, o.kind])).toEqual([
      [4, 'door'],
      [5, 'window'],
    ]);
    expect(shape.slopes).toEqual([{ wall: 0, kneeHeight: 1.2, pitch: 40 }]);
    const plan = page.getByTestId('plan-svg');
    await expect(plan.locator('[data-opening-kind="door"]')).toHaveCount(1);
    await expect(plan.locator('[data-opening-kind="window"]')).toHaveCount(1);
    await expect(plan.locator('[data-slope-wall="0"]')).toHaveCount(1);

    // The door slid along its wall by its handle: 60 px to the right at this zoom.
    const handle = page.getByTestId('room-opening-0');
    const box = (await handle.boundingBox())!;
    const before = shape.openings[0].offset;
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width / 2 + 30, box.y + box.height / 2, { steps: 4 });
    await page.mouse.move(box.x + box.width / 2 + 60, box.y + box.height / 2, { steps: 4 });
    await page.mouse.up();
    // Wall 4 runs west (from x = 3.6 to 0): dragging east brings the door nearer the wall's start.
    await expect.poll(async () => (await room(page)).shape!.openings[0].offset).toBeLessThan(before - 0.2);

    // A wall shorter than 10 cm breaks a room rule: refused, the room unchanged, the reason on screen.
    await page.getByTestId('room-wall-0').click();
    await typeInto(page, 'room-wall-length', '0.05');
    await expect(page.getByTestId('status-line')).toContainText('at least 0.1 m');
    expect((await room(page)).width).toBe(7);

    // A rail in the wide wing, past the slope (its ceiling is flat from z ≈ 1.9 m); pulling the east wall in to 5 m would leave it outside.
    expect(await page.evaluate(() => window.luxbox!.runAction('placePreset', { presetId: 'single', x: 5.5, z: 2.4, rotation: 0 }))).toEqual({ ok: true });
    await page.getByTestId('room-wall-0').click();
    await typeInto(page, 'room-wall-length', '5');
    await expect(page.getByTestId('status-line')).toContainText('outside');
    expect((await room(page)).width).toBe(7);

    await page.screenshot({ path: test.info().outputPath('room-shape-desktop.png') });
    await page.getByTestId('room-shape-done').click();
    await expect(page.getByTestId('room-shape-editor')).toHaveCount(0);
    await expect(plan.locator('[data-opening-kind="door"]')).toHaveCount(1);
    await page.screenshot({ path: test.info().outputPath('room-shape-desktop-done.png') });
  });
});

test.describe('phone', () => {
  test.use({ reducedMotion: 'reduce', viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true });

  test('the room-shape mode on a phone: preset, typed length, a door, a corner dragged', async ({ page }) => {
    await startRoom(page, '6', '5');
    await page.getByTestId('panel-toggle').click();
    await page.getByTestId('edit-room-shape').click();
    await expect(page.getByTestId('room-shape-editor')).toBeVisible();
    await page.getByTestId('room-preset-L').tap();
    await page.getByTestId('room-wall-2').tap();
    await typeInto(page, 'room-wall-length', '2');
    await expect(page.getByTestId('room-wall-2')).toHaveText('2.00');
    await page.getByTestId('room-add-door').tap();
    await expect(page.getByTestId('plan-svg').locator('[data-opening-kind="door"]')).toHaveCount(1);
    // The L's inner corner dragged 40 px down: its z grows, the walls either side follow.
    const corner = page.getByTestId('room-corner-3');
    const c = (await corner.boundingBox())!;
    const z = (await room(page)).shape!.outline[3][1];
    await page.mouse.move(c.x + c.width / 2, c.y + c.height / 2);
    await page.mouse.down();
    await page.mouse.move(c.x + c.width / 2, c.y + c.height / 2 + 20, { steps: 3 });
    await page.mouse.move(c.x + c.width / 2, c.y + c.height / 2 + 40, { steps: 3 });
    await page.mouse.up();
    await expect.poll(async () => (await room(page)).shape!.outline[3][1]).toBeGreaterThan(z + 0.2);
    // Without a pointer: the arrow keys move a corner 5 cm.
    const x = (await room(page)).shape!.outline[3][0];
    await page.getByTestId('room-corner-3').focus();
    await page.keyboard.press('ArrowLeft');
    await expect.poll(async () => (await room(page)).shape!.outline[3][0]).toBeCloseTo(x - 0.05, 6);
    await page.getByTestId('room-corner-3').tap();
    await expect(page.getByTestId('room-corner-angle')).toBeVisible();
    await page.screenshot({ path: test.info().outputPath('room-shape-phone.png') });
  });
});
