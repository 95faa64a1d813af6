import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vitest/config';

// The cross-engine suite (docs/browsers.md): its own config so the unit run (vite.config.ts,
// tests/**) never picks it up. One file, one fork; the engines run one after another.
export default defineConfig({
  root: fileURLToPath(new URL('..', import.meta.url)),
  test: {
    include: ['e2e-engines/**/*.engines.ts'],
    environment: 'node',
    pool: 'forks',
    fileParallelism: false,
    testTimeout: 240_000,
    hookTimeout: 90_000,
  },
});
