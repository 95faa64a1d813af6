// The package's type declarations and API report (docs/package.md, "API report"): for each door,
// api-extractor rolls the declarations tsc emitted (tsconfig.lib.json → build/types) into one
// lib/<door>.d.ts, and compares the door's public API with its reviewed report docs/api/<door>.api.md.
// `node scripts/packageApi.mjs` (run by scripts/test.sh) emits the declarations and fails when a
// report differs (a public change nobody reviewed); `--update` writes the new reports, to be
// committed with the change (as `npm run api:update` does with the whole package build).
import { Extractor, ExtractorConfig } from '@microsoft/api-extractor';
import { execFileSync } from 'node:child_process';
import { appendFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
export const DOORS = { luxbox: 'index', react: 'react', element: 'element', engine: 'engine' };

/**
 * api-extractor leaves `declare global` blocks out of its rollups (a documented limitation,
 * "ae-global-augmentation" is not supported), so the element's tag-name typing
 * (`document.createElement('luxbox-configurator')` → LuxboxConfiguratorElement, in
 * src/hosts/package/LuxboxConfiguratorElement.ts) is appended to lib/element.d.ts here.
 */
const GLOBAL_AUGMENTATIONS = {
  element: "\ndeclare global {\n  interface HTMLElementTagNameMap {\n    'luxbox-configurator': LuxboxConfiguratorElement;\n  }\n}\n",
};

export function extractApi({ update }) {
  const failures = [];
  for (const [door, file] of Object.entries(DOORS)) {
    const config = ExtractorConfig.prepare({
      configObject: {
        projectFolder: root,
        mainEntryPointFilePath: resolve(root, `build/types/src/hosts/package/${file}.d.ts`),
        compiler: {
          overrideTsconfig: {
            compilerOptions: { target: 'ES2022', module: 'ESNext', moduleResolution: 'bundler', lib: ['ES2023', 'DOM', 'DOM.Iterable'], strict: true, skipLibCheck: true, types: [] },
            files: [resolve(root, `build/types/src/hosts/package/${file}.d.ts`)],
          },
        },
        apiReport: { enabled: true, reportFileName: `${door}.api.md`, reportFolder: resolve(root, 'docs/api'), reportTempFolder: resolve(root, 'build/api') },
        docModel: { enabled: false },
        dtsRollup: { enabled: true, untrimmedFilePath: resolve(root, `lib/${door}.d.ts`) },
        tsdocMetadata: { enabled: false },
        messages: {
          compilerMessageReporting: { default: { logLevel: 'warning' } },
          extractorMessageReporting: {
            default: { logLevel: 'warning' },
            // Release tags (@public/@beta) are not used: what a door exports is public.
            'ae-missing-release-tag': { logLevel: 'none' },
            // Types reachable from the API but not exported by name appear in the report as they are.
            'ae-forgotten-export': { logLevel: 'none' },
            // The report shows each declaration's doc comment where it has one; a missing one is not an error.
            'ae-undocumented': { logLevel: 'none' },
          },
          tsdocMessageReporting: { default: { logLevel: 'none' } },
        },
      },
      configObjectFullPath: undefined,
      packageJsonFullPath: resolve(root, 'package.json'),
    });
    const result = Extractor.invoke(config, { localBuild: update, showVerboseMessages: false });
    if (GLOBAL_AUGMENTATIONS[door]) appendFileSync(resolve(root, `lib/${door}.d.ts`), GLOBAL_AUGMENTATIONS[door]);
    if (!result.succeeded || (!update && result.apiReportChanged))
      failures.push(`${door}: ${result.apiReportChanged ? 'the public API differs from docs/api/' + door + '.api.md (review it and run `npm run api:update`)' : `${result.errorCount} errors, ${result.warningCount} warnings`}`);
  }
  return failures;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  // Alone (scripts/test.sh), it emits the declarations first; scripts/buildPackage.mjs has already.
  execFileSync(resolve(root, 'node_modules/.bin/tsc'), ['-p', 'tsconfig.lib.json'], { cwd: root, stdio: 'inherit' });
  const failures = extractApi({ update: process.argv.includes('--update') });
  for (const f of failures) console.error(f);
  process.exitCode = failures.length > 0 ? 1 : 0;
}
