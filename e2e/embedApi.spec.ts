import { expect, test } from '@playwright/test';

test('window.luxbox: list and run actions, set/get config, subscribe, bill of materials', async ({ page }) => {
  await page.goto('/');
  const result = await page.evaluate(() => {
    const lx = window.luxbox!;
    const changes: string[] = [];
    const off = lx.subscribe((json) => changes.push(json));
    const listed = lx.listActions({ placePreset: { presetId: 'single' }, deleteSystem: { systemId: 'nope' } });
    const place = lx.runAction('placePreset', { presetId: 'single' });
    // Both are type errors (LuxboxInstance.runAction is typed); plain JavaScript can still make them.
    // @ts-expect-error: no action of that name
    const unknown = lx.runAction('launchRocket', {});
    // @ts-expect-error: x is a number
    const badParams = lx.runAction('moveSystem', { systemId: 's1', x: 'left' });
    const config = JSON.parse(lx.getConfig());
    const bom = lx.getBillOfMaterials();
    off();
    lx.runAction('deleteSystem', { systemId: config.configuration.systems[0].id });
    let setError = '';
    try {
      lx.setConfig('{"format":"luxbox-configuration","version":99}');
    } catch (e) {
      setError = (e as Error).message;
    }
    lx.setConfig(JSON.stringify(config));
    return {
      placeListed: listed.find((a) => a.name === 'placePreset'),
      deleteListed: listed.find((a) => a.name === 'deleteSystem'),
      place,
      unknown,
      badParams,
      changes: changes.length,
      systems: config.configuration.systems.length,
      bomTotal: bom.total,
      bomCurrency: bom.currency,
      bomLines: bom.lines.length,
      setError,
      restored: JSON.parse(lx.getConfig()).configuration.systems.length,
      scene: lx.getLightingScene() as { version: number; luminaires: unknown[] },
    };
  });
  expect(result.placeListed).toMatchObject({ enabled: true, reason: null });
  expect(result.deleteListed?.enabled).toBe(false);
  expect(result.deleteListed?.reason).toContain("no system with id 'nope'");
  expect(result.place).toEqual({ ok: true });
  expect(result.unknown.ok).toBe(false);
  expect(result.badParams.ok).toBe(false);
  // zod's English sentence, as in Node: the browser parses through safeParseInEnglish too (zod/mini alone says "Invalid input").
  expect(result.badParams).toMatchObject({ reason: expect.stringContaining('x: Invalid input: expected number, received string') });
  expect(result.changes).toBe(1);
  expect(result.systems).toBe(1);
  expect(result.bomCurrency).toBe('EUR');
  expect(result.bomTotal).toBeGreaterThan(0);
  expect(result.bomLines).toBeGreaterThan(3);
  expect(result.setError).toContain('newer luxbox');
  expect(result.restored).toBe(1);
  expect(result.scene.version).toBe(1);
  expect(result.scene.luminaires).toHaveLength(3);
  // Running an action from the host page left the setup screen for the plan.
  await expect(page.getByTestId('plan')).toBeVisible();
});
