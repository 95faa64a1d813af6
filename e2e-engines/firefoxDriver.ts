import puppeteer from 'puppeteer-core';
import type { DriverKey, EngineDriver } from './engineDriver';
import { VIEWPORT } from './engineDriver';

export const FIREFOX_PATH = process.env.FIREFOX_PATH ?? '/usr/bin/firefox-esr';

/**
 * Debian's Firefox ESR through puppeteer-core over WebDriver BiDi (Playwright cannot fetch its
 * own Firefox build here). Headed under xvfb-run, as a desktop user runs it: WebGL2 on Mesa's
 * llvmpipe through the X server.
 */
export async function launchFirefox(): Promise<EngineDriver> {
  const browser = await puppeteer.launch({
    browser: 'firefox',
    executablePath: FIREFOX_PATH,
    protocol: 'webDriverBiDi',
    headless: false,
    defaultViewport: VIEWPORT,
  });
  const page = await browser.newPage();
  await page.setViewport(VIEWPORT);
  return {
    engine: 'firefox',
    goto: async (url) => void (await page.goto(url)),
    evaluate: async <T>(expression: string) => JSON.parse((await page.evaluate(`JSON.stringify(${expression})`)) as string) as T,
    click: (selector) => page.click(selector),
    fill: async (selector, text) => {
      await page.click(selector);
      await page.keyboard.down('Control');
      await page.keyboard.press('a');
      await page.keyboard.up('Control');
      await page.keyboard.type(text);
    },
    press: async (selector: string, key: DriverKey, times = 1) => {
      await page.focus(selector);
      for (let i = 0; i < times; i++) await page.keyboard.press(key);
    },
    setInputFile: async (selector, path) => {
      const input = await page.$(selector);
      if (!input) throw new Error(`firefox: no element matches ${selector}`);
      await (input as import('puppeteer-core').ElementHandle<HTMLInputElement>).uploadFile(path);
    },
    screenshot: async (path) => void (await page.screenshot({ path: path as `${string}.png` })),
    close: () => browser.close(),
  };
}
