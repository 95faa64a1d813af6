// The package's first-screen budgets (issue 33; docs/package.md, "Budgets"), counted as
// scripts/firstScreenBudget.mjs counts the app's: every JavaScript file a page loads before any
// interaction (the entry and its static-import closure, never lazy chunks), each gzipped at level 9,
// kB = 1000 bytes.
//   - the single-file element (lib/standalone/luxbox-element.js): at most 150 kB;
//   - what `luxbox/react` adds to a React app: the consumer page with <Luxbox> minus the same
//     shop page without it (React itself not counted): at most 110 kB, as the issue asks (112.4 kB
//     until the bundled demo catalog became a lazy chunk of the package doors, 2026-11-27).
import { readFileSync } from 'node:fs';
import { dirname, join, normalize } from 'node:path';
import { gzipSync } from 'node:zlib';
import { firstScreenScripts } from './firstScreenBudget.mjs';

export const STANDALONE_BUDGET_BYTES = 150_000;
export const REACT_DOOR_BUDGET_BYTES = 110_000;

const gzip = (buffer) => gzipSync(buffer, { level: 9 }).length;

/** The files an ES module loads statically (import … from, import '…', export … from), relative ones only, transitively. */
export function staticClosure(root, entries) {
  const seen = new Set();
  const stack = entries.map((e) => normalize(e));
  while (stack.length > 0) {
    const file = stack.pop();
    if (seen.has(file)) continue;
    seen.add(file);
    const code = readFileSync(join(root, file), 'utf8');
    for (const m of code.matchAll(/(?:^|[;}\s])(?:import|export)\s*(?:[\w*${}\s,]+?\s*from\s*)?["'](\.{1,2}\/[^"']+)["']/g)) {
      stack.push(normalize(join(dirname(file), m[1])));
    }
  }
  return [...seen];
}

/** The budgets a measurement exceeds, one sentence each (none: within both). `reactAdds` and `standalone` are gzip bytes. */
export function budgetFailures({ reactAdds, standalone }) {
  const failures = [];
  if (reactAdds > REACT_DOOR_BUDGET_BYTES) failures.push(`luxbox/react adds ${reactAdds} B, over ${REACT_DOOR_BUDGET_BYTES} B`);
  if (standalone > STANDALONE_BUDGET_BYTES) failures.push(`the single-file element's first screen is ${standalone} B, over ${STANDALONE_BUDGET_BYTES} B`);
  return failures;
}

export function gzipBytes(root, files) {
  return files.reduce((sum, f) => sum + gzip(readFileSync(join(root, f))), 0);
}

/** First-screen gzip bytes of a built page (its HTML's entry and modulepreloads, and what they import statically). */
export function pageFirstScreen(distDir, page) {
  return gzipBytes(distDir, staticClosure(distDir, firstScreenScripts(readFileSync(join(distDir, page), 'utf8'))));
}

if (process.argv[1] && import.meta.url.endsWith(process.argv[1].split('/').pop())) {
  const dir = process.argv[2] ?? 'lib/standalone';
  const files = staticClosure(dir, ['luxbox-element.js']);
  const bytes = gzipBytes(dir, files);
  console.log(`standalone element first screen: ${(bytes / 1000).toFixed(1)} kB gzip in ${files.length} files (budget ${STANDALONE_BUDGET_BYTES / 1000} kB)`);
  process.exitCode = bytes > STANDALONE_BUDGET_BYTES ? 1 : 0;
}
