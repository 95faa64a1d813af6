/// <reference types="vitest/config" />
import { defineConfig } from 'vite';
import react from '@vitejs/plugin-react';

// One config for the app build and for Vitest (unit + headless-gl tests).
export default defineConfig({
  plugins: [react()],
  server: { port: 5173, strictPort: false, host: true },
  preview: { port: 4173, strictPort: true },
  build: {
    outDir: 'dist',
    sourcemap: true,
    // dist/.vite/manifest.json: lets the bundle benchmark follow each chunk's static imports.
    manifest: true,
    chunkSizeWarningLimit: 1200,
    // Two pages: the app at / and the shop-page embedding example at /embed.html (docs/embedding.md).
    rolldownOptions: { input: { main: 'index.html', embed: 'embed.html' } },
  },
  test: {
    include: ['tests/**/*.test.ts', 'tests/**/*.test.tsx'],
    environment: 'node',
    // headless-gl contexts are per process; forks keep native state isolated.
    pool: 'forks',
    testTimeout: 120_000,
    hookTimeout: 120_000,
  },
});
