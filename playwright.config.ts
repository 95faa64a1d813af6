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
  fullyParallel: false,
  workers: 1,
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
