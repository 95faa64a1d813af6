import AxeBuilder from '@axe-core/playwright';
import { expect, test, type Locator, type Page } from '@playwright/test';
import { footprintsReady, moduleCount, sceneFile, zoomToModuleLevel } from './helpers';

// Issue 27, "Done when": a shopper who has never seen luxbox configures a working L-shaped rail
// system on a German phone without a dead end, without reading an id or a Greek letter, and shares
// it. One journey, touch only, 390 × 844, de-DE: Planung beginnen → the L corner from the first-run
// card → + until refused → the one-tap remedy at the control → more modules → 3D and back → Teilen…
// (the Web Share API recorded, as in shareLink.spec.ts) → the shared link in a fresh browser shows
// the same configuration. At each step the shopper-visible text (Expert off) is checked for ids and
// Greek letters, and axe finds no violations. Screenshots: test-results/journey-*.png (docs/planner.md, "Issue 27 coverage").

const PHONE = { viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true, locale: 'de-DE', reducedMotion: 'reduce' } as const;

/** What the shopper reads: the visible text of the page plus the tooltips and accessible names of visible elements. */
function shopperText(page: Page): Promise<string> {
  return page.evaluate(() => {
    const visible = (el: Element) => {
      const r = el.getBoundingClientRect();
      return r.width > 0 && r.height > 0 && getComputedStyle(el).visibility !== 'hidden';
    };
    const labels = [...document.querySelectorAll('[title], [aria-label]')].filter(visible).flatMap((el) => [el.getAttribute('title') ?? '', el.getAttribute('aria-label') ?? '']);
    return [document.body.innerText, ...labels].join('\n');
  });
}

/**
 * Internal ids the shopper must never read: every id in the configuration (systems, rails, modules,
 * furniture) as a whole word, and the id shapes the core makes (a letter and a number: s1, r2, m3,
 * o12, f4). Greek letters (ρ, Φ, η …) are engineering notation: none in the shopper's UI.
 */
async function expectNoJargon(page: Page, step: string): Promise<void> {
  const text = await shopperText(page);
  const file = JSON.parse(await page.evaluate(() => window.luxbox!.getConfig())) as { configuration: Record<string, unknown> };
  const ids = new Set<string>();
  const collect = (v: unknown) => {
    if (Array.isArray(v)) v.forEach(collect);
    else if (v && typeof v === 'object') {
      for (const [k, x] of Object.entries(v)) {
        if (k === 'id' && typeof x === 'string') ids.add(x);
        else collect(x);
      }
    }
  };
  collect(file.configuration);
  const words = new Set(text.split(/[^\p{L}\p{N}_-]+/u));
  // Catalog ids (type names such as "spot") are words a shopper may read; configuration ids with a digit are not.
  const leaked = [...ids].filter((id) => /\d/.test(id) && words.has(id));
  expect(leaked, `${step}: ids in the shopper's text`).toEqual([]);
  expect(text.match(/\b[srmofc]\d+\b/g) ?? [], `${step}: id-shaped words`).toEqual([]);
  expect(text.match(/[\u0370-\u03ff]/g) ?? [], `${step}: Greek letters`).toEqual([]);
}

/** axe's violations of any impact, as readable lines (the Tests: "an axe scan stays at zero violations"). */
async function violations(page: Page): Promise<string[]> {
  const result = await new AxeBuilder({ page }).analyze();
  return result.violations.flatMap((v) => v.nodes.map((n) => `${v.impact} ${v.id} (${v.help}): ${n.target.join(' ')}`));
}

const tapIt = (l: Locator) => l.tap({ force: true });

test('German phone, touch: the L corner from the first run, past the full driver by one tap, 3D and back, shared and reopened', async ({ browser }) => {
  const context = await browser.newContext(PHONE);
  const page = await context.newPage();
  // A phone's Web Share API, recorded (headless Chromium on Linux has none).
  await page.addInitScript(() => {
    const calls: ShareData[] = [];
    (window as unknown as { shareCalls: ShareData[] }).shareCalls = calls;
    Object.defineProperty(navigator, 'share', { value: async (data: ShareData) => void calls.push(data), configurable: true });
  });
  await page.goto('/?quality=fast');
  await expectNoJargon(page, 'welcome');
  await tapIt(page.getByRole('button', { name: 'Planung beginnen' }));

  // 1. The empty plan leads: the card offers the L corner.
  const card = page.getByTestId('first-run');
  await expect(card).toContainText('Mit einer Vorlage beginnen');
  await expectNoJargon(page, 'first run');
  expect(await violations(page), 'first run').toEqual([]);
  await page.screenshot({ path: 'test-results/journey-1-first-run.png' });
  await tapIt(page.getByTestId('first-run-corner-l'));
  await expect(card).toHaveCount(0);
  await footprintsReady(page);
  const placed = await sceneFile(page);
  expect(placed.configuration.systems).toHaveLength(1);
  expect(placed.configuration.systems[0].rails.length).toBeGreaterThanOrEqual(2);

  // 2. + is refused (the driver is full); the reason and the fix appear at the control; one tap on the fix.
  await zoomToModuleLevel(page);
  await expectNoJargon(page, 'the L corner placed');
  const plus = page.locator('[data-testid^="plus-"] button').first();
  await expect(plus).toHaveAttribute('aria-disabled', 'true');
  const before = await moduleCount(page);
  await tapIt(plus);
  const tip = page.getByTestId('disabled-tip');
  await expect(tip).toContainText(/Treiber ist voll/);
  await expect(tip.getByTestId('remedy')).toHaveText(/^321,6-W-Treiber verwenden/);
  // A message starts with a capital (issue 27, "Words for shoppers").
  expect((await tip.innerText()).trim()).toMatch(/^\p{Lu}/u);
  await expectNoJargon(page, 'refusal tip');
  expect(await violations(page), 'refusal tip').toEqual([]);
  await page.screenshot({ path: 'test-results/journey-2-remedy.png' });
  await tapIt(tip.getByTestId('remedy'));
  await expect(tip).toHaveCount(0);

  // 3. More modules: + adds until this rail is full; a further refusal (if any) explains itself again, never silently.
  let added = 0;
  for (let i = 0; i < 6; i++) {
    if ((await plus.getAttribute('aria-disabled')) === 'true') break;
    await tapIt(plus);
    added++;
    await expect.poll(() => moduleCount(page)).toBe(before + added);
  }
  expect(added).toBeGreaterThanOrEqual(1);
  if ((await plus.getAttribute('aria-disabled')) === 'true') {
    await tapIt(plus);
    await expect(tip).toBeVisible();
    expect((await tip.innerText()).trim()).toMatch(/^\p{Lu}/u);
    await expectNoJargon(page, 'a later refusal');
    await page.screenshot({ path: 'test-results/journey-3-later-refusal.png' });
    await tapIt(tip.getByTestId('disabled-tip-close'));
    await expect(tip).toHaveCount(0);
  }
  await footprintsReady(page);
  await expectNoJargon(page, 'modules added');
  await page.screenshot({ path: 'test-results/journey-3-modules.png' });
  const configured = await sceneFile(page);

  // 4. 3D and back: the configuration is untouched.
  await tapIt(page.getByTestId('tool-3d'));
  await expect(page.getByTestId('view3d')).toBeVisible();
  await expect(page.getByTestId('view3d-canvas')).toBeVisible();
  await expectNoJargon(page, '3D view');
  // The dimmers name each module by its catalog name and place ("Spot 30°, Modul 2 von 4 auf Schiene 1"), never "spot m3".
  await tapIt(page.locator('.viewer3d-modules summary'));
  await expect(page.locator('.viewer3d-modules')).toHaveAttribute('open', '');
  await expect(page.locator('.viewer3d-modules label').first()).toContainText(/^\S.*, Modul 1 von \d+ auf Schiene 1: \d+\s%$/);
  await expectNoJargon(page, '3D view, dimmers open');
  expect(await violations(page), '3D view, dimmers open').toEqual([]);
  await page.screenshot({ path: 'test-results/journey-4-3d.png' });
  await tapIt(page.getByTestId('tool-3d'));
  await expect(page.getByTestId('plan')).toBeVisible();
  expect(await sceneFile(page)).toEqual(configured);

  // 5. Share: the drawer, then one tap on "Link teilen" opens the system share sheet with the link.
  await tapIt(page.getByTestId('panel-toggle'));
  await expect(page.locator('.side-panel.open')).toBeVisible();
  await expectNoJargon(page, 'side panel');
  expect(await violations(page), 'side panel').toEqual([]);
  await tapIt(page.getByTestId('share'));
  await expect.poll(() => page.evaluate(() => (window as unknown as { shareCalls: ShareData[] }).shareCalls.length)).toBe(1);
  await page.screenshot({ path: 'test-results/journey-5-shared.png' });
  const calls = await page.evaluate(() => (window as unknown as { shareCalls: ShareData[] }).shareCalls);
  expect(calls[0].url).toBe(await page.getByTestId('share-link').inputValue());
  expect(calls[0].url).toContain('#c=');

  // 6. The shared link in a fresh phone browser: the same configuration.
  const other = await browser.newContext(PHONE);
  const p2 = await other.newPage();
  await p2.goto(calls[0].url!.replace(/^https?:\/\/[^/]+/, new URL(page.url()).origin));
  await expect(p2.getByTestId('plan')).toBeVisible();
  expect((await sceneFile(p2)).configuration).toEqual(configured.configuration);
  await expectNoJargon(p2, 'the shared link opened');
  await p2.screenshot({ path: 'test-results/journey-6-reopened.png' });
  await other.close();
  await context.close();
});
