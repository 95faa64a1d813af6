// Entry of the single-file CLI bundle (scripts/packGpuBench.mjs, docs/gpu-server.md):
// the same main as bin/luxbox.js, without tsx, for machines with nothing installed.
import { main } from './main';

process.exitCode = await main(process.argv.slice(2));
