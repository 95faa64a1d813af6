import { defineConfig } from '@playwright/test';

// Debian's chromium (no browser download possible here). SwiftShader gives WebGL2
// with EXT_color_buffer_float in headless mode (docs/architecture.md, "Test machines").
export const chromiumArgs = ['--no-sandbox', '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'];

// LUXBOX_E2E_PORT lets two copies of the tree run their suites side by side.
const port = Number(process.env.LUXBOX_E2E_PORT ?? 4173);

export default defineConfig({
  testDir: 'e2e',
  // Golden images live in the repo, one per test and size, independent of the OS suffix.
  snapshotPathTemplate: '{testDir}/__screenshots__/{testFilePath}/{arg}{ext}',
  timeout: 120_000,
  expect: { timeout: 30_000 },
  // Two workers, test by test (each test has its own browser context, its own files and free
  // ports): SwiftShader rasterises on one thread per core but the page's JavaScript, the GPU
  // process's command thread and the test's Node side run between its draws, so a second browser
  // fills the cores one leaves idle (docs/benchmarks.md, "Test suite time"). `--workers=1` runs
  // them one after another as before.
  fullyParallel: true,
  workers: 2,
  retries: 0,
  reporter: [['list']],
  use: {
    baseURL: `http://localhost:${port}`,
    launchOptions: { executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium', args: chromiumArgs },
  },
  webServer: {
    command: `npx vite preview --port ${port} --strictPort`,
    url: `http://localhost:${port}`,
    reuseExistingServer: false,
    timeout: 60_000,
  },
});
