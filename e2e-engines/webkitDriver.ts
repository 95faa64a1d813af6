import { spawn, type ChildProcess } from 'node:child_process';
import { writeFile } from 'node:fs/promises';
import { createServer } from 'node:net';
import { Builder, By, Key, type WebDriver } from 'selenium-webdriver';
import type { DriverKey, EngineDriver } from './engineDriver';
import { VIEWPORT } from './engineDriver';

export const WEBKIT_DRIVER_PATH = process.env.WEBKIT_DRIVER_PATH ?? '/usr/bin/WebKitWebDriver';
/** libwebkit2gtk-4.1-0 installs MiniBrowser under the multiarch library folder. */
const MULTIARCH: Record<string, string> = { x64: 'x86_64-linux-gnu', arm64: 'aarch64-linux-gnu' };
export const MINIBROWSER_PATH = process.env.MINIBROWSER_PATH ?? `/usr/lib/${MULTIARCH[process.arch] ?? `${process.arch}-linux-gnu`}/webkit2gtk-4.1/MiniBrowser`;

/** A TCP port nobody listens on right now (the OS picks it). */
export function freePort(): Promise<number> {
  return new Promise((resolve, reject) => {
    const server = createServer();
    server.on('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const { port } = server.address() as { port: number };
      server.close(() => resolve(port));
    });
  });
}

async function waitForDriver(url: string, process: ChildProcess, timeoutMs: number): Promise<void> {
  const end = Date.now() + timeoutMs;
  for (;;) {
    if (process.exitCode !== null) throw new Error(`WebKitWebDriver exited with code ${process.exitCode} before it answered on ${url}`);
    try {
      const res = await fetch(`${url}/status`);
      if (res.ok) return;
    } catch {
      // not listening yet
    }
    if (Date.now() > end) throw new Error(`WebKitWebDriver did not answer on ${url} within ${timeoutMs} ms`);
    await new Promise((r) => setTimeout(r, 100));
  }
}

const KEYS: Record<DriverKey, string> = { Home: Key.HOME, End: Key.END, ArrowLeft: Key.ARROW_LEFT, ArrowRight: Key.ARROW_RIGHT };

/**
 * WebKitGTK (Safari's engine) through Debian's WebKitWebDriver on a free port and
 * selenium-webdriver; the browser is WebKitGTK's MiniBrowser in automation mode.
 */
export async function launchWebkit(): Promise<EngineDriver> {
  const port = await freePort();
  const server = spawn(WEBKIT_DRIVER_PATH, [`--port=${port}`], { stdio: 'ignore' });
  const url = `http://127.0.0.1:${port}`;
  let driver: WebDriver;
  try {
    await waitForDriver(url, server, 20_000);
    driver = await new Builder()
      .usingServer(url)
      .withCapabilities({ browserName: 'MiniBrowser', 'webkitgtk:browserOptions': { binary: MINIBROWSER_PATH, args: ['--automation'] } })
      .build();
    // setRect sizes the outer window, and MiniBrowser's own toolbar takes part of it: grow the
    // window by what is missing so the page gets the same viewport as the other engines.
    await driver.manage().window().setRect({ width: VIEWPORT.width, height: VIEWPORT.height });
    const inner = await driver.executeScript<[number, number]>('return [innerWidth, innerHeight]');
    await driver
      .manage()
      .window()
      .setRect({ width: 2 * VIEWPORT.width - inner[0], height: 2 * VIEWPORT.height - inner[1] });
  } catch (e) {
    server.kill();
    throw e;
  }
  const find = (selector: string) => driver.findElement(By.css(selector));
  return {
    engine: 'webkit',
    goto: (target) => driver.get(target),
    evaluate: async <T>(expression: string) => JSON.parse(await driver.executeScript<string>(`return JSON.stringify(${expression})`)) as T,
    click: async (selector) => (await find(selector)).click(),
    fill: async (selector, text) => {
      const el = await find(selector);
      await el.click();
      await el.sendKeys(Key.chord(Key.CONTROL, 'a'), text);
    },
    press: async (selector: string, key: DriverKey, times = 1) => {
      const el = await find(selector);
      for (let i = 0; i < times; i++) await el.sendKeys(KEYS[key]);
    },
    setInputFile: async (selector, path) => (await find(selector)).sendKeys(path),
    screenshot: async (path) => writeFile(path, Buffer.from(await driver.takeScreenshot(), 'base64')),
    close: async () => {
      try {
        await driver.quit();
      } finally {
        server.kill();
      }
    },
  };
}
