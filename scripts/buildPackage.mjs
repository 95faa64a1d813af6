// Builds what the npm package ships into lib/ (docs/package.md); `npm pack` runs it (prepack).
//   lib/{luxbox,element,engine}.js   ES modules, UI on preact      (vite.lib.config.ts, LUXBOX_LIB=preact)
//   lib/react.js                     ES module, UI on the shop's React (LUXBOX_LIB=react)
//   lib/standalone/luxbox-element.js the element for pages without a bundler, with its lazy chunks
//                                    and the demo catalog's photometry (ies/) beside it (LUXBOX_LIB=script)
//   lib/*.d.ts                       one declaration file per door (scripts/packageApi.mjs), whose
//                                    API is checked against docs/api/*.api.md (--update-api accepts a change)
//   lib/cli/luxbox.mjs               the CLI in one file (esbuild; headless-gl stays a dependency)
import { execFileSync } from 'node:child_process';
import { cpSync, mkdirSync, readFileSync, rmSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { extractApi } from './packageApi.mjs';
import { copyCatalogPhotometry, packagesInMetafile, writeThirdPartyNotices } from './thirdPartyNotices.mjs';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const bin = (name) => join(root, 'node_modules/.bin', name);
const run = (cmd, args, env = {}) => execFileSync(cmd, args, { cwd: root, stdio: 'inherit', env: { ...process.env, ...env } });

rmSync(join(root, 'lib'), { recursive: true, force: true });
rmSync(join(root, 'build/types'), { recursive: true, force: true });
// VITE_CONFIG_NATIVE_IGNORE_WARNING: vite.lib.config.ts imports vite.config.ts's aliases without a file
// extension (tsc refuses `.ts` there), which Vite's future native config loader will not read; the
// bundling loader used today does.
for (const mode of ['preact', 'react', 'script']) run(bin('vite'), ['build', '--config', 'vite.lib.config.ts'], { LUXBOX_LIB: mode, VITE_CONFIG_NATIVE_IGNORE_WARNING: 'true' });
// Only the photometry the bundled demo catalog names (all of it MIT or the makers' own data, public/ies/SOURCES.md).
mkdirSync(join(root, 'lib/standalone/ies'), { recursive: true });
copyCatalogPhotometry(root, join(root, 'src/core/catalog/default-catalog.json'), join(root, 'public/ies/SOURCES.md'), join(root, 'lib/standalone/ies'), (from, to) => cpSync(from, to));

run(bin('tsc'), ['-p', 'tsconfig.lib.json']);
const failures = extractApi({ update: process.argv.includes('--update-api') });

run(bin('esbuild'), [
  'src/hosts/cli/bundleEntry.ts',
  '--bundle',
  '--platform=node',
  '--format=esm',
  '--target=node20',
  '--external:gl',
  '--outfile=lib/cli/luxbox.mjs',
  '--metafile=build/cli-meta.json',
  // Bundled CommonJS dependencies call require(): give the ES module one (as scripts/packGpuBench.mjs).
  "--banner:js=import { createRequire as __luxboxRequire } from 'node:module'; const require = __luxboxRequire(import.meta.url);",
  '--log-level=warning',
]);

const bundled = (mode) => JSON.parse(readFileSync(join(root, `build/bundled-${mode}.json`), 'utf8'));
writeThirdPartyNotices(
  root,
  { 'lib/*.js (preact)': bundled('preact'), 'lib/react.js': bundled('react'), 'lib/standalone': bundled('script'), 'lib/cli': [...packagesInMetafile(join(root, 'build/cli-meta.json'))] },
  join(root, 'lib/THIRD-PARTY-NOTICES.md'),
);

if (failures.length > 0) {
  for (const f of failures) console.error(`API report: ${f}`);
  process.exit(1);
}
