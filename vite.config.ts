/// <reference types="vitest/config" />
import { defineConfig, type Plugin } from 'vite';
import react from '@vitejs/plugin-react';

/**
 * One chunk for the first screen (docs/benchmarks.md, "First screen"). Left to itself Rolldown
 * splits the modules both pages load at start into about ten chunks, by which lazy chunks (3D
 * view, options panel, language packs) also import them; each is gzipped alone and carries an
 * export map, so the first screen cost 3 KiB more than the same code in one file. After the module
 * graph is complete (buildEnd) this plugin works out the modules every page entry imports
 * statically (directly or through others); `inFirstScreen` puts exactly those into one `app`
 * chunk. Lazy-only modules stay in their lazy chunks, and a module only one page uses stays with
 * that page's entry.
 */
export function firstScreenChunk(): Plugin & { inFirstScreen: (id: string) => boolean } {
  let shared: Set<string> | null = null;
  return {
    name: 'luxbox-first-screen-chunk',
    apply: 'build',
    buildEnd() {
      const closureOf = (entry: string) => {
        const seen = new Set<string>();
        const stack = [entry];
        while (stack.length > 0) {
          const id = stack.pop()!;
          if (seen.has(id)) continue;
          seen.add(id);
          stack.push(...(this.getModuleInfo(id)?.importedIds ?? []));
        }
        return seen;
      };
      const entries = [...this.getModuleIds()].filter((id) => this.getModuleInfo(id)?.isEntry);
      const closures = entries.map(closureOf);
      shared = new Set([...(closures[0] ?? [])].filter((id) => !entries.includes(id) && closures.every((c) => c.has(id))));
    },
    inFirstScreen: (id) => shared?.has(id) === true,
  };
}

/**
 * React → preact/compat in the browser build only (−55 KiB gzip of the first screen: react-dom's
 * client is 62 KiB, preact with compat and hooks about 7). The code uses createRoot, hooks
 * (useSyncExternalStore, useId, also through zustand), memo, lazy/Suspense and StrictMode, all
 * in preact/compat (the plan's gestures are its own pointer listeners, usePlanGestures.ts).
 * Vitest and the dev server keep real React, so the unit tests run the components on React and
 * the Playwright suite runs them on preact
 * (docs/architecture.md, "React in tests, preact in the browser build").
 */
export const reactOnPreact = (command: string) =>
  command === 'build'
    ? [
        { find: /^react-dom\/client$/, replacement: 'preact/compat/client' },
        { find: /^react\/jsx-runtime$/, replacement: 'preact/compat/jsx-runtime' },
        { find: /^react\/jsx-dev-runtime$/, replacement: 'preact/compat/jsx-dev-runtime' },
        { find: /^react\/compiler-runtime$/, replacement: 'preact/compat/compiler-runtime' },
        { find: /^react-dom$/, replacement: 'preact/compat' },
        { find: /^react$/, replacement: 'preact/compat' },
      ]
    : [];

/** Component interaction tests (tests/components, docs/architecture.md "Component tests on both runtimes"). */
const COMPONENT_TESTS = 'tests/components/**/*.test.tsx';

/**
 * The component tests run twice, in happy-dom: on React (what `luxbox/react` ships) and on
 * preact/compat with the browser build's aliases (what the standalone pages and the element
 * ship). The test files import `@testing-library/react`; on preact that name is
 * `@testing-library/preact`, whose render, screen, fireEvent, act and cleanup are the same calls.
 */
const componentProjects = [
  { name: 'components-react', runtime: 'react', alias: [] },
  { name: 'components-preact', runtime: 'preact', alias: [{ find: /^@testing-library\/react$/, replacement: '@testing-library/preact' }, ...reactOnPreact('build')] },
].map(({ name, runtime, alias }) => ({
  extends: true as const,
  resolve: { alias },
  test: {
    name,
    include: [COMPONENT_TESTS],
    environment: 'happy-dom',
    setupFiles: ['tests/setup/touchScreen.ts'],
    env: { LUXBOX_UI_RUNTIME: runtime },
    // Packages that import React (zustand's hooks, React Spring) go through the aliases too, as in the build.
    server: { deps: { inline: runtime === 'preact' ? ['zustand', /@react-spring/] : [] } },
  },
}));

// One config for the app build and for Vitest (unit + headless-gl tests, component tests on both runtimes).
export default defineConfig(({ command }) => {
  const firstScreen = firstScreenChunk();
  return {
    plugins: [react(), firstScreen],
    resolve: { alias: reactOnPreact(command) },
    server: { port: 5173, strictPort: false, host: true },
    preview: { port: 4173, strictPort: true },
    build: {
      outDir: 'dist',
      sourcemap: true,
      // dist/.vite/manifest.json: lets the bundle benchmark follow each chunk's static imports.
      manifest: true,
      chunkSizeWarningLimit: 1200,
      modulePreload: { polyfill: false },
      // Two pages: the app at / and the shop-page embedding example at /embed.html (docs/embedding.md).
      rolldownOptions: {
        input: { main: 'index.html', embed: 'embed.html' },
        output: { codeSplitting: { groups: [{ name: 'app', test: firstScreen.inFirstScreen }] } },
      },
    },
    test: {
      setupFiles: ['tests/setup/colourFilterSpectra.ts', 'tests/setup/roomShapeSupport.ts'],
      environment: 'node',
      // headless-gl contexts are per process; forks keep native state isolated.
      pool: 'forks',
      testTimeout: 120_000,
      hookTimeout: 120_000,
      projects: [{ extends: true, test: { name: 'unit', include: ['tests/**/*.test.ts', 'tests/**/*.test.tsx'], exclude: [COMPONENT_TESTS] } }, ...componentProjects],
    },
  };
});
