#!/usr/bin/env node
// Command-line entry. In the repository it runs the TypeScript sources directly through tsx, so
// the CLI and the browser share one code base with no build step; the npm package has no sources
// and runs the CLI bundled into lib/cli/luxbox.mjs (scripts/buildPackage.mjs, docs/package.md).
import { existsSync } from 'node:fs';

const sources = new URL('../src/hosts/cli/main.ts', import.meta.url);
if (existsSync(sources)) {
  const { register } = await import('tsx/esm/api');
  register();
  const { main } = await import(sources.href);
  process.exitCode = await main(process.argv.slice(2));
} else {
  try {
    await import('../lib/cli/luxbox.mjs');
  } catch (e) {
    // headless-gl is an optional dependency (a shop installing the web doors needs no native build):
    // say what is missing instead of Node's stack trace.
    if (e?.code !== 'ERR_MODULE_NOT_FOUND' || !/'gl'/.test(String(e.message))) throw e;
    console.error('luxbox: the command line needs headless-gl, an optional dependency that is not installed here: npm install gl (docs/gpu-server.md)');
    process.exitCode = 1;
  }
}
