import AxeBuilder from '@axe-core/playwright';
import { expect, test, type Page } from '@playwright/test';
import { sceneFile } from './helpers';

// Springs skipped (prefers-reduced-motion) so each zoom lands at once; a fixed bake quality for the 3D view.
test.use({ reducedMotion: 'reduce', viewport: { width: 1280, height: 800 } });

/** axe-core's findings of every impact, minor to critical (WCAG 2.0–2.2 A/AA and best practices), as readable lines. */
async function violations(page: Page, include?: string): Promise<string[]> {
  const builder = new AxeBuilder({ page });
  if (include) builder.include(include);
  const result = await builder.analyze();
  return result.violations.flatMap((v) => v.nodes.map((n) => `${v.impact} ${v.id} (${v.help}): ${n.target.join(' ')}`));
}

/** The page-level landmarks among them (the side panel's named sections are regions inside them). */
const pageLandmarks = (found: string[]) => found.filter((l) => /^(banner|main|complementary)\b/.test(l));

/** The page's landmarks as role and name, in document order (what a screen reader's landmark list shows). */
async function landmarks(page: Page): Promise<string[]> {
  const tree = await page.locator('body').ariaSnapshot();
  return tree
    .split('\n')
    .map((line) => /^\s*- (banner|main|complementary|region|navigation|contentinfo)(?: "([^"]*)")?/.exec(line))
    .filter((m): m is RegExpExecArray => m !== null)
    .map((m) => (m[2] ? `${m[1]} ${m[2]}` : m[1]));
}

/**
 * Presses Tab (Shift+Tab when `backwards`) until the focused element matches `selector`, at most
 * `max` presses, checking that every stop on the way shows its focus.
 */
async function tabTo(page: Page, selector: string, { backwards = false, max = 120 } = {}): Promise<void> {
  for (let i = 0; i < max; i++) {
    await page.keyboard.press(backwards ? 'Shift+Tab' : 'Tab');
    const stop = await page.evaluate((sel) => {
      const el = document.activeElement as HTMLElement | null;
      if (!el || el === document.body) return { matches: false, visible: true, name: 'body' };
      const cs = getComputedStyle(el);
      // A focus ring: an outline that is drawn, or (for the visually hidden file input) one on its label.
      const ring = (s: CSSStyleDeclaration) => s.outlineStyle !== 'none' && parseFloat(s.outlineWidth) > 0;
      const visible = ring(cs) || (el.parentElement !== null && ring(getComputedStyle(el.parentElement)));
      return { matches: el.matches(sel), visible, name: `${el.tagName.toLowerCase()} ${el.getAttribute('data-testid') ?? el.getAttribute('aria-label') ?? el.textContent?.trim().slice(0, 30)}` };
    }, selector);
    expect(stop.visible, `no visible focus on ${stop.name}`).toBe(true);
    if (stop.matches) return;
  }
  throw new Error(`${selector} not reached within ${max} Tab presses`);
}

const announcer = (page: Page) => page.getByTestId('plan-announcer');
/** The beam of the first module of the first rail (e2e/helpers' sceneFile type leaves beams out). */
const firstBeam = (page: Page): Promise<string> => page.evaluate(() => JSON.parse(window.luxbox!.getConfig()).configuration.systems[0].rails[0].modules[0].beam);

test('axe: room setup, plan with a selection, side panel, 3D view controls — no violations of any impact', async ({ page }) => {
  await page.goto('/?quality=fast');
  expect(await violations(page)).toEqual([]);
  // The standalone app is the whole page: its header is the banner, the room setup the one main.
  expect(pageLandmarks(await landmarks(page))).toEqual(['banner', 'main']);

  await page.locator('form.setup-card button[type="submit"]').click();
  // The empty plan's first-run card (issue 27).
  await expect(page.getByTestId('first-run-corner-l')).toBeVisible();
  expect(await violations(page)).toEqual([]);
  await page.getByTestId('preset-corner-l').click();
  const module = (await sceneFile(page)).configuration.systems[0].rails[0].modules[0];
  await page.evaluate((id) => window.luxbox!.runAction('setModuleDimming', { moduleId: id, dimming: 0.5 }), module.id);
  // Select a module the way a user does: its button on the plan at module level.
  for (let i = 0; i < 8 && (await page.getByTestId('plan').getAttribute('data-level')) !== 'module'; i++) {
    const before = await page.getByTestId('plan').getAttribute('data-scale');
    await page.getByTestId('zoom-in').click();
    await expect(page.getByTestId('plan')).not.toHaveAttribute('data-scale', before ?? '');
  }
  // A refused + explains itself in a tip at the control, with its remedy (issue 27).
  await page.locator('[data-testid^="plus-"] button').first().click({ force: true });
  await expect(page.getByTestId('disabled-tip').getByTestId('remedy')).toBeVisible();
  expect(await violations(page)).toEqual([]);
  await page.keyboard.press('Escape');
  await page.getByTestId(`module-${module.id}`).getByRole('button').click();
  await expect(page.getByTestId('options-panel')).toBeVisible();
  expect(await violations(page)).toEqual([]);
  // The plan (with the bottom bar) is the main, the side panel an aside beside it.
  expect(pageLandmarks(await landmarks(page))).toEqual(['banner', 'main', 'complementary Presets and price']);

  await page.getByTestId('tool-3d').click();
  await expect(page.getByTestId('view3d-canvas')).toBeVisible();
  await page.locator('details.viewer3d-modules > summary').click();
  expect(await violations(page, '[data-testid="view3d"]')).toEqual([]);
  await page.getByTestId('mode-lux').click();
  expect(await violations(page, '[data-testid="view3d"]')).toEqual([]);

  // Phone: the side panel is a drawer behind the header's button.
  await page.getByTestId('tool-3d').click();
  await expect(page.getByTestId('plan')).toBeVisible();
  await page.setViewportSize({ width: 375, height: 667 });
  if (!(await page.locator('.side-panel.open').isVisible())) await page.locator('.panel-toggle').click();
  await expect(page.locator('.side-panel.open')).toBeVisible();
  expect(await violations(page)).toEqual([]);
});

test('axe: the configurator embedded in the shop page — no violations, and the shop keeps its own banner and main', async ({ page }) => {
  await page.goto('/embed.html');
  await expect(page.getByTestId('configurator-host').locator('.app')).toBeVisible();
  expect(await violations(page)).toEqual([]);
  const found = await landmarks(page);
  // One banner and one main, the shop's: luxbox is one named region inside them and adds neither.
  expect(found.filter((l) => l === 'banner')).toHaveLength(1);
  expect(found.filter((l) => l === 'main')).toHaveLength(1);
  // The shop page speaks German (its locale option): the region is named in the UI language.
  expect(found).toContain('region luxbox Lichtkonfigurator');
});

test('keyboard only: Tab to a preset, place it, select a module, change its beam, 3D and back; each step announced', async ({ page }) => {
  await page.goto('/?quality=fast');
  await tabTo(page, 'form.setup-card button[type="submit"]');
  await page.keyboard.press('Enter');
  await expect(page.getByTestId('plan')).toBeVisible();

  await tabTo(page, '[data-testid="preset-corner-l"]');
  await page.keyboard.press('Enter');
  await expect.poll(async () => (await sceneFile(page)).configuration.systems.length).toBe(1);
  const system = (await sceneFile(page)).configuration.systems[0];
  const modules = system.rails.reduce((n, r) => n + r.modules.length, 0);
  await expect(announcer(page)).toHaveText(`System 1, 2 rails, ${modules} modules selected`);

  // Zoom in with the plan's button until the modules have buttons of their own.
  await tabTo(page, '[data-testid="zoom-in"]');
  const plan = page.getByTestId('plan');
  for (let i = 0; i < 8 && (await plan.getAttribute('data-level')) !== 'module'; i++) {
    const before = await plan.getAttribute('data-scale');
    await page.keyboard.press('Enter');
    await expect(plan).not.toHaveAttribute('data-scale', before ?? '');
  }
  await expect(plan).toHaveAttribute('data-level', 'module');

  const first = system.rails[0].modules[0];
  await tabTo(page, `[data-testid="module-${first.id}"] button`);
  await page.keyboard.press('Enter');
  await expect(page.getByTestId('options-panel')).toBeVisible();
  await expect(announcer(page)).toHaveText(new RegExp(`^Module 1 of ${system.rails[0].modules.length} on rail 1, .* selected$`));

  // Another beam of the same module: the first beam button that is enabled and not current.
  const beam = await page.evaluate(() => {
    const b = Array.from(document.querySelectorAll<HTMLElement>('[data-testid^="beam-"]')).find((e) => e.getAttribute('aria-pressed') !== 'true' && e.getAttribute('aria-disabled') !== 'true');
    return b?.dataset.testid ?? null;
  });
  expect(beam, 'the selected module offers another beam').not.toBeNull();
  await tabTo(page, `[data-testid="${beam}"]`);
  await page.keyboard.press('Enter');
  await expect.poll(() => firstBeam(page)).toBe(beam!.slice('beam-'.length));
  await expect(announcer(page)).toHaveText(/^Changed: Module 1 of \d+ on rail 1, /);

  // The bottom bar comes before the side panel in the tab order: back from the options.
  await tabTo(page, '[data-testid="tool-3d"]', { backwards: true });
  await page.keyboard.press('Enter');
  await expect(page.getByTestId('view3d-canvas')).toBeVisible();
  // The 3D panel's controls (camera, mode, quality, exposure with Re-adapt, colour adaptation, modules, …) come first.
  await tabTo(page, '[data-testid="back-2d"]', { max: 160 });
  await page.keyboard.press('Enter');
  await expect(plan).toBeVisible();
  expect(await firstBeam(page)).toBe(beam!.slice('beam-'.length));
});

/** Interactive elements rendered at less than 44 × 44 px (a check box or radio counts by its label, which is what a finger hits). */
async function smallTargets(page: Page): Promise<string[]> {
  return page.evaluate(() => {
    const out: string[] = [];
    for (const el of document.querySelectorAll<HTMLElement>('button, a[href], input, select, summary, [role="button"]')) {
      if (el.closest('.sr-only') || el.classList.contains('file-input')) continue; // visually hidden; the visible label is the target
      const target = el instanceof HTMLInputElement && (el.type === 'checkbox' || el.type === 'radio') ? (el.closest('label') ?? el) : el;
      const r = target.getBoundingClientRect();
      if (r.width === 0 || r.height === 0 || getComputedStyle(target).visibility === 'hidden') continue;
      if (r.width < 44 - 0.5 || r.height < 44 - 0.5)
        out.push(`${el.tagName.toLowerCase()} ${el.getAttribute('data-testid') ?? el.getAttribute('aria-label') ?? el.textContent?.trim().slice(0, 30)}: ${Math.round(r.width)} × ${Math.round(r.height)}`);
    }
    return out;
  });
}

test('touch targets at phone size: every visible control is at least 44 × 44 px', async ({ page }) => {
  await page.setViewportSize({ width: 375, height: 667 });
  // With the expert tools on, so live control's rows are measured too.
  await page.goto('/?quality=fast&expert=1');
  expect(await smallTargets(page)).toEqual([]);
  await page.locator('form.setup-card button[type="submit"]').click();
  await page.locator('.panel-toggle').click();
  await page.getByTestId('preset-corner-l').click();
  expect(await smallTargets(page)).toEqual([]);
  await page.getByTestId('tool-options').click();
  await expect(page.getByTestId('options-panel')).toBeVisible();
  expect(await smallTargets(page)).toEqual([]);
  await page.locator('.panel-toggle').click();
  await page.getByTestId('tool-3d').click();
  await expect(page.getByTestId('view3d-canvas')).toBeVisible();
  await page.locator('details.viewer3d-modules > summary').click();
  await page.getByTestId('live-on').check();
  expect(await smallTargets(page)).toEqual([]);
});
