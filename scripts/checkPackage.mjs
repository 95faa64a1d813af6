// Tests what ships (docs/package.md, "Checking the package"): builds the package (failing on an
// unreviewed API change, scripts/packageApi.mjs), packs the tarball, installs it into a fresh
// consumer project outside the repository (so nothing resolves from the repository's
// node_modules), then
//   1. type-checks a shop's TypeScript against the tarball's declarations (e2e-package/consumer/src),
//   2. runs `luxbox/engine` and the `luxbox` bin under Node on a photometric file,
//   3. builds the consumer's React page with Vite, puts the plain page with the element's
//      single-file script beside it, checks the first-screen budgets (scripts/packageBudgets.mjs),
//      and opens both pages in Chromium (e2e-package/consumer.spec.ts).
// Usage: node scripts/checkPackage.mjs [--keep]   (--keep leaves the consumer folder for a look)
import { execFileSync, spawnSync } from 'node:child_process';
import { cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { budgetFailures, gzipBytes, pageFirstScreen, REACT_DOOR_BUDGET_BYTES, STANDALONE_BUDGET_BYTES, staticClosure } from './packageBudgets.mjs';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const bin = (name) => join(root, 'node_modules/.bin', name);
const run = (cmd, args, options = {}) => execFileSync(cmd, args, { cwd: root, stdio: 'inherit', ...options });
const read = (cmd, args, options = {}) => execFileSync(cmd, args, { cwd: root, encoding: 'utf8', stdio: ['ignore', 'pipe', 'inherit'], ...options });
const started = Date.now();
const step = (what) => console.log(`\n[checkPackage ${((Date.now() - started) / 1000).toFixed(0)} s] ${what}`);
const pkg = JSON.parse(readFileSync(join(root, 'package.json'), 'utf8'));

step('build the package (lib/) and compare its API with docs/api/');
run('node', ['scripts/buildPackage.mjs']);

// The single-file element finds the demo's photometry beside itself (its default asset base): a
// `data:` URL there means the bundler inlined a module for `new URL(…, import.meta.url)` instead.
const elementScript = readFileSync(join(root, 'lib/standalone/luxbox-element.js'), 'utf8');
if (/new URL\(\s*["'`]data:/.test(elementScript)) {
  console.error('checkPackage: lib/standalone/luxbox-element.js builds a URL from an inlined data: URL (its default asset base would not be its folder)');
  process.exit(1);
}

step('npm pack');
const packDir = join(root, 'build/pack');
rmSync(packDir, { recursive: true, force: true });
mkdirSync(packDir, { recursive: true });
// --ignore-scripts: lib/ was just built; prepack would build it again.
const tarball = join(packDir, read('npm', ['pack', '--ignore-scripts', '--silent', '--pack-destination', packDir]).trim().split('\n').pop());

step(`install ${tarball} into a fresh consumer project`);
const consumer = mkdtempSync(join(tmpdir(), 'luxbox-consumer-'));
cpSync(join(root, 'e2e-package/consumer'), consumer, { recursive: true });
const dev = pkg.devDependencies;
// React from the shop's side (the peer dependency); headless-gl (optional) is not built here, it is linked below.
run(
  'npm',
  [
    'install',
    '--no-audit',
    '--no-fund',
    '--prefer-offline',
    '--omit=optional',
    '--ignore-scripts',
    tarball,
    `react@${dev.react}`,
    `react-dom@${dev['react-dom']}`,
    `@types/react@${dev['@types/react']}`,
    `@types/react-dom@${dev['@types/react-dom']}`,
  ],
  { cwd: consumer },
);

step('type-check the consumer against the tarball’s declarations');
run(bin('tsc'), ['-p', join(consumer, 'tsconfig.json')]);

step('luxbox/engine and the luxbox bin under Node');
const lampFile = join(consumer, 'node_modules/luxbox/lib/standalone/ies/zumtobel_linetik_s_direct_indirect.ldt');
// Installed without the optional headless-gl, the bin says what is missing (exit 1, one line).
const withoutGl = spawnSync('node', [join(consumer, 'node_modules/.bin/luxbox'), 'ies', 'info', lampFile], { cwd: consumer, encoding: 'utf8' });
if (withoutGl.status !== 1 || !withoutGl.stderr.startsWith('luxbox: the command line needs headless-gl')) throw new Error(`the bin without headless-gl: exit ${withoutGl.status}, ${withoutGl.stderr}`);
// The repository's built headless-gl stands for the one npm builds where the optional dependency installs.
symlinkSync(join(root, 'node_modules/gl'), join(consumer, 'node_modules/gl'), 'dir');
const cli = JSON.parse(read('node', [join(consumer, 'node_modules/.bin/luxbox'), 'ies', 'info', '--json', lampFile], { cwd: consumer }));
const engineLumens = Number(
  read(
    'node',
    [
      '--input-type=module',
      '-e',
      `import { readFileSync } from 'node:fs'; import { integrateFlux, parsePhotometry } from 'luxbox/engine'; process.stdout.write(String(integrateFlux(parsePhotometry(readFileSync(${JSON.stringify(lampFile)}), 'lamp.ldt'))));`,
    ],
    { cwd: consumer },
  ),
);
// The CLI rounds to 0.01 lm; the stated flux (7650 lm) is the file's own, independent figure (public/ies/SOURCES.md: integrated within 0.1 %).
if (Math.abs(engineLumens - cli.integratedLumens) > 0.005 || Math.abs(engineLumens / cli.statedLumens - 1) > 0.001)
  throw new Error(`integrated flux: engine ${engineLumens} lm, CLI ${cli.integratedLumens} lm, stated ${cli.statedLumens} lm`);
console.log(`integrated flux ${engineLumens.toFixed(2)} lm (CLI ${cli.integratedLumens}, stated ${cli.statedLumens})`);

step('build the consumer pages');
const catalogDir = join(consumer, 'public/catalog');
mkdirSync(catalogDir, { recursive: true });
cpSync(join(root, 'src/core/catalog/default-catalog.json'), join(catalogDir, 'catalog.json'));
// docs/package.md: the photometry the demo catalog names is shipped in lib/standalone/ies.
cpSync(join(consumer, 'node_modules/luxbox/lib/standalone/ies'), join(catalogDir, 'ies'), { recursive: true });
run(bin('vite'), ['build', consumer, '--logLevel', 'warn']);
// The plain page: no bundler, the element's script folder copied as a shop would upload it.
cpSync(join(consumer, 'node_modules/luxbox/lib/standalone'), join(consumer, 'dist/luxbox'), { recursive: true });
cpSync(join(consumer, 'static/element.html'), join(consumer, 'dist/element.html'));
run(bin('vite'), ['build', join(consumer, 'baseline'), '--logLevel', 'warn']);

step('first-screen budgets');
const reactAdds = pageFirstScreen(join(consumer, 'dist'), 'index.html') - pageFirstScreen(join(consumer, 'baseline/dist'), 'index.html');
const standaloneFiles = staticClosure(join(consumer, 'dist/luxbox'), ['luxbox-element.js']);
const standalone = gzipBytes(join(consumer, 'dist/luxbox'), standaloneFiles);
console.log(`luxbox/react adds ${(reactAdds / 1000).toFixed(1)} kB gzip to the React page's first screen (budget ${REACT_DOOR_BUDGET_BYTES / 1000} kB)`);
console.log(`the single-file element's first screen: ${(standalone / 1000).toFixed(1)} kB gzip in ${standaloneFiles.length} files (budget ${STANDALONE_BUDGET_BYTES / 1000} kB)`);
const overBudget = budgetFailures({ reactAdds, standalone });
if (overBudget.length > 0) throw new Error(`first-screen budget exceeded (docs/package.md, "Budgets"): ${overBudget.join('; ')}`);
writeFileSync(join(consumer, 'expected-bom.json'), read(bin('tsx'), ['e2e-package/expectedBom.ts']));

step('open both pages in Chromium');
try {
  run(bin('playwright'), ['test', '-c', 'playwright.package.config.ts'], { env: { ...process.env, LUXBOX_CONSUMER_DIR: consumer } });
} finally {
  if (process.argv.includes('--keep')) console.log(`consumer kept in ${consumer}`);
  else rmSync(consumer, { recursive: true, force: true });
}
step('done');
