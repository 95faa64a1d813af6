import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test, type Page } from '@playwright/test';

// The shop page of embed.html (src/hosts/embedDemo) mounts luxbox with its own room, locale, catalog and
// autosave key, and reads everything through the public API (docs/embedding.md). These tests
// drive that page like a shopper and like the host's own script (window.shopDemo.instance).

/** Intl puts no-break spaces (U+00A0, U+202F) into prices; compare with plain spaces. */
const plain = (s: string | null) => (s ?? '').replace(/[\u00a0\u202f]/g, ' ').trim();

async function text(page: Page, testId: string): Promise<string> {
  return plain(await page.getByTestId(testId).textContent());
}

const errors: string[] = [];
test.beforeEach(({ page }) => {
  errors.length = 0;
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  page.on('pageerror', (e) => errors.push(e.message));
});
test.afterEach(() => {
  expect(errors, 'console errors on the shop page').toEqual([]);
});

async function bomTotal(page: Page): Promise<number> {
  return page.evaluate(() => window.shopDemo!.instance!.getBillOfMaterials().total);
}

test('mounts with the host room and locale; the host total follows actions run by name', async ({ page }) => {
  await page.goto('/embed.html');
  // The room passed as an option, not the configurator's default and not its room-setup page.
  await expect(page.getByTestId('plan')).toBeVisible();
  // The German storefront (de-DE) gets a German configurator with German number formatting.
  await expect(page.locator('.room-label')).toHaveText('Raum 5,5 × 4,2 × 2,7 m');
  await expect(page.getByTestId('plan-svg')).toHaveAttribute('aria-label', /^Raumplan, 5,5 mal 4,2 m/);
  expect(plain(await page.getByTestId('header-total').textContent())).toBe('0,00 €');
  expect(await text(page, 'host-total')).toBe('0,00 €');

  // The shop's brand in the configurator's header, not "luxbox" (issue #27).
  await expect(page.locator('.app-header h1')).toHaveText('Lichtwerk');

  // Disabled action, reported with the model's reason in the configurator's language (issue #27:
  // the embed speaks one language): the 6 m line does not fit a 5.5 m room.
  const longLine = page.getByTestId('host-action-long-line');
  await expect(longLine).toBeDisabled();
  const german = 'kein freier Platz für „Lange Linie“ in diesem Raum';
  await expect(page.getByTestId('host-action-note-long-line')).toHaveText(german);
  const listed = await page.evaluate(() => window.shopDemo!.instance!.listActions({ placePreset: { presetId: 'long-line' } }).find((a) => a.name === 'placePreset'));
  expect(listed).toEqual({ name: 'placePreset', label: expect.any(String), enabled: false, reason: german });
  expect(await page.evaluate(() => window.shopDemo!.instance!.runAction('placePreset', { presetId: 'long-line' }))).toEqual({ ok: false, reason: german });

  // A host button runs placePreset by name. Expected: 1.5 m rail 40 + 60·1.5 = 130, 2 suspension
  // kits 2·18, 1 power feed 65 with the driver the preset ships with (HLG-240H-48, 84.90: room for
  // two more spots), 3 narrow spots 3·189 (catalog prices) = 882.90 EUR, in de-DE format.
  await expect(page.getByTestId('host-action-single')).toBeEnabled();
  await page.getByTestId('host-action-single').click();
  await expect(page.getByTestId('host-total')).toHaveText(/^882,90\s€$/);
  expect(plain(await page.getByTestId('header-total').textContent())).toBe('882,90 €');
  expect(await page.evaluate(() => window.shopDemo!.changes)).toBe(1);
  await expect(page.getByTestId('host-bom').locator('tr')).toHaveCount(5);

  // An action run from the host's script: onChange alone brings the host's total up to date.
  const run = await page.evaluate(() => window.shopDemo!.instance!.runAction('placePreset', { presetId: 'corner-l' }));
  expect(run).toEqual({ ok: true });
  const total = await bomTotal(page);
  expect(total).toBeGreaterThan(1000);
  const expected = new Intl.NumberFormat('de-DE', { style: 'currency', currency: 'EUR' }).format(total);
  await expect(page.getByTestId('host-total')).toHaveText(expected);
  // German grouping and decimal comma, e.g. "1.234,50 €".
  expect(await text(page, 'host-total')).toMatch(/^\d{1,3}(\.\d{3})+,\d{2} €$/);
  expect(plain(await page.getByTestId('header-total').textContent())).toBe(plain(expected));
  expect(await page.evaluate(() => window.shopDemo!.changes)).toBe(2);

  // Undo from the host page goes back to the single rail.
  await page.getByTestId('host-undo').click();
  await expect(page.getByTestId('host-total')).toHaveText(/^882,90\s€$/);

  // The shop's autosave key is used; the standalone app's is never touched.
  const keys = await page.evaluate(() => Object.keys(localStorage).sort());
  expect(keys).toEqual(['lichtwerk.luxbox.de.v1']);
});

test("the API speaks the configurator's language (BOM names, reasons) unless apiLanguage is en; brand null shows none", async ({ page }) => {
  await page.goto('/embed.html');
  await page.getByTestId('host-action-single').click();
  await page.evaluate(() => window.shopDemo!.instance!.whenReady());
  const names = await page.evaluate(() => window.shopDemo!.instance!.getBillOfMaterials().lines.map((l) => l.name));
  // German names of the catalog entries, as the planner's own bill of materials shows them (German number format).
  expect(names).toEqual([
    'Tragschiene 1,50 m',
    'Abhängeset (Stahlseil, Deckenbaldachin)',
    'Einspeiseset (End- oder Verbindereinspeisung, Treiberbox an der Decke)',
    'Treiber Mean Well HLG-240H-48, 240 W 48 V DC',
    'Strahler, Enger Spot 12°, 3000 K',
  ]);

  await page.goto('/embed.html?apiLanguage=en&brand=none');
  await expect(page.getByTestId('plan')).toBeVisible();
  await page.evaluate(() => window.shopDemo!.instance!.whenReady());
  await expect(page.locator('.app-header h1')).toHaveCount(0);
  // The configurator itself still speaks German; the API gives the core's English sentences.
  await expect(page.locator('.room-label')).toHaveText('Raum 5,5 × 4,2 × 2,7 m');
  expect(await page.evaluate(() => window.shopDemo!.instance!.runAction('placePreset', { presetId: 'long-line' }))).toEqual({ ok: false, reason: "no free space for 'Long line' in this room" });
});

test('add to cart copies the bill of materials into the host cart', async ({ page }) => {
  await page.goto('/embed.html');
  await expect(page.getByTestId('add-to-cart')).toBeDisabled();
  await page.getByTestId('host-action-single').click();
  await page.getByTestId('add-to-cart').click();
  const bom = await page.evaluate(() => window.shopDemo!.instance!.getBillOfMaterials());
  const cart = page.getByTestId('cart').locator('li');
  await expect(cart).toHaveCount(bom.lines.length);
  for (const [i, line] of bom.lines.entries()) {
    await expect(cart.nth(i).locator('.cart-article')).toHaveText(line.article);
    await expect(cart.nth(i).locator('.cart-name')).toHaveText(`${line.count}× ${line.name}`);
  }
  expect(await text(page, 'cart-total')).toBe('882,90 €');
  // Adding the same configuration again adds to the counts (same articles), not new lines.
  await page.getByTestId('add-to-cart').click();
  await expect(cart).toHaveCount(bom.lines.length);
  await expect(cart.first().locator('.cart-name')).toHaveText(`${2 * bom.lines[0].count}× ${bom.lines[0].name}`);
  expect(await text(page, 'cart-total')).toBe('1.765,80 €');
});

test("assetBase: the plan and the 3D view load photometry from the host's folder, each file once", async ({ page }) => {
  const fromHost: string[] = [];
  const fromApp: string[] = [];
  await page.route('**/shop-assets/ies/**', async (route) => {
    const name = new URL(route.request().url()).pathname.split('/').pop()!;
    fromHost.push(name);
    await route.fulfill({ body: readFileSync(join('public/ies', name)), contentType: 'text/plain' });
  });
  page.on('request', (r) => {
    if (/\/ies\//.test(r.url()) && !r.url().includes('/shop-assets/')) fromApp.push(r.url());
  });
  await page.goto('/embed.html?assetBase=/shop-assets/');
  await page.getByTestId('host-action-single').click();
  await page.getByTestId('tool-3d').click();
  await expect.poll(() => page.evaluate(() => window.shopDemo!.instance!.view3d().lit), { timeout: 90_000, intervals: [250] }).toBe(true);
  expect(fromHost.length).toBeGreaterThan(0);
  expect(new Set(fromHost).size).toBe(fromHost.length);
  expect(fromApp).toEqual([]);
});

test('destroy() unmounts cleanly and a re-mount works and restores the autosave', async ({ page }) => {
  await page.goto('/embed.html');
  await page.getByTestId('host-action-single').click();
  await expect(page.getByTestId('host-total')).toHaveText(/^882,90\s€$/);
  const before = await page.evaluate(() => window.shopDemo!.instance!.getConfig());
  // Destroy while the 3D view is open and still refining: its WebGL work must stop without errors.
  await page.getByTestId('tool-3d').click();
  await expect(page.getByTestId('view3d-canvas')).toBeVisible();
  await expect.poll(() => page.evaluate(() => window.shopDemo!.instance!.view3d().lit), { timeout: 90_000, intervals: [250] }).toBe(true);

  // Keep the old handle to check it refuses use after destroy().
  await page.evaluate(() => {
    (window as unknown as { oldInstance: unknown }).oldInstance = window.shopDemo!.instance;
  });
  await page.getByTestId('toggle-configurator').click();
  expect(await page.evaluate(() => window.shopDemo!.instance)).toBeNull();
  expect(await page.getByTestId('configurator-host').evaluate((el) => el.childElementCount)).toBe(0);
  await expect(page.getByTestId('plan')).toHaveCount(0);
  await expect(page.getByTestId('view3d-canvas')).toHaveCount(0);
  await expect(page.getByTestId('host-action-single')).toBeDisabled();
  const afterDestroy = await page.evaluate(() => {
    try {
      (window as unknown as { oldInstance: { getConfig(): string } }).oldInstance.getConfig();
      return 'no error';
    } catch (e) {
      return (e as Error).message;
    }
  });
  expect(afterDestroy).toBe('this luxbox instance was destroyed');

  await page.getByTestId('toggle-configurator').click();
  await expect(page.getByTestId('plan')).toBeVisible();
  await expect(page.getByTestId('plan')).toHaveCount(1);
  expect(await page.evaluate(() => window.shopDemo!.instance!.getConfig())).toBe(before);
  await expect(page.getByTestId('host-total')).toHaveText(/^882,90\s€$/);
  // The new instance is live: its actions and onChange work.
  await page.getByTestId('host-action-corner-l').click();
  await expect(page.getByTestId('host-total')).not.toHaveText(/^882,90\s€$/);
  expect(await page.evaluate(() => JSON.parse(window.shopDemo!.instance!.getConfig()).configuration.systems.length)).toBe(2);
});

test('setConfig with a corrupt scene file throws a clear InputError and changes nothing', async ({ page }) => {
  await page.goto('/embed.html');
  await page.getByTestId('host-action-single').click();
  await expect(page.getByTestId('host-total')).toHaveText(/^882,90\s€$/);
  const result = await page.evaluate(() => {
    const lx = window.shopDemo!.instance!;
    const before = lx.getConfig();
    const changesBefore = window.shopDemo!.changes;
    const attempt = (input: string) => {
      try {
        lx.setConfig(input);
        return null;
      } catch (e) {
        return { name: (e as Error).name, message: (e as Error).message };
      }
    };
    const truncated = attempt(before.slice(0, before.length / 2));
    const badRoom = attempt(before.replace(/"width":\s*5\.5/, '"width": -3'));
    return { truncated, badRoom, unchanged: lx.getConfig() === before, changes: window.shopDemo!.changes - changesBefore };
  });
  expect(result.truncated?.name).toBe('SceneFileError');
  expect(result.truncated?.message).toMatch(/^setConfig is not valid JSON/);
  expect(result.badRoom?.name).toBe('SceneFileError');
  expect(result.badRoom?.message).toMatch(/^setConfig: .*room.*width/);
  expect(result.unchanged).toBe(true);
  expect(result.changes).toBe(0);
  expect(await text(page, 'host-total')).toBe('882,90 €');
  await expect(page.locator('.room-label')).toHaveText('Raum 5,5 × 4,2 × 2,7 m');
});

test("a shop's own catalog priced in CHF changes the prices shown (de-CH)", async ({ page }) => {
  await page.goto('/embed.html?shop=ch');
  await page.getByTestId('host-action-single').click();
  // The Swiss price list is the EUR one × 0.95, rounded to 5 rappen: rail base 38 + 57·1.5 = 123.50,
  // suspension 17.10 (×2), feed 61.75, HLG-240H-48 driver 80.65 (84.90 × 0.95 = 80.655), narrow spot 179.55 (×3); sum 838.75 CHF (the EUR page shows 882,90 €).
  const bom = await page.evaluate(() => window.shopDemo!.instance!.getBillOfMaterials());
  expect(bom.currency).toBe('CHF');
  expect(bom.lines.map((l) => [l.article, l.count, l.unitPrice])).toEqual([
    ['LX-RAIL-1500', 1, 123.5],
    ['LX-SUSP', 2, 17.1],
    ['LX-FEED', 1, 61.75],
    ['MW-HLG-240H-48', 1, 80.65],
    ['LX-SPOT-N12-3000', 3, 179.55],
  ]);
  expect(bom.total).toBe(838.75);
  await expect(page.getByTestId('host-total')).toHaveText(/^CHF\s838\.75$/);
  expect(plain(await page.getByTestId('header-total').textContent())).toBe('CHF 838.75');
  expect(plain(await page.getByTestId('bom-total').textContent())).toBe('CHF 838.75');
  // Swiss grouping once the total passes 1000: an apostrophe (ASCII in current CLDR data, U+2019 in older).
  await page.getByTestId('host-action-corner-l').click();
  await expect(page.getByTestId('host-total')).toHaveText(/^CHF\s\d{1,3}(['’]\d{3})+\.\d{2}$/);
  expect(await page.evaluate(() => Object.keys(localStorage))).toEqual(['lichtwerk.luxbox.ch.v1']);
});

test("luxbox's styles stay inside its root: the shop page keeps its own fonts, margins and box model", async ({ page }) => {
  await page.goto('/embed.html');
  await expect(page.getByTestId('plan')).toBeVisible();
  // Open the 3D view so that its lazily loaded stylesheet is on the page too.
  await page.getByTestId('tool-3d').click();
  await expect(page.getByTestId('view3d-canvas')).toBeVisible();
  const r = await page.evaluate(() => {
    const root = document.getElementById('configurator')!;
    const rules: CSSStyleRule[] = [];
    const collect = (list: CSSRuleList) => {
      for (const rule of Array.from(list)) {
        if (rule instanceof CSSStyleRule) rules.push(rule);
        else if ('cssRules' in rule) collect((rule as CSSGroupingRule).cssRules); // @container, @media
      }
    };
    for (const sheet of Array.from(document.styleSheets)) collect(sheet.cssRules);
    const all = Array.from(document.querySelectorAll('*'));
    const outside = all.filter((el) => !root.contains(el)); // html, body and the shop's own elements
    const inside = all.filter((el) => root.contains(el));
    const matchesAny = (els: Element[], selector: string) => els.some((el) => el.matches(selector));
    const foreign = rules.filter((rule) => !rule.selectorText.startsWith('body.shop'));
    const shopBody = rules.find((rule) => rule.selectorText === 'body.shop')!.style;
    const style = (el: Element) => {
      const s = getComputedStyle(el);
      return { fontFamily: s.fontFamily, fontSize: s.fontSize, color: s.color, backgroundColor: s.backgroundColor, lineHeight: s.lineHeight, boxSizing: s.boxSizing, margin: [s.marginTop, s.marginRight, s.marginBottom, s.marginLeft] };
    };
    return {
      foreignRules: foreign.length,
      foreignRulesStylingInside: foreign.filter((rule) => matchesAny(inside, rule.selectorText)).length,
      leaks: foreign.filter((rule) => matchesAny(outside, rule.selectorText)).map((rule) => rule.selectorText),
      declared: {
        fontFamily: shopBody.fontFamily,
        fontSize: shopBody.fontSize,
        color: shopBody.color,
        backgroundColor: shopBody.backgroundColor,
        margin: [shopBody.marginTop, shopBody.marginRight, shopBody.marginBottom, shopBody.marginLeft],
      },
      body: style(document.body),
      html: style(document.documentElement),
      buyBox: style(document.querySelector('.buy-box')!),
      hostBoxSizing: getComputedStyle(root).boxSizing,
      appFont: getComputedStyle(root.querySelector('.app')!).fontFamily,
    };
  });
  // The detector sees luxbox's rules at work inside its root (else the leak check below proves nothing)...
  expect(r.foreignRules).toBeGreaterThan(100);
  expect(r.foreignRulesStylingInside).toBeGreaterThan(50);
  // ...and no rule other than the shop's own matches html, body or any shop element.
  expect(r.leaks).toEqual([]);
  // The body's computed style is exactly what the shop's CSS declares (Georgia, 15 px, margin 0, its colours)...
  expect(r.declared.fontFamily).toMatch(/^Georgia/);
  expect({ fontFamily: r.body.fontFamily, fontSize: r.body.fontSize, color: r.body.color, backgroundColor: r.body.backgroundColor, margin: r.body.margin }).toEqual(r.declared);
  // ...and what it leaves unset keeps the browser's defaults (luxbox used to set 1.4 and border-box on them).
  for (const s of [r.html, r.body, r.buyBox]) {
    expect(s.lineHeight).toBe('normal');
    expect(s.boxSizing).toBe('content-box');
  }
  expect(r.html.margin).toEqual(['0px', '0px', '0px', '0px']);
  // The box the shop sized keeps the shop's box model; luxbox brings its own font inside it.
  expect(r.hostBoxSizing).toBe('content-box');
  expect(r.appFont).toMatch(/^system-ui/);
});

test('in the 860 px box on a 1440 px window the layout follows the box: side panel as a drawer, 3D view as wide as the box', async ({ page }) => {
  await page.setViewportSize({ width: 1440, height: 900 });
  await page.goto('/embed.html');
  await expect(page.getByTestId('plan')).toBeVisible();
  const host = page.getByTestId('configurator-host');
  expect(await host.evaluate((el) => el.clientWidth)).toBe(860);
  // Narrow layout (the one the standalone app has in a window this wide): the panel is a drawer
  // behind the header's Presets button, and it opens inside the box.
  const toggle = page.locator('.panel-toggle'); // reads 'Vorlagen' (Presets), then 'Schließen' (Close) while the drawer is open: the German storefront
  const panel = page.getByRole('complementary', { name: 'Vorlagen und Preis' });
  await expect(toggle).toBeVisible();
  await expect(toggle).toHaveText('Vorlagen');
  await expect(panel).toBeHidden();
  await toggle.click();
  await expect(panel).toBeVisible();
  await expect(toggle).toHaveText('Schließen');
  const [pb, hb] = [(await panel.boundingBox())!, (await host.boundingBox())!];
  expect(pb.x).toBeGreaterThanOrEqual(hb.x);
  expect(pb.x + pb.width).toBeLessThanOrEqual(hb.x + hb.width + 0.5);
  expect(pb.width).toBe(340);
  await toggle.click();
  await expect(panel).toBeHidden();
  // The 3D image takes the box's width (the viewer's panel goes below it), not 860 − 320 − 240 = 300 px.
  await page.getByTestId('tool-3d').click();
  const canvas = page.getByTestId('view3d-canvas');
  await expect(canvas).toBeVisible();
  const width = (await canvas.boundingBox())!.width;
  expect(width).toBeGreaterThan(500);
  expect(Math.abs(width - 860)).toBeLessThanOrEqual(1);
});
