import { expect, test, type Page } from '@playwright/test';
import { sceneFile, zoomToModuleLevel } from './helpers';

// Languages (issue #13, docs/i18n.md): the browser's language, `?lang=`, the visible switch, and
// the embedding option `locale`. The default Playwright browser language is en-US.
test.use({ reducedMotion: 'reduce', viewport: { width: 1440, height: 900 } });

/** Intl's no-break spaces (U+00A0, U+202F) as plain spaces. */
const plain = (s: string | null) => (s ?? '').replace(/[\u00a0\u202f]/g, ' ').trim();

/**
 * Records, from the first byte on, whether an English text of the room setup or the plan was
 * ever in the document: a German page must never flash English while its texts load.
 */
async function watchForEnglish(page: Page): Promise<void> {
  await page.addInitScript(() => {
    const w = window as unknown as { __sawEnglish: string[] };
    w.__sawEnglish = [];
    new MutationObserver(() => {
      const text = document.body?.innerText ?? '';
      for (const english of ['Start planning', 'Your room', 'Bill of materials', 'Presets and price']) if (text.includes(english) && !w.__sawEnglish.includes(english)) w.__sawEnglish.push(english);
    }).observe(document, { subtree: true, childList: true, characterData: true });
  });
}

const sawEnglish = (page: Page) => page.evaluate(() => (window as unknown as { __sawEnglish: string[] }).__sawEnglish);

test('?lang=de gives German texts in the room setup and the plan, with no English first frame', async ({ page }) => {
  await watchForEnglish(page);
  await page.goto('/?lang=de');
  await expect(page.getByRole('heading', { name: 'Ihr Raum' })).toBeVisible();
  await expect(page.locator('.app')).toHaveAttribute('lang', 'de');
  // Finish names by id, reflectances with a decimal comma; room sizes shown the German way.
  await expect(page.getByTestId('setup-finish-floor')).toContainText('Grauer Teppich – reflektiert 20\u00a0%');
  await expect(page.getByLabel('Höhe (m)')).toHaveValue('2,8');
  // Validation messages in German, numbers with a decimal comma.
  const width = page.getByLabel('Breite (m)');
  await width.fill('45');
  await expect(page.getByText('Die Breite muss zwischen 1 und 30 m liegen.')).toBeVisible();
  await width.fill('6');
  await page.getByLabel('Tiefe (m)').fill('4,5');
  await page.getByRole('button', { name: 'Planung beginnen' }).click();
  await expect(page.getByTestId('plan')).toBeVisible();
  await expect(page.locator('.room-label')).toHaveText(/^Raum 6 × 4,5 × \d(,\d+)? m$/);
  await page.getByTestId('preset-single').click();
  const bom = page.getByTestId('bom');
  await expect(bom.getByRole('heading', { name: 'Stückliste' })).toBeVisible();
  // Catalog names come from the catalog's translations; prices follow the German locale.
  await expect(bom).toContainText('Tragschiene 1,50 m');
  await expect(bom).toContainText('Strahler, Enger Spot 12°, 3000 K');
  expect(plain(await page.getByTestId('header-total').textContent())).toMatch(/^\d{1,3}(\.\d{3})*,\d{2} €$/);
  await expect(page.getByTestId('tool-delete')).toContainText('Löschen');
  // A refusal from the model, translated by its code: five 43 W spots fill the preset's 240 W driver (issue 11).
  await zoomToModuleLevel(page);
  const plus = page.locator('[data-testid^="plus-"] button');
  for (let k = 0; k < 2; k++) {
    await expect(plus).not.toHaveAttribute('aria-disabled', 'true');
    await plus.click();
  }
  await expect(plus).toHaveAttribute('title', /: der 240-W-Treiber ist voll: 215 W belegt; wählen Sie in den Systemoptionen den 321,6-W-Treiber /);
  expect(await page.evaluate(() => window.luxbox!.getLanguage())).toEqual({ language: 'de', locale: 'de' });
  // The 3D view's texts come with its chunk: German too.
  await page.getByTestId('tool-3d').click();
  await expect(page.getByRole('group', { name: 'Kamera' })).toBeVisible();
  await expect(page.getByTestId('back-2d')).toHaveText('Zurück zum 2D-Plan');
  expect(await sawEnglish(page)).toEqual([]);
});

test('the language switch changes the language and keeps the configuration; the choice is remembered', async ({ page }) => {
  await page.goto('/?demo');
  await expect(page.getByTestId('plan')).toBeVisible();
  const before = await sceneFile(page);
  const bomTitle = page.getByTestId('bom').getByRole('heading', { level: 2 });
  await expect(bomTitle).toHaveText('Bill of materials');
  const select = page.getByTestId('language-switch');
  await expect(select).toHaveAccessibleName('Language');
  // Keyboard reachable: focus it and pick French with the keyboard's value change.
  await select.focus();
  await select.selectOption('fr');
  await expect(bomTitle).toHaveText('Nomenclature');
  await expect(select).toHaveAccessibleName('Langue');
  await expect(page.getByTestId('tool-undo')).toContainText('Annuler');
  expect(await sceneFile(page)).toEqual(before);
  expect(await page.evaluate(() => window.luxbox!.getLanguage().language)).toBe('fr');
  expect(await page.evaluate(() => localStorage.getItem('luxbox.language'))).toBe('fr');
  // Stored: the next visit opens in French (the demo scene again, so the plan is there to read).
  await page.goto('/?demo');
  await expect(page.getByTestId('bom').getByRole('heading', { level: 2 })).toHaveText('Nomenclature');
  expect((await sceneFile(page)).configuration).toEqual(before.configuration);
  // The API switches too, and says so.
  await page.evaluate(() => window.luxbox!.setLanguage('it'));
  await expect(page.getByTestId('bom').getByRole('heading', { level: 2 })).toHaveText('Distinta materiali');
});

test.describe('browser language', () => {
  test.use({ locale: 'it-CH' });
  test('an Italian-Swiss browser gets Italian texts and Swiss formatting', async ({ page }) => {
    await page.goto('/?demo');
    await expect(page.getByTestId('plan')).toBeVisible();
    expect(await page.evaluate(() => window.luxbox!.getLanguage())).toEqual({ language: 'it', locale: 'it-CH' });
    await expect(page.getByTestId('bom').getByRole('heading', { level: 2 })).toHaveText('Distinta materiali');
    // it-CH writes a decimal point (CLDR; four-digit amounts are not grouped there), the euro sign in front.
    expect(plain(await page.getByTestId('header-total').textContent())).toMatch(/^€ ?\d{1,3}(['’]?\d{3})*\.\d{2}$/);
  });
});

test("the shop page embeds with locale 'fr-CH': French texts, Swiss-French formatting, prices in the catalog's currency", async ({ page }) => {
  await page.goto('/embed.html?locale=fr-CH');
  await expect(page.getByTestId('plan')).toBeVisible();
  expect(await page.evaluate(() => window.shopDemo!.instance!.getLanguage())).toEqual({ language: 'fr', locale: 'fr-CH' });
  await expect(page.locator('.room-label')).toHaveText('Pièce 5,5 × 4,2 × 2,7 m');
  await expect(page.getByTestId('tool-delete')).toContainText('Supprimer');
  // The German storefront's catalog is priced in EUR: French-Swiss formatting, never another currency.
  expect(plain(await page.getByTestId('header-total').textContent())).toMatch(/€/);
  // The shop chooses the language: no switch inside the embedded configurator.
  await expect(page.getByTestId('language-switch')).toHaveCount(0);
});

test('a German shopper reads the core in German: a full driver, broken scene files, a malformed IES file', async ({ page }) => {
  // The narrow spot's photometric file is served broken (no TILT= line: not an IES file at all).
  await page.route('**/ies/bega_84693_narrow_spot.ies', (route) => route.fulfill({ status: 200, contentType: 'application/octet-stream', body: 'Lichtdaten folgen\n1 2 3\n' }));
  await page.goto('/?lang=de');
  await page.getByRole('button', { name: 'Planung beginnen' }).click();
  await page.getByTestId('preset-single').click();
  await expect(page.getByTestId('plan')).toBeVisible();
  // A refusal of the model: spots until the driver is full, the reason in German from its code.
  await zoomToModuleLevel(page);
  const plus = page.locator('[data-testid^="plus-"] button');
  for (let k = 0; k < 6 && (await plus.getAttribute('aria-disabled')) !== 'true'; k++) await plus.click();
  await expect(plus).toHaveAttribute('aria-disabled', 'true');
  const reason = (await plus.getAttribute('title')) ?? '';
  expect(reason).toMatch(/Treiber ist voll|Einspeisung/);
  expect(reason).not.toMatch(/driver|feed|would|choose/);

  // Broken scene files: the file name and where in it, in German; the configuration is untouched.
  const before = await sceneFile(page);
  const banner = page.getByTestId('banner');
  const file = JSON.parse(await page.evaluate(() => window.luxbox!.getConfig())) as { version: number; configuration: { systems: { suspension: number }[] } };
  await page.getByTestId('open-file').setInputFiles({ name: 'neuer.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify({ ...file, version: 99 })) });
  await expect(banner).toContainText(/„neuer\.json“ kann nicht geöffnet werden|„neuer\.json“ wurde mit einer neueren luxbox erstellt \(Version 99; diese liest bis Version \d+\)/);
  await expect(banner).not.toContainText('was made by');
  await banner.getByRole('button', { name: /schließen|Meldung/i }).click();
  const tooLow = { ...file, configuration: { ...file.configuration, systems: file.configuration.systems.map((s) => ({ ...s, suspension: 9.5 })) } };
  await page.getByTestId('open-file').setInputFiles({ name: 'abhängung.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(tooLow)) });
  await expect(banner).toContainText('„abhängung.json“: configuration.systems[0].suspension: die Abhängung muss zwischen');
  await expect(banner).toContainText('(war 9,5)');
  await expect(banner).not.toContainText('must be between');
  expect(await sceneFile(page)).toEqual(before);

  // The malformed IES file: the 3D view names the file and says what is wrong, in German.
  await page.getByTestId('tool-3d').click();
  const error = page.getByTestId('view3d-error');
  await expect(error).toContainText('Die photometrischen Daten konnten nicht geladen werden', { timeout: 60_000 });
  await expect(error).toContainText('bega_84693_narrow_spot.ies');
  await expect(error).toContainText('keine Zeile „TILT=“ gefunden: keine IES-Datei nach LM-63');
  await expect(error).not.toContainText('not an IES');
});
