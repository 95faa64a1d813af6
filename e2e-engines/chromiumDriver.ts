import { chromium } from 'playwright-core';
import { chromiumArgs } from '../playwright.config';
import type { DriverKey, EngineDriver } from './engineDriver';
import { VIEWPORT } from './engineDriver';

/** Debian's chromium through Playwright, with the e2e suite's flags (SwiftShader WebGL2). */
export async function launchChromium(): Promise<EngineDriver> {
  const browser = await chromium.launch({ executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium', args: chromiumArgs });
  const context = await browser.newContext({ viewport: VIEWPORT });
  const page = await context.newPage();
  return {
    engine: 'chromium',
    goto: async (url) => void (await page.goto(url)),
    evaluate: async <T>(expression: string) => JSON.parse(await page.evaluate(`JSON.stringify(${expression})`)) as T,
    click: (selector) => page.locator(selector).first().click(),
    fill: async (selector, text) => {
      await page.locator(selector).first().click();
      await page.keyboard.press('Control+a');
      await page.keyboard.type(text);
    },
    press: async (selector: string, key: DriverKey, times = 1) => {
      await page.locator(selector).first().focus();
      for (let i = 0; i < times; i++) await page.keyboard.press(key);
    },
    setInputFile: (selector, path) => page.locator(selector).first().setInputFiles(path),
    screenshot: async (path) => void (await page.screenshot({ path })),
    close: () => browser.close(),
  };
}
