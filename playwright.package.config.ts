import { defineConfig } from '@playwright/test';
import { chromiumArgs } from './playwright.config';

// The packed package's consumer pages (scripts/checkPackage.mjs builds them into LUXBOX_CONSUMER_DIR/dist).
const port = Number(process.env.LUXBOX_E2E_PORT ?? 4174);
const consumer = process.env.LUXBOX_CONSUMER_DIR;
if (!consumer) throw new Error('LUXBOX_CONSUMER_DIR is not set: run node scripts/checkPackage.mjs');

export default defineConfig({
  testDir: 'e2e-package',
  timeout: 180_000,
  expect: { timeout: 30_000 },
  workers: 1,
  retries: 0,
  reporter: [['list']],
  use: {
    baseURL: `http://localhost:${port}`,
    launchOptions: { executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium', args: chromiumArgs },
  },
  webServer: {
    // The consumer folder has no Vite config: `vite preview` serves its dist/ as is.
    command: `npx vite preview ${JSON.stringify(consumer)} --port ${port} --strictPort`,
    url: `http://localhost:${port}/element.html`,
    reuseExistingServer: false,
    timeout: 60_000,
  },
});
