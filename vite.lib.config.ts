import { dirname, resolve, basename } from 'node:path';
import { fileURLToPath } from 'node:url';
import { defineConfig, type Plugin } from 'vite';
import react from '@vitejs/plugin-react';
import { reactOnPreact, zodOnMini, zodWithoutJsonSchema } from './vite.config.ts';

/**
 * The npm package's builds (docs/package.md), one per UI runtime, chosen by LUXBOX_LIB
 * (scripts/buildPackage.mjs runs all three):
 * - `preact`: `luxbox` (mountLuxbox), `luxbox/element` and `luxbox/engine` as ES modules, the UI on
 *   preact/compat exactly as the app's browser build (vite.config.ts); dependencies stay imports
 *   for the shop's bundler except zustand, whose `react` import must become preact's.
 * - `react`: `luxbox/react`, the same UI on the shop's React (react and react-dom are peer
 *   dependencies and stay imports).
 * - `script`: lib/standalone/luxbox-element.js, `<luxbox-configurator>` for a page without a
 *   bundler: everything bundled and minified, preact included; the 3D view and language packs
 *   stay lazy chunks beside it.
 */
const root = dirname(fileURLToPath(import.meta.url));
const fromRoot = (path: string) => resolve(root, path);

/** Each CSS import becomes a call of injectStyle with the minified CSS text (src/hosts/package/injectStyle.ts). */
function injectCss(): Plugin {
  // The virtual id must not end in .css, or Vite's own CSS plugin takes it for a stylesheet.
  const PREFIX = '\0luxbox-css:';
  const SUFFIX = '.inject.js';
  return {
    name: 'luxbox-inject-css',
    enforce: 'pre',
    resolveId(source, importer) {
      if (!importer || !source.endsWith('.css') || importer.startsWith(PREFIX)) return null;
      return PREFIX + resolve(dirname(importer), source) + SUFFIX;
    },
    load(id) {
      if (!id.startsWith(PREFIX)) return null;
      const path = id.slice(PREFIX.length, -SUFFIX.length);
      return [`import css from ${JSON.stringify(`${path}?inline`)};`, `import { injectStyle } from ${JSON.stringify(fromRoot('src/hosts/package/injectStyle.ts'))};`, `injectStyle(${JSON.stringify(basename(path, '.css'))}, css);`].join(
        '\n',
      );
    },
  };
}

// `zod` itself is not among them: it is aliased to src/core/zodClassicOnMini.ts (bundled) as in the
// app's build, which imports `zod/mini` from the package.
const DEPENDENCIES = ['preact', 'three', 'three-mesh-bvh', 'zod/mini', 'fflate', 'fast-xml-parser'];
const asImports = (names: string[]) => new RegExp(`^(${names.join('|')})(/|$)`);

export default defineConfig(() => {
  const mode = process.env.LUXBOX_LIB ?? 'preact';
  if (!['preact', 'react', 'script'].includes(mode)) throw new Error(`LUXBOX_LIB=${mode}: expected preact, react or script`);
  const onPreact = mode !== 'react';
  const entry =
    mode === 'preact'
      ? { luxbox: fromRoot('src/hosts/package/index.ts'), element: fromRoot('src/hosts/package/element.ts'), engine: fromRoot('src/hosts/package/engine.ts') }
      : mode === 'react'
        ? { react: fromRoot('src/hosts/package/react.tsx') }
        : { 'luxbox-element': fromRoot('src/hosts/package/elementScript.ts') };
  const external = mode === 'script' ? [] : [asImports(mode === 'react' ? [...DEPENDENCIES, 'react', 'react-dom'] : DEPENDENCIES)];
  return {
    configFile: false,
    plugins: [react(), injectCss(), ...(mode === 'script' ? [zodWithoutJsonSchema()] : [])],
    resolve: { alias: [...zodOnMini('build'), ...(onPreact ? reactOnPreact('build') : [])] },
    // Public files (the demo's photometry) are copied by scripts/buildPackage.mjs where each door expects them.
    publicDir: false,
    logLevel: 'warn',
    build: {
      outDir: fromRoot(mode === 'script' ? 'lib/standalone' : 'lib'),
      emptyOutDir: false,
      // Source maps for the ES modules a shop's bundler reads; the script is served as it is.
      sourcemap: mode !== 'script',
      minify: mode === 'script',
      target: 'es2022',
      lib: { entry, formats: ['es'] },
      rolldownOptions: {
        external,
        output: { entryFileNames: '[name].js', chunkFileNames: `chunks/${mode === 'react' ? 'react-' : ''}[name]-[hash].js` },
      },
    },
  };
});
