import { expect, test, type Browser, type Locator, type Page } from '@playwright/test';
import { footprintsReady, sceneFile, zoomToModuleLevel } from './helpers';

// Issue 27, "Choices that stick" and "Furniture", on a phone (touch, 390 × 844) and a desktop
// (1440 × 900), English and German (docs/planner.md, "Issue 27 coverage"): a module's type change
// keeps its beam angle, or takes the nearest and says so; a new piece of furniture goes to free
// floor, named in the UI language; a drag past a wall stops the piece at the wall.

const DEVICES = {
  phone: { viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true },
  desktop: { viewport: { width: 1440, height: 900 } },
} as const;
type Device = keyof typeof DEVICES;
const TEXT = {
  'en-GB': { start: 'Start planning', table: 'Dining table', sofa: 'Sofa', note: /^Wide flood has no “Spot 30°, warm dim”: the nearest beam, “Flood 48°”, is set$/ },
  'de-DE': { start: 'Planung beginnen', table: 'Esstisch', sofa: 'Sofa (drei Sitze)', note: /^Breitstrahler gibt es nicht mit „Spot 30°, Warm-Dim“: die nächstliegende Ausstrahlung, „Fluter 48°“, ist gewählt$/ },
} as const;
type Locale = keyof typeof TEXT;

async function open(browser: Browser, device: Device, locale: Locale, path: string): Promise<Page> {
  const context = await browser.newContext({ ...DEVICES[device], locale, reducedMotion: 'reduce' });
  const page = await context.newPage();
  await page.goto(path);
  return page;
}

// A disabled control is aria-disabled, not disabled: it is pressed like any other.
const press = (device: Device) => (l: Locator) => (device === 'desktop' ? l.click({ force: true }) : l.tap({ force: true }));

interface FloorObject {
  id: string;
  source: { kind: string; item?: string };
  placement: { on: 'floor'; x: number; z: number };
  yaw: number;
}
async function objects(page: Page): Promise<FloorObject[]> {
  return JSON.parse(await page.evaluate(() => window.luxbox!.getConfig())).configuration.objects ?? [];
}

/** A one-finger drag by CDP touch events (a phone), or a mouse drag (a desktop), in 10 steps. */
async function drag(page: Page, device: Device, from: { x: number; y: number }, to: { x: number; y: number }): Promise<void> {
  const at = (i: number) => ({ x: from.x + ((to.x - from.x) * i) / 10, y: from.y + ((to.y - from.y) * i) / 10 });
  if (device === 'desktop') {
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    for (let i = 1; i <= 10; i++) await page.mouse.move(at(i).x, at(i).y);
    await page.mouse.up();
    return;
  }
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ ...from, id: 0 }] });
  for (let i = 1; i <= 10; i++) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [{ ...at(i), id: 0 }] });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
}

for (const device of ['phone', 'desktop'] as const) {
  for (const locale of ['en-GB', 'de-DE'] as const) {
    const text = TEXT[locale];

    test(`${device}, ${locale}: a type change keeps the beam, or sets the nearest and says so`, async ({ browser }) => {
      // `fast`: this test stays in 2D, so the demo's background bake need not hold the cores (docs/benchmarks.md, "Test suite time").
      const page = await open(browser, device, locale, '/?demo&quality=fast');
      const tap = press(device);
      await footprintsReady(page);
      await zoomToModuleLevel(page);
      const rail = (await sceneFile(page)).configuration.systems[0].rails[0];
      // A spot whose button is on screen (a phone at module level shows part of the rail).
      let spot: string | null = null;
      for (const m of rail.modules.filter((x) => x.type === 'spot')) if (!spot && (await page.getByTestId(`module-${m.id}`).isVisible())) spot = m.id;
      expect(spot).not.toBeNull();
      await tap(page.getByTestId(`module-${spot}`).getByRole('button'));
      const options = page.getByTestId('options-panel');
      await expect(options).toBeVisible();
      const moduleNow = async () => (await sceneFile(page)).configuration.systems[0].rails[0].modules.find((m) => m.id === spot) as unknown as { type: string; beam: string };

      // Spot 30° → Warm-dim spot: the same 30° beam (the catalog's warm-dim spot has it too), nothing to say.
      await tap(options.getByTestId('beam-medium'));
      await expect.poll(async () => (await moduleNow()).beam).toBe('medium');
      await tap(options.getByTestId('type-spot-warmdim'));
      await expect.poll(moduleNow).toEqual(expect.objectContaining({ type: 'spot-warmdim', beam: 'medium' }));
      await expect(options.getByTestId('beam-medium')).toHaveAttribute('aria-pressed', 'true');
      await expect(options.getByTestId('beam-changed')).toHaveCount(0);

      // → Wide flood (48° or 55°): no 30°, so the nearest, 48°, and a note that says so.
      const flood = options.getByTestId('type-flood');
      await flood.scrollIntoViewIfNeeded();
      if ((await flood.getAttribute('aria-disabled')) === 'true') {
        // The full driver of the demo's L corner: the refusal's one-tap remedy, then the change.
        await tap(flood);
        await tap(page.getByTestId('disabled-tip').getByTestId('remedy'));
        await expect(flood).not.toHaveAttribute('aria-disabled', 'true');
      }
      await tap(flood);
      await expect.poll(moduleNow).toEqual(expect.objectContaining({ type: 'flood', beam: 'flood48' }));
      const note = options.getByTestId('beam-changed');
      await expect(note).toHaveText(text.note);
      await note.scrollIntoViewIfNeeded();
      await page.screenshot({ path: `test-results/choices-beam-${device}-${locale}.png` });
      await page.context().close();
    });

    test(`${device}, ${locale}: furniture goes to free floor, named in the language; a drag past a wall stops at the wall`, async ({ browser }) => {
      const page = await open(browser, device, locale, '/');
      const tap = press(device);
      await tap(page.getByRole('button', { name: text.start }));
      await expect(page.getByTestId('plan')).toBeVisible();
      const openPanel = async () => {
        if (device === 'phone' && !(await page.locator('.side-panel.open').isVisible())) await tap(page.getByTestId('panel-toggle'));
      };
      await openPanel();
      const tableButton = page.getByTestId('furniture-dining-table');
      await expect(tableButton).toContainText(text.table);
      await tap(tableButton);
      await openPanel();
      await expect(page.getByTestId('furniture-sofa')).toContainText(text.sofa);
      await tap(page.getByTestId('furniture-sofa'));
      const [table, sofa] = await objects(page);
      expect([table.source.item, sofa.source.item]).toEqual(['dining-table', 'sofa']);
      // The 1.8 × 0.9 m table at the middle; the 0.9 m deep sofa beside it, not in it (2 cm apart at least).
      expect(Math.abs(sofa.placement.z - table.placement.z)).toBeGreaterThanOrEqual(0.9 - 1e-9);
      await expect(page.locator('.side-panel.open')).toHaveCount(0);

      // Drag the table 2.2 m to the west from x = 2.5 m (0.6 m past the wall): it stops with its west edge at the wall, x = 0.9 m.
      const scale = Number(await page.getByTestId('plan').getAttribute('data-scale'));
      const view = await page.evaluate(() => {
        const g = document.querySelector('[data-testid="plan-svg"] > g')!;
        const m = /matrix\(([^)]*)\)/.exec(g.getAttribute('transform')!)![1].split(/[ ,]+/).map(Number);
        return { scale: m[0], offsetX: m[4], offsetY: m[5] };
      });
      expect(view.scale).toBeCloseTo(scale, 2);
      const svg = (await page.getByTestId('plan-svg').boundingBox())!;
      // A point on the table away from the sofa: 0.3 m from its centre on the far side.
      const side = Math.sign(table.placement.z - sofa.placement.z);
      const from = { x: svg.x + table.placement.x * view.scale + view.offsetX, y: svg.y + (table.placement.z + 0.3 * side) * view.scale + view.offsetY };
      const to = { x: from.x - 2.2 * view.scale, y: from.y };
      expect(to.x).toBeGreaterThan(0);
      await drag(page, device, from, to);
      await expect.poll(async () => (await objects(page))[0].placement.x).toBeCloseTo(0.9, 2);
      const moved = (await objects(page))[0];
      expect(moved.placement.z).toBeCloseTo(table.placement.z, 2);
      expect(moved.yaw).toBe(0);
      await page.screenshot({ path: `test-results/choices-furniture-${device}-${locale}.png` });
      await page.context().close();
    });
  }
}
