#!/usr/bin/env node
// Command-line entry. Runs the TypeScript sources directly through tsx, so the
// CLI and the browser share one code base with no separate build step.
import { register } from 'tsx/esm/api';

register();
const { main } = await import('../src/hosts/cli/main.ts');
process.exitCode = await main(process.argv.slice(2));
