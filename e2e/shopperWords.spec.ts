import AxeBuilder from '@axe-core/playwright';
import { expect, test, type Browser, type Locator, type Page } from '@playwright/test';
import { footprintsReady, sceneFile, zoomToModuleLevel } from './helpers';

// Issue 27, "Words for shoppers" and "Expert tools" (docs/planner.md, "Words for shoppers"): the
// distribution options as pictures, Extend the chain named by direction, colour details and the
// expert tools out of a shopper's way, the 3D statistics in one layout that fits, a tip beside its
// remedy that does not send the shopper elsewhere, and a tap beside the phone drawer that is not
// lost. Phone (touch, 375 × 667) and desktop (1440 × 900), English and German; axe at zero
// violations; screenshots into test-results/shopper-*.png for review.

const DEVICES = {
  phone: { viewport: { width: 375, height: 667 }, hasTouch: true, isMobile: true },
  desktop: { viewport: { width: 1440, height: 900 } },
} as const;
type Device = keyof typeof DEVICES;
const TEXT = {
  'en-GB': {
    outside: 'Space the modules evenly, the outer ones at the rail ends',
    outsideShort: 'Spread to the ends',
    extendLeft: 'Add a rail: Left 90° (90° corner connector)',
    extendPrefix: 'Add a rail: ',
    details: 'Expert details',
    expert: 'Expert tools',
    byHand: 'system options',
  },
  'de-DE': {
    outside: 'Module gleichmäßig verteilen, die äußeren an den Schienenenden',
    outsideShort: 'Bis an die Enden',
    extendLeft: 'Schiene anfügen: Links 90° (90°-Eckverbinder)',
    extendPrefix: 'Schiene anfügen: ',
    details: 'Expertendetails',
    expert: 'Expertenwerkzeuge',
    byHand: 'Systemoptionen',
  },
} as const;
type Locale = keyof typeof TEXT;

// The demo at a pinned `fast` level: the tests that stay in 2D would otherwise share the cores with the
// always-ready service baking the furnished living room in the background at the calibrated level
// (docs/viewer.md, "Always ready: the bake service"; docs/benchmarks.md, "Test suite time").
async function open(browser: Browser, device: Device, locale: Locale, path = '/?demo&quality=fast'): Promise<Page> {
  const context = await browser.newContext({ ...DEVICES[device], locale, reducedMotion: 'reduce' });
  const page = await context.newPage();
  await page.goto(path);
  await expect(page.getByTestId('plan')).toBeVisible();
  return page;
}

// A disabled control is aria-disabled, not disabled: it is pressed like any other (force: Playwright would wait for it).
const press = (device: Device) => (l: Locator) => (device === 'desktop' ? l.click({ force: true }) : l.tap({ force: true }));

async function violations(page: Page, include?: string): Promise<string[]> {
  const builder = new AxeBuilder({ page });
  if (include) builder.include(include);
  const result = await builder.analyze();
  return result.violations.flatMap((v) => v.nodes.map((n) => `${v.impact} ${v.id} (${v.help}): ${n.target.join(' ')}`));
}

/** Opens the side panel where it is a drawer (a no-op on a desktop). */
async function openPanel(page: Page, device: Device): Promise<void> {
  if (device === 'phone' && !(await page.locator('.side-panel.open').isVisible())) await press(device)(page.getByTestId('panel-toggle'));
}
async function closePanel(page: Page, device: Device): Promise<void> {
  if (device === 'phone' && (await page.locator('.side-panel.open').isVisible())) await press(device)(page.getByTestId('panel-toggle'));
}

/** Elements under `scope` whose content overflows their box (a cell cut off or spilling), as readable lines. */
function overflowing(scope: Locator): Promise<string[]> {
  return scope.evaluate((root) =>
    [root, ...root.querySelectorAll<HTMLElement>('th, td, button, summary, label')]
      .filter((el) => el.scrollWidth > el.clientWidth + 1 && getComputedStyle(el).overflowX !== 'auto')
      .map((el) => `${el.tagName.toLowerCase()} "${el.textContent?.trim().slice(0, 40)}" ${el.scrollWidth} > ${el.clientWidth}`),
  );
}

/**
 * Taps (or clicks) a rail that runs across the screen where nothing else is: 34 px below its + button
 * (PlanControls' NEAR_PX: the + sits that far on the rail's upper side), in the middle of the rail,
 * which on the L corner's first rail (four modules centred in 0.5 m cells) is a gap between modules.
 */
async function selectRail(page: Page, device: Device, railId: string): Promise<void> {
  const plus = (await page.getByTestId(`plus-${railId}`).boundingBox())!;
  const at = { x: plus.x + plus.width / 2, y: plus.y + plus.height / 2 + 34 };
  if (device === 'desktop') await page.mouse.click(at.x, at.y);
  else await page.touchscreen.tap(at.x, at.y);
  await expect(page.getByTestId(`distribution-${railId}`)).toBeVisible();
}

for (const device of ['phone', 'desktop'] as const) {
  for (const locale of ['en-GB', 'de-DE'] as const) {
    const text = TEXT[locale];
    const shot = (page: Page, what: string) => page.screenshot({ path: `test-results/shopper-${what}-${device}-${locale}.png` });

    test(`${device}, ${locale}: distribution pictures and Extend the chain by direction`, async ({ browser }) => {
      const page = await open(browser, device, locale);
      const tap = press(device);
      await footprintsReady(page);
      const system = (await sceneFile(page)).configuration.systems[0];

      // Extend the chain: the system's options name each button by its direction and connector, an arrow each.
      await tap(page.getByTestId('tool-select'));
      await tap(page.getByTestId('tool-options'));
      const options = page.getByTestId('options-panel');
      await expect(options).toBeVisible();
      const extend = options.locator('[data-testid^="extend-"]');
      await expect(extend).toHaveCount(9);
      for (const b of await extend.all()) {
        await expect(b).toHaveAccessibleName(new RegExp(`^${text.extendPrefix}`));
        await expect(b.locator('svg.turn-arrow')).toHaveCount(1);
      }
      await expect(options.getByTestId('extend-corner90-left')).toHaveAccessibleName(text.extendLeft);
      await expect(options).not.toContainText('↰');
      // Every arrow starts along the chain's end as the plan shows it (one heading; tests/ui/planner/shopperWords.test.tsx checks it against the model).
      const headings = await extend.locator('svg.turn-arrow').evaluateAll((svgs) => svgs.map((svg) => svg.getAttribute('data-heading')));
      expect(new Set(headings).size).toBe(1);
      expect(await overflowing(options)).toEqual([]);
      expect(await violations(page, '[data-testid="options-panel"]')).toEqual([]);
      await options.getByTestId('extend-corner90-left').scrollIntoViewIfNeeded();
      await shot(page, 'extend');
      // The first enabled one adds its rail, turned as its name says.
      const enabled = options.locator('[data-testid^="extend-"]:not([aria-disabled="true"])').first();
      const id = (await enabled.getAttribute('data-testid'))!;
      await tap(enabled);
      const after = (await sceneFile(page)).configuration.systems[0] as unknown as { rails: unknown[]; joints: { connector: string; turn: number }[] };
      expect(after.rails).toHaveLength(system.rails.length + 1);
      const joint = after.joints[after.joints.length - 1];
      expect(`extend-${joint.connector}-${joint.turn > 0 ? 'left' : joint.turn < 0 ? 'right' : 'straight'}`).toBe(id);
      await page.evaluate(() => window.luxbox!.undo());
      await closePanel(page, device);

      // Distribution: the selected rail's options on the plan are pictures, named in shopper words.
      await zoomToModuleLevel(page);
      const railId = system.rails[0].id;
      await selectRail(page, device, railId);
      const chips = page.getByTestId(`distribution-${railId}`);
      await expect(chips.locator('svg.distribution-picture')).toHaveCount(4);
      await expect(chips.getByRole('button', { name: text.outside })).toBeVisible();
      // Inside the plan, whole.
      const plan = (await page.getByTestId('plan').boundingBox())!;
      const box = (await chips.boundingBox())!;
      expect(box.x).toBeGreaterThanOrEqual(plan.x - 0.5);
      expect(box.x + box.width).toBeLessThanOrEqual(plan.x + plan.width + 0.5);
      expect(await violations(page, '[data-testid="plan"]')).toEqual([]);
      await shot(page, 'distribution-plan');
      await tap(chips.getByRole('button', { name: text.outside }));
      await expect.poll(async () => ((await sceneFile(page)).configuration.systems[0].rails[0] as unknown as { distribution: string }).distribution).toBe('outside-centred');
      await expect(chips.getByRole('button', { name: text.outside })).toHaveAttribute('aria-pressed', 'true');
      // In the rail's options (still open on a desktop, where they follow the selection): the same pictures over their short names.
      if (!(await options.isVisible())) await tap(page.getByTestId('tool-options'));
      await expect(options).toBeVisible();
      const named = options.getByTestId('distribution-option-outside-centred');
      await expect(named).toContainText(text.outsideShort);
      await expect(named.locator('svg.distribution-picture')).toHaveCount(1);
      expect(await overflowing(options)).toEqual([]);
      expect(await violations(page, '[data-testid="options-panel"]')).toEqual([]);
      await named.scrollIntoViewIfNeeded();
      await shot(page, 'distribution-options');
      await page.context().close();
    });

    test(`${device}, ${locale}: colour details closed; a refused type change offers what makes it fit; the tip beside a remedy says the problem only`, async ({ browser }) => {
      const page = await open(browser, device, locale);
      const tap = press(device);
      await footprintsReady(page);
      await zoomToModuleLevel(page);
      const rail = (await sceneFile(page)).configuration.systems[0].rails[0];
      // The L corner as placed: its + is refused for the driver; the tip offers the larger one and does not send the shopper elsewhere.
      const plus = page.getByTestId(`plus-${rail.id}`).getByRole('button');
      await expect(plus).toHaveAttribute('aria-disabled', 'true');
      await expect(plus).toHaveAttribute('title', new RegExp(text.byHand));
      await tap(plus);
      const tip = page.getByTestId('disabled-tip');
      await expect(tip.getByTestId('remedy')).toBeVisible();
      await expect(tip).not.toContainText(text.byHand);
      await shot(page, 'remedy-tip');
      await tap(tip.getByTestId('disabled-tip-close'));

      // A spot's options: the filter readout keeps CIE x, y and Duv behind Expert details, closed.
      // A spot whose button is on screen (a phone at module level shows part of the rail).
      let spot = rail.modules[0];
      for (const m of rail.modules.filter((x) => x.type === 'spot')) if ((await page.getByTestId(`module-${m.id}`).count()) > 0) spot = m;
      await tap(page.getByTestId(`module-${spot.id}`).getByRole('button'));
      const options = page.getByTestId('options-panel');
      await expect(options).toBeVisible();
      const details = options.getByTestId('filter-expert-details');
      await expect(details).toBeVisible();
      await expect(details).not.toHaveAttribute('open', '');
      await expect(details.getByText(/^CIE x/)).toBeHidden();
      await tap(details.getByText(text.details));
      await expect(details).toHaveAttribute('open', '');
      await expect(details).toContainText(/CIE x 0[.,]\d{4}, y 0[.,]\d{4}/);
      expect(await violations(page, '[data-testid="options-panel"]')).toEqual([]);
      await details.scrollIntoViewIfNeeded();
      await shot(page, 'colour-details');

      // The 0.6 m linear diffuser does not fit the 2 m rail's four 0.5 m cells: the tip offers another arrangement.
      await options.getByTestId('type-linear').scrollIntoViewIfNeeded();
      await expect(options.getByTestId('type-linear')).toHaveAttribute('aria-disabled', 'true');
      await tap(options.getByTestId('type-linear'));
      await expect(tip).toContainText(locale === 'en-GB' ? 'Linear diffuser' : 'Linearer Diffusor');
      await expect(tip.getByTestId('remedy')).toBeVisible();
      await shot(page, 'type-remedy');
      await tap(tip.getByTestId('remedy'));
      await expect(options.getByTestId('type-linear')).not.toHaveAttribute('aria-disabled', 'true');
      await tap(options.getByTestId('type-linear'));
      await expect.poll(async () => (await sceneFile(page)).configuration.systems[0].rails[0].modules.find((m) => m.id === spot.id)?.type).toBe('linear');
      await page.context().close();
    });

    test(`${device}, ${locale}: expert tools off for shoppers; the switch shows them and is remembered; the statistics fit`, async ({ browser }) => {
      const page = await open(browser, device, locale, '/?demo&quality=fast');
      const tap = press(device);
      await openPanel(page, device);
      // The bill of materials: one layout in the side panel at every width, no cell cut off or spilling.
      const bom = page.getByTestId('bom');
      const bomBox = (await bom.boundingBox())!;
      const bomTable = (await bom.locator('table').boundingBox())!;
      expect(bomTable.x + bomTable.width).toBeLessThanOrEqual(bomBox.x + bomBox.width + 0.5);
      expect(await overflowing(bom.locator('table'))).toEqual([]);
      await bom.scrollIntoViewIfNeeded();
      await shot(page, 'bom');
      await expect(page.getByTestId('download-radiance')).toHaveCount(0);
      const sw = page.getByRole('switch', { name: text.expert });
      await sw.scrollIntoViewIfNeeded();
      await expect(sw).not.toBeChecked();
      await tap(sw);
      await expect(sw).toBeChecked();
      await expect(page.getByTestId('download-radiance')).toBeVisible();
      expect(await violations(page, '.side-panel')).toEqual([]);
      await shot(page, 'expert-switch');
      // Remembered: a reload keeps them on.
      await page.reload();
      await openPanel(page, device);
      await expect(page.getByRole('switch', { name: text.expert })).toBeChecked();
      await expect(page.getByTestId('download-radiance')).toBeVisible();
      await closePanel(page, device);

      // In 3D: live control with the expert tools on; the statistics table inside the panel, no cell overflowing.
      await tap(page.getByTestId('tool-3d'));
      await expect(page.getByTestId('view3d-canvas')).toBeVisible();
      await expect(page.getByTestId('live-on')).toHaveCount(1);
      await tap(page.getByTestId('mode-lux'));
      await tap(page.getByTestId('plane-on'));
      await expect(page.getByTestId('stats-floor-avg')).toContainText(/\d/, { timeout: 90_000 });
      await expect(page.getByTestId('stats-plane-avg')).toContainText(/\d/, { timeout: 90_000 });
      const table = page.locator('table.viewer3d-stats');
      const panel = (await page.locator('.viewer3d-panel').boundingBox())!;
      const t = (await table.boundingBox())!;
      expect(t.x).toBeGreaterThanOrEqual(panel.x - 0.5);
      expect(t.x + t.width).toBeLessThanOrEqual(panel.x + panel.width + 0.5);
      expect(await overflowing(table)).toEqual([]);
      // No number breaks over two lines: every value is one line box.
      const lines = await table.locator('td').evaluateAll((cells) =>
        cells.map((c) => {
          const range = document.createRange();
          range.selectNodeContents(c);
          return new Set([...range.getClientRects()].map((r) => Math.round(r.top))).size;
        }),
      );
      expect(
        lines.every((n) => n === 1),
        lines.join(' '),
      ).toBe(true);
      expect(await violations(page, '[data-testid="view3d"]')).toEqual([]);
      await table.scrollIntoViewIfNeeded();
      await shot(page, 'statistics');
      // Off again (in 2D, where the switch is): live control goes from the 3D panel.
      await tap(page.getByTestId('tool-3d'));
      await openPanel(page, device);
      await tap(page.getByRole('switch', { name: text.expert }));
      await expect(page.getByTestId('download-radiance')).toHaveCount(0);
      await closePanel(page, device);
      await tap(page.getByTestId('tool-3d'));
      await expect(page.getByTestId('live-on')).toHaveCount(0);
      await page.context().close();
    });
  }
}

test('the shop decides: no expert tools and no switch by default, ?expert=switch offers it, ?expert=on shows them', async ({ browser }) => {
  for (const [query, sw, tools] of [
    ['', 0, 0],
    ['?expert=switch', 1, 0],
    ['?expert=on', 0, 1],
  ] as const) {
    const context = await browser.newContext({ viewport: { width: 1440, height: 900 }, reducedMotion: 'reduce' });
    const page = await context.newPage();
    await page.goto(`/embed.html${query}`);
    await expect(page.getByTestId('plan')).toBeVisible();
    await expect(page.getByTestId('expert-switch'), query).toHaveCount(sw);
    await expect(page.getByTestId('download-radiance'), query).toHaveCount(tools);
    await context.close();
  }
});

test('phone drawer: a tap beside it closes it and reaches the plan under the veil', async ({ browser }) => {
  const page = await open(browser, 'phone', 'de-DE');
  await page.getByTestId('panel-toggle').tap();
  const drawer = page.getByRole('complementary');
  await expect(drawer).toBeVisible();
  await page.getByTestId('plan').evaluate((plan) => {
    const w = window as unknown as { planPresses: string[] };
    w.planPresses = [];
    for (const type of ['pointerdown', 'pointerup']) plan.addEventListener(type, () => w.planPresses.push(type));
  });
  const box = (await drawer.boundingBox())!;
  expect(box.x).toBeGreaterThan(20);
  await page.touchscreen.tap(box.x / 2, 300);
  await expect(drawer).toBeHidden();
  // The same tap reached the plan (the veil used to take it and nothing else happened).
  expect(await page.evaluate(() => (window as unknown as { planPresses: string[] }).planPresses)).toEqual(['pointerdown', 'pointerup']);
  await page.context().close();
});
