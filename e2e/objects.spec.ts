import { readFileSync } from 'node:fs';
import { expect, test, type Page } from '@playwright/test';
import type { ActionParams } from '../src/core/model/actions/actionDefinitions';

// Springs are skipped under prefers-reduced-motion, so views land at once.
test.use({ reducedMotion: 'reduce' });

interface SceneObject {
  id: string;
  source: { kind: 'library'; item: string } | { kind: 'imported'; mesh: string };
  placement: { on: 'floor'; x: number; z: number } | { on: 'wall'; wall: string; u: number; y: number };
  yaw: number;
  scale: number;
}

async function objects(page: Page): Promise<SceneObject[]> {
  const doc = JSON.parse(await page.evaluate(() => window.luxbox!.getConfig()));
  return doc.configuration.objects ?? [];
}

async function importedMeshCount(page: Page): Promise<number> {
  const doc = JSON.parse(await page.evaluate(() => window.luxbox!.getConfig()));
  return Object.keys(doc.configuration.importedMeshes ?? {}).length;
}

const fixture = (name: string) => ({ name, mimeType: 'application/octet-stream', buffer: readFileSync(`tests/fixtures/models/${name}`) });

async function startEmptyRoom(page: Page): Promise<void> {
  await page.goto('/');
  await page.getByRole('button', { name: 'Start planning' }).click();
  await expect(page.getByTestId('plan')).toBeVisible();
}

/** Opens the side panel on narrow boxes (it is a drawer there); a no-op on wide ones. */
async function openPanel(page: Page): Promise<void> {
  const toggle = page.getByRole('button', { name: 'Presets' });
  if (await toggle.isVisible()) await toggle.click();
}

test.describe('desktop', () => {
  test.use({ viewport: { width: 1440, height: 900 } });

  test('place a dining table and a sofa, move and turn them, import the OBJ table, undo, reload keeps them', async ({ page }) => {
    await startEmptyRoom(page);

    // Tap adds at the middle of the visible plan (the room is fitted: its centre, 2.5 m × 2 m).
    await page.getByTestId('furniture-dining-table').click();
    await page.getByTestId('furniture-sofa').click();
    let objs = await objects(page);
    expect(objs.map((o) => (o.source.kind === 'library' ? o.source.item : ''))).toEqual(['dining-table', 'sofa']);
    expect(objs[0].placement).toEqual({ on: 'floor', x: 2.5, z: 2 });
    // The sofa goes to the free floor nearest the middle (issue #27): beside the table, not in it
    // (table z 1.55…2.45, 2 cm apart, the sofa 90 cm deep, on the 5 cm lattice).
    expect(objs[1].placement).toEqual({ on: 'floor', x: 2.5, z: 1.05 });
    await expect(page.locator('[data-object-id]')).toHaveCount(2);

    // The sofa is selected: arrows move it 0.1 m, R turns it 15°.
    await expect(page.locator(`[data-object-id="${objs[1].id}"]`)).toHaveAttribute('data-selected', 'true');
    for (let i = 0; i < 20; i++) await page.keyboard.press('ArrowDown');
    await page.keyboard.press('r');
    objs = await objects(page);
    expect(objs[1].placement).toEqual({ on: 'floor', x: 2.5, z: 3.05 });
    expect(objs[1].yaw).toBe(15);

    // Drag the table 120 px to the right with the mouse: 120 px / scale metres, snapped to the centimetre.
    const plan = page.getByTestId('plan');
    const box = (await plan.boundingBox())!;
    const scale = Number(await plan.getAttribute('data-scale'));
    const svgBox = (await page.getByTestId('plan-svg').boundingBox())!;
    const view = await page.evaluate(() => {
      const g = document.querySelector('[data-testid="plan-svg"] > g')!;
      const m = /matrix\(([^)]*)\)/.exec(g.getAttribute('transform')!)![1].split(/[ ,]+/).map(Number);
      return { scale: m[0], offsetX: m[4], offsetY: m[5] };
    });
    expect(view.scale).toBeCloseTo(scale, 2);
    const at = { x: svgBox.x + 2.5 * view.scale + view.offsetX, y: svgBox.y + 1.8 * view.scale + view.offsetY };
    expect(at.x).toBeGreaterThan(box.x);
    await page.mouse.move(at.x, at.y);
    await page.mouse.down();
    for (let i = 1; i <= 6; i++) await page.mouse.move(at.x + 20 * i, at.y);
    await page.mouse.up();
    objs = await objects(page);
    const table = objs[0].placement as { x: number; z: number };
    expect(table.x).toBeCloseTo(Math.round((2.5 + 120 / view.scale) * 100) / 100, 6);
    expect(table.z).toBe(2);

    // Turn the selected table with the bottom bar's Rotate (the same command as R).
    await page.getByTestId('tool-rotate').click();
    expect((await objects(page))[0].yaw).toBe(15);

    // The options of the selected table: its real size in cm; a finish per material.
    await page.getByTestId('tool-options').click();
    const options = page.getByTestId('options-panel');
    await expect(options.getByTestId('object-size')).toContainText('180 × 90 × 75 cm');
    await options.getByTestId('object-finish-top').selectOption('white-lacquer');
    await expect(page.locator(`[data-object-id="${objs[0].id}"] path`)).toHaveAttribute('fill', '#e7e7e7');

    // A broken file: the error names it, nothing is added.
    const before = await page.evaluate(() => window.luxbox!.getConfig());
    await page.getByTestId('import-file').setInputFiles({ name: 'broken.obj', mimeType: 'text/plain', buffer: Buffer.from('v 0 0 0\nf 1 2 3\n') });
    await expect(page.getByTestId('import-error')).toContainText('broken.obj');
    expect(await page.evaluate(() => window.luxbox!.getConfig())).toBe(before);

    // Winding (issue #35): an inside-out box is turned outward, a single quad is lit on both sides,
    // and the preview says so before anything is added.
    const cube = ['v 0 0 0', 'v 1 0 0', 'v 0 1 0', 'v 1 1 0', 'v 0 0 1', 'v 1 0 1', 'v 0 1 1', 'v 1 1 1'];
    const outward = [
      [1, 5, 7],
      [1, 7, 3],
      [2, 4, 8],
      [2, 8, 6],
      [1, 2, 6],
      [1, 6, 5],
      [3, 7, 8],
      [3, 8, 4],
      [1, 3, 4],
      [1, 4, 2],
      [5, 6, 8],
      [5, 8, 7],
    ];
    const insideOut = [...cube, ...outward.map(([a, b, c]) => `f ${a} ${c} ${b}`)].join('\n');
    await page.getByTestId('import-file').setInputFiles({ name: 'mirrored.obj', mimeType: 'text/plain', buffer: Buffer.from(`${insideOut}\n`) });
    await expect(page.getByTestId('import-orientation')).toHaveText('1 closed part faced inward and was turned outward');
    await page.getByTestId('import-file').setInputFiles({ name: 'sheet.obj', mimeType: 'text/plain', buffer: Buffer.from('v 0 0 0\nv 0 0 1\nv 1 0 1\nv 1 0 0\nf 1 2 3 4\n') });
    await expect(page.getByTestId('import-orientation')).toHaveText('1 open surface is lit and reflects on both sides');
    await expect(page.getByTestId('import-triangles')).toContainText('2 triangles');
    // Three triangles of one part on one edge: no winding fits, so it is lit on both sides, with a warning.
    const fan = ['v 0 0 0', 'v 0 0 1', 'v 1 0 0.5', 'v -0.5 0.866 0.5', 'v -0.5 -0.866 0.5', 'f 1 2 3', 'f 3 4 2', 'f 1 2 4', 'f 4 5 1', 'f 1 2 5'].join('\n');
    await page.getByTestId('import-file').setInputFiles({ name: 'fan.obj', mimeType: 'text/plain', buffer: Buffer.from(`${fan}\n`) });
    await expect(page.getByTestId('import-undecided')).toContainText('1 part has no clear inside (faces that cannot be wound alike): it is lit on both sides');
    expect(await page.evaluate(() => window.luxbox!.getConfig())).toBe(before);

    // Import the OBJ fixture with its MTL: units, triangle count and size shown before adding.
    await page.getByTestId('import-file').setInputFiles([fixture('table.obj'), fixture('table.mtl')]);
    const preview = page.getByTestId('import-preview');
    await expect(preview).toContainText('table.obj');
    await expect(page.getByTestId('import-triangles')).toContainText('120 × 80 × 75 cm');
    await expect(page.getByTestId('import-units')).toHaveValue('m');
    await expect(page.getByTestId('import-orientation')).toHaveText('Every part is closed and faces outward');
    // Overriding the unit reads the file again: in centimetres the table is 1.2 cm long.
    await page.getByTestId('import-units').selectOption('cm');
    await expect(page.getByTestId('import-triangles')).toContainText('60 triangles · 1.2 × 0.8 ×');
    await page.getByTestId('import-units').selectOption('m');
    await expect(page.getByTestId('import-triangles')).toContainText('120 × 80 × 75 cm');
    expect(await page.evaluate(() => window.luxbox!.getConfig())).toBe(before);
    await page.getByTestId('import-add').click();
    await expect(page.getByTestId('import-preview')).toHaveCount(0);
    expect(await objects(page)).toHaveLength(3);
    expect(await importedMeshCount(page)).toBe(1);

    // The share link leaves the imported model out and says so next to the link.
    await page.getByTestId('share').click();
    await expect(page.getByTestId('share-notice')).toContainText("'table.obj' is not in the link");

    // Undo removes the import; redo brings it back.
    await page.getByTestId('tool-undo').click();
    expect(await objects(page)).toHaveLength(2);
    expect(await importedMeshCount(page)).toBe(0);
    await page.getByTestId('tool-redo').click();
    expect(await objects(page)).toHaveLength(3);

    // Reload: the autosave keeps every object, the imported mesh included.
    const saved = await objects(page);
    await page.reload();
    await expect(page.getByTestId('plan')).toBeVisible();
    expect(await objects(page)).toEqual(saved);
    expect(await importedMeshCount(page)).toBe(1);
    await expect(page.locator('[data-object-id]')).toHaveCount(3);

    // Delete removes the selected object.
    await page.getByTestId('tool-select').click();
    await page.getByTestId('tool-select').click();
    await page.getByTestId('tool-select').click();
    await page.keyboard.press('Delete');
    expect(await objects(page)).toHaveLength(2);
  });

  test('a picture goes on the nearest wall and slides along it', async ({ page }) => {
    await startEmptyRoom(page);
    await page.getByTestId('furniture-picture').click();
    const [pic] = await objects(page);
    expect(pic.placement).toMatchObject({ on: 'wall', y: 1.55 });
    const wall = (pic.placement as { wall: string }).wall;
    await page.keyboard.press(wall === 'north' || wall === 'south' ? 'ArrowRight' : 'ArrowDown');
    const [moved] = await objects(page);
    expect((moved.placement as { u: number }).u).toBeCloseTo((pic.placement as { u: number }).u + 0.1, 6);
    expect((moved.placement as { wall: string }).wall).toBe(wall);
  });
});

/** A furnished room for the screenshots: table, sofa, shelf, plant, picture, the imported table; the sofa selected with its options open. */
async function furnish(page: Page): Promise<void> {
  await startEmptyRoom(page);
  await page.evaluate(() => {
    const l = window.luxbox!;
    const add = (item: string, placement: ActionParams<'addObject'>['placement'], yaw = 0) => {
      const r = l.runAction('addObject', { source: { kind: 'library', item }, placement, yaw });
      if (!r.ok) throw new Error(r.reason);
    };
    add('dining-table', { on: 'floor', x: 1.6, z: 1.3 });
    add('chair', { on: 'floor', x: 1.2, z: 2.05 }, 180);
    add('chair', { on: 'floor', x: 2.0, z: 2.05 }, 180);
    add('open-shelf', { on: 'floor', x: 4.8, z: 1.2 }, 270);
    add('floor-plant', { on: 'floor', x: 0.45, z: 3.5 });
    add('picture', { on: 'wall', wall: 'north', u: 3.6, y: 1.55 });
    add('sofa', { on: 'floor', x: 3.0, z: 3.4 }, 180);
    l.runAction('placePreset', { presetId: 'single' });
  });
  await openPanel(page);
  await page.getByTestId('import-file').setInputFiles([fixture('table.obj'), fixture('table.mtl')]);
  await page.getByTestId('import-add').click();
  // Select the sofa from the plan and open its options.
  const close = page.getByRole('button', { name: 'Close' });
  if (await close.isVisible()) await close.click();
  await page.getByTestId('tool-select').click();
  const all = await objects(page);
  const sofa = all.find((o) => o.source.kind === 'library' && o.source.item === 'sofa')!;
  for (let i = 0; i < 12; i++) {
    if ((await page.locator(`[data-object-id="${sofa.id}"]`).getAttribute('data-selected')) === 'true') break;
    await page.getByTestId('tool-select').click();
  }
  await expect(page.locator(`[data-object-id="${sofa.id}"]`)).toHaveAttribute('data-selected', 'true');
}

for (const [name, viewport] of [
  ['phone', { width: 390, height: 844 }],
  ['tablet', { width: 820, height: 1180 }],
  ['desktop', { width: 1440, height: 900 }],
] as const) {
  test(`screenshots: a furnished room at ${name} size`, async ({ page }) => {
    await page.setViewportSize(viewport);
    await furnish(page);
    await page.screenshot({ path: `test-results/objects-${name}-plan.png` });
    await page.getByTestId('tool-options').click();
    await expect(page.getByTestId('options-panel')).toBeVisible();
    await page.screenshot({ path: `test-results/objects-${name}-options.png` });
    await page.getByTestId('furniture-panel').scrollIntoViewIfNeeded();
    await page.screenshot({ path: `test-results/objects-${name}-furniture.png` });
  });
}
