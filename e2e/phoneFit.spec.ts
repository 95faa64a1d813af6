import { expect, test, type Page } from '@playwright/test';

// Every language fits every phone (issue 27, docs/accessibility.md "Narrow phones"): the header
// and the bottom bar of the plan, in the standalone app and in the shop embed, at the narrowest
// phones we support, in the languages with the longest words. Touch, springs skipped.
test.use({ hasTouch: true, isMobile: true, reducedMotion: 'reduce' });

const PHONES = [
  { width: 360, height: 640 },
  { width: 375, height: 667 },
];
const LANGUAGES = ['de', 'fr', 'it'] as const;
const EMBED_LOCALE = { de: 'de-DE', fr: 'fr-CH', it: 'it-CH' } as const;

interface Overflow {
  what: string;
  left: number;
  right: number;
  top: number;
  bottom: number;
}

/**
 * Every button, select, input and link of the header and the bottom bar whose box is not fully
 * inside the viewport (or is hidden by the bar's overflow), and the bars themselves when their
 * content is wider than they are.
 */
async function outside(page: Page, bars = '.luxbox .app-header, .luxbox .bottom-bar'): Promise<Overflow[]> {
  return page.evaluate((bars) => {
    const vw = document.documentElement.clientWidth;
    const vh = window.innerHeight;
    const out: Overflow[] = [];
    for (const bar of document.querySelectorAll<HTMLElement>(bars)) {
      const b = bar.getBoundingClientRect();
      if (bar.scrollWidth > bar.clientWidth) out.push({ what: `${bar.className} scrollWidth ${bar.scrollWidth} > ${bar.clientWidth}`, left: b.left, right: b.right, top: b.top, bottom: b.bottom });
      for (const el of bar.querySelectorAll<HTMLElement>('button, select, input, a, .total, h1')) {
        const r = el.getBoundingClientRect();
        const cs = getComputedStyle(el);
        if (cs.display === 'none' || cs.visibility === 'hidden') continue;
        const name = `${el.tagName.toLowerCase()} ${el.dataset.testid ?? el.getAttribute('aria-label') ?? el.textContent?.trim()}`;
        // Inside the viewport and inside its bar (a bar that clips with overflow hides what sticks out).
        const inside = r.width > 0 && r.height > 0 && r.left >= -0.5 && r.right <= vw + 0.5 && r.top >= -0.5 && r.bottom <= vh + 0.5 && r.left >= b.left - 0.5 && r.right <= b.right + 0.5;
        // Text that does not fit its own box (clipped or ellipsed label).
        const clipped = el.scrollWidth > el.clientWidth && el.tagName !== 'SELECT' && el.tagName !== 'INPUT';
        if (!inside || clipped) out.push({ what: `${name}${clipped ? ` text ${el.scrollWidth} > ${el.clientWidth}` : ''}`, left: Math.round(r.left), right: Math.round(r.right), top: Math.round(r.top), bottom: Math.round(r.bottom) });
      }
    }
    return out;
  }, bars);
}

/** The bars' controls that are touch targets smaller than 44 px (docs/accessibility.md). */
async function smallTargets(page: Page): Promise<string[]> {
  return page.evaluate(() =>
    [...document.querySelectorAll<HTMLElement>('.luxbox .app-header button, .luxbox .app-header select, .luxbox .bottom-bar button')]
      .filter((el) => getComputedStyle(el).display !== 'none')
      .map((el) => ({ el, r: el.getBoundingClientRect() }))
      .filter(({ r }) => r.width < 44 - 0.5 || r.height < 44 - 0.5)
      .map(({ el, r }) => `${el.dataset.testid ?? el.getAttribute('aria-label')} ${r.width.toFixed(0)}×${r.height.toFixed(0)}`),
  );
}

/** The bottom bar's buttons: each has an accessible name (its full label) even where the visible text is shortened. */
async function unnamedTools(page: Page): Promise<string[]> {
  return page.evaluate(() => [...document.querySelectorAll<HTMLElement>('.luxbox .bottom-bar button')].filter((b) => !(b.getAttribute('aria-label') ?? '').trim()).map((b) => b.dataset.testid ?? '?'));
}

for (const phone of PHONES) {
  for (const lang of LANGUAGES) {
    test.describe(`${phone.width} × ${phone.height}, ${lang}`, () => {
      test.use({ viewport: phone });

      test('app: header and bottom bar fit, with a system selected', async ({ page }) => {
        await page.goto(`/?demo&lang=${lang}`);
        await expect(page.getByTestId('plan')).toBeVisible();
        await page.getByTestId('tool-select').tap();
        await expect(page.locator('[data-testid^="fields-"], [data-testid^="move-"]').first()).toBeAttached();
        expect(await outside(page)).toEqual([]);
        expect(await smallTargets(page)).toEqual([]);
        expect(await unnamedTools(page)).toEqual([]);
        // The same in the 3D view, whose toggle reads "2D".
        await page.getByTestId('tool-3d').tap();
        await expect(page.getByTestId('back-2d')).toBeVisible();
        expect(await outside(page)).toEqual([]);
      });

      test("shop embed: the configurator's header and bottom bar fit, with a system selected", async ({ page }) => {
        await page.goto(`/embed.html?locale=${EMBED_LOCALE[lang]}`);
        await expect(page.getByTestId('plan')).toBeVisible();
        expect(await page.evaluate(() => window.shopDemo!.instance!.runAction('placePreset', { presetId: 'single' }))).toEqual({ ok: true });
        await page.getByTestId('tool-select').tap();
        await expect(page.locator('[data-testid^="fields-"], [data-testid^="move-"]').first()).toBeAttached();
        await page.getByTestId('configurator-host').scrollIntoViewIfNeeded();
        const host = (await page.getByTestId('configurator-host').boundingBox())!;
        expect(host.x).toBeGreaterThanOrEqual(0);
        expect(host.x + host.width).toBeLessThanOrEqual(phone.width);
        // The shop page scrolls: each bar is checked where it is on screen.
        for (const bar of ['.luxbox .app-header', '.luxbox .bottom-bar']) {
          await page.locator(bar).scrollIntoViewIfNeeded();
          expect(await outside(page, bar), bar).toEqual([]);
        }
        expect(await smallTargets(page)).toEqual([]);
      });
    });
  }
}

test.describe('phone drawer, 375 × 667', () => {
  test.use({ viewport: { width: 375, height: 667 } });

  test('closing the drawer by its toggle or a tap beside it leaves nothing pressed; the next tap on Options opens it', async ({ page }) => {
    await page.goto('/?demo&lang=de');
    await expect(page.getByTestId('plan')).toBeVisible();
    const optionsButton = page.getByTestId('tool-options');
    const toggle = page.getByTestId('panel-toggle');
    const drawer = page.getByRole('complementary');
    const panel = page.getByTestId('options-panel');
    /** aria-pressed and the look agree: the accent fill only while pressed. */
    const looksPressed = () => optionsButton.evaluate((b) => getComputedStyle(b).backgroundColor === 'rgb(31, 95, 191)');
    const expectClosed = async () => {
      await expect(drawer).toBeHidden();
      await expect(optionsButton).toHaveAttribute('aria-pressed', 'false');
      await expect(toggle).toHaveAttribute('aria-expanded', 'false');
      expect(await looksPressed()).toBe(false);
    };
    const open = async () => {
      await optionsButton.tap();
      await expect(panel).toBeVisible();
      await expect(optionsButton).toHaveAttribute('aria-pressed', 'true');
      await expect(toggle).toHaveAttribute('aria-expanded', 'true');
      expect(await looksPressed()).toBe(true);
    };
    await expectClosed();
    // 1. The header's toggle (✕ while open).
    await open();
    await toggle.tap();
    await expectClosed();
    // 2. A tap beside the drawer, on the veiled plan (the drawer leaves a strip on the left).
    await open();
    const box = (await drawer.boundingBox())!;
    expect(box.x).toBeGreaterThan(20);
    await page.touchscreen.tap(box.x / 2, 300);
    await expectClosed();
    // 3. Closed twice in a row by the toggle: each next tap on Options opens it (it used to toggle a hidden state and show nothing).
    await open();
    await toggle.tap();
    await expectClosed();
    await open();
    // The drawer covers the bottom bar's Options button (x ≈ 130 of 375): the toggle is the way to close it from there.
    await toggle.tap();
    await expectClosed();
  });
});

/**
 * The fraction of the plan's area under the on-plan fields of the selected system (move, length
 * and their fold button), as the union of their boxes clipped to the plan, sampled every 2 px.
 */
async function coveredFraction(page: Page): Promise<number> {
  return page.evaluate(() => {
    const plan = document.querySelector<HTMLElement>('[data-testid="plan"]')!.getBoundingClientRect();
    const boxes = [...document.querySelectorAll<HTMLElement>('.plan-control.move-field, .plan-control.length-field, .plan-control.fields-toggle-wrap')].map((el) => el.getBoundingClientRect());
    let covered = 0;
    let all = 0;
    for (let y = plan.top + 1; y < plan.bottom; y += 2) {
      for (let x = plan.left + 1; x < plan.right; x += 2) {
        all++;
        if (boxes.some((b) => x >= b.left && x < b.right && y >= b.top && y < b.bottom)) covered++;
      }
    }
    return covered / all;
  });
}

test.describe('on-plan fields on a phone, 375 × 667', () => {
  test.use({ viewport: { width: 375, height: 667 } });

  test("the selected system's x/z and length fields fold behind one button and cover under 2 % of the plan until unfolded", async ({ page }) => {
    // The demo: the L corner (three rails) selected, the plan at system level.
    await page.goto('/?demo&lang=de');
    await expect(page.getByTestId('plan')).toHaveAttribute('data-level', 'system');
    await page.getByTestId('tool-select').tap();
    const toggle = page.locator('[data-testid^="fields-toggle-"]');
    await expect(toggle).toHaveAttribute('aria-expanded', 'false');
    await expect(toggle).toHaveAccessibleName('Position und Längen bearbeiten');
    await expect(page.locator('.plan-control.move-field, .plan-control.length-field')).toHaveCount(0);
    const folded = await coveredFraction(page);
    // Unfolded: the fields as every plan showed them before (issue 27: "cover much of the small plan").
    await toggle.tap();
    await expect(toggle).toHaveAttribute('aria-expanded', 'true');
    await expect(toggle).toBeFocused();
    const x = page.getByRole('textbox', { name: 'Systemposition x (m)' });
    await expect(x).toBeVisible();
    const unfolded = await coveredFraction(page);
    console.log(`plan covered by the system's fields at 375 × 667: folded ${(folded * 100).toFixed(1)} %, unfolded ${(unfolded * 100).toFixed(1)} %`);
    // Measured (2026-11-27, Chromium): folded 0.9 %, unfolded 5.2 % (the old layout; 7.5 % zoomed in about the system).
    // The bound is one touch target's worth: a 48 px button (44 + border) on the 375 × ~535 px plan is 1.2 %.
    expect(folded).toBeLessThan(0.02);
    expect(unfolded).toBeGreaterThan(folded * 3);
    // Folding again by the same button.
    await toggle.tap();
    await expect(x).toBeHidden();

    // Zoomed in about the system (wheel at its fold button) as far as the system level goes, where the rails are long enough for their length fields.
    const plan = page.getByTestId('plan');
    for (let i = 0; i < 8; i++) {
      const at = (await toggle.boundingBox())!;
      const before = Number(await plan.getAttribute('data-scale'));
      await page.mouse.move(at.x + at.width / 2, at.y + at.height / 2);
      await page.mouse.wheel(0, -80);
      await expect.poll(async () => Number(await plan.getAttribute('data-scale'))).toBeGreaterThan(before);
      if ((await plan.getAttribute('data-level')) !== 'system') {
        await page.mouse.wheel(0, 80);
        await expect(plan).toHaveAttribute('data-level', 'system');
        break;
      }
    }
    const zoomedFolded = await coveredFraction(page);
    await toggle.tap();
    await expect(page.locator('.plan-control.length-field').first()).toBeVisible();
    const zoomedUnfolded = await coveredFraction(page);
    console.log(`zoomed in (scale ${await plan.getAttribute('data-scale')} px/m): folded ${(zoomedFolded * 100).toFixed(1)} %, unfolded ${(zoomedUnfolded * 100).toFixed(1)} %`);
    expect(zoomedFolded).toBeLessThan(0.02);

    // A new selection starts folded: select round the room's systems and objects back to the system.
    for (let i = 0; (i < 12 && !(await toggle.isVisible())) || i === 0; i++) await page.getByTestId('tool-select').tap();
    await expect(toggle).toHaveAttribute('aria-expanded', 'false');
  });
});
