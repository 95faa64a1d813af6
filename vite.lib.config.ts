import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, resolve, basename } from 'node:path';
import { fileURLToPath } from 'node:url';
import { defineConfig, type Plugin } from 'vite';
import react from '@vitejs/plugin-react';
import { firstScreenChunk, reactOnPreact } from './vite.config';

/**
 * The npm package's builds (docs/package.md), one per UI runtime, chosen by LUXBOX_LIB
 * (scripts/buildPackage.mjs runs all three):
 * - `preact`: `luxbox` (mountLuxbox), `luxbox/element` and `luxbox/engine` as ES modules, the UI on
 *   preact/compat exactly as the app's browser build (vite.config.ts); dependencies stay imports
 *   for the shop's bundler except zustand and React Spring, whose `react` imports must become preact's.
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

/**
 * Images as files beside the chunks, not base64 in them. Vite's library mode inlines every asset
 * whatever its size, which put the furniture library's 34 kB sprite sheet
 * (src/ui/planner/furnitureThumbnails.png) into the first-screen chunk of `luxbox/react` and of the
 * standalone element as 46 kB of base64 (+35 kB gzip, docs/package.md "Budgets"). Here an image
 * import becomes `new URL(<file>, import.meta.url)`, which the shop's bundler (Vite, webpack 5,
 * Rollup, esbuild with its loader) copies and a page without one fetches from the folder.
 */
function imagesAsFiles(): Plugin {
  const PREFIX = '\0luxbox-image:';
  return {
    name: 'luxbox-images-as-files',
    enforce: 'pre',
    resolveId(source, importer) {
      if (!importer || !/\.(png|jpe?g|webp|svg)$/.test(source) || importer.startsWith(PREFIX)) return null;
      return PREFIX + resolve(dirname(importer), source);
    },
    load(id) {
      if (!id.startsWith(PREFIX)) return null;
      const path = id.slice(PREFIX.length);
      const ref = this.emitFile({ type: 'asset', name: basename(path), source: readFileSync(path) });
      return `export default import.meta.ROLLUP_FILE_URL_${ref};`;
    },
  };
}

/**
 * Writes the npm packages this build bundles (rather than leaves as imports) to
 * build/bundled-<mode>.json, for lib/THIRD-PARTY-NOTICES.md (scripts/thirdPartyNotices.mjs).
 */
function recordBundledPackages(mode: string): Plugin {
  return {
    name: 'luxbox-record-bundled-packages',
    generateBundle(_options, bundle) {
      const names = new Set<string>();
      for (const chunk of Object.values(bundle)) {
        if (chunk.type !== 'chunk') continue;
        for (const id of chunk.moduleIds) {
          const m = /[\\/]node_modules[\\/]((?:@[^\\/]+[\\/])?[^\\/]+)/.exec(id);
          if (m) names.add(m[1].replace('\\', '/'));
        }
      }
      mkdirSync(fromRoot('build'), { recursive: true });
      writeFileSync(fromRoot(`build/bundled-${mode}.json`), JSON.stringify([...names].sort()));
    },
  };
}

// The packages the library builds leave as imports (package.json dependencies), subpaths included
// (the schemas import `zod/mini`), so the shop's bundle holds one copy of each.
export const DEPENDENCIES = ['preact', 'three', 'three-mesh-bvh', 'zod', 'fflate', '@use-gesture/vanilla'];
const asImports = (names: string[]) => new RegExp(`^(${names.join('|')})(/|$)`);

export default defineConfig(() => {
  const mode = process.env.LUXBOX_LIB ?? 'preact';
  if (!['preact', 'react', 'script'].includes(mode)) throw new Error(`LUXBOX_LIB=${mode}: expected preact, react or script`);
  const onPreact = mode !== 'react';
  // The first screen of the script and of the React door in one chunk, as the app's pages (vite.config.ts): each file is
  // gzipped alone, so 40 chunks cost more than one, and a shop's bundler keeps a file's modules together.
  const firstScreen = firstScreenChunk();
  const entry: Record<string, string> =
    mode === 'preact'
      ? { luxbox: fromRoot('src/hosts/package/index.ts'), element: fromRoot('src/hosts/package/element.ts'), engine: fromRoot('src/hosts/package/engine.ts') }
      : mode === 'react'
        ? { react: fromRoot('src/hosts/package/react.tsx') }
        : { 'luxbox-element': fromRoot('src/hosts/package/elementScript.ts') };
  const external = mode === 'script' ? [] : [asImports(mode === 'react' ? [...DEPENDENCIES, 'react', 'react-dom'] : DEPENDENCIES)];
  return {
    plugins: [react(), injectCss(), imagesAsFiles(), recordBundledPackages(mode), ...(mode !== 'preact' ? [firstScreen] : [])],
    resolve: { alias: onPreact ? reactOnPreact('build') : [] },
    // Public files (the demo's photometry) are copied by scripts/buildPackage.mjs where each door expects them.
    publicDir: false as const,
    // Relative asset URLs (`new URL('../assets/…', import.meta.url)`), so the files are found beside the chunks wherever the folder is served from.
    base: './',
    logLevel: 'warn' as const,
    build: {
      outDir: fromRoot(mode === 'script' ? 'lib/standalone' : 'lib'),
      emptyOutDir: false,
      // Source maps for the ES modules a shop's bundler reads; the script is served as it is.
      sourcemap: mode !== 'script',
      minify: mode === 'script',
      target: 'es2022',
      lib: { entry, formats: ['es' as const] },
      rolldownOptions: {
        external,
        output: {
          entryFileNames: '[name].js',
          chunkFileNames: `chunks/${mode === 'react' ? 'react-' : ''}[name]-[hash].js`,
          assetFileNames: 'assets/[name]-[hash][extname]',
          ...(mode !== 'preact' ? { codeSplitting: { groups: [{ name: 'first-screen', test: firstScreen.inFirstScreen }] } } : {}),
        },
      },
    },
  };
});
