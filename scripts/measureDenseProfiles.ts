/**
 * Direct-pass time with dense profile tables against the measured grid's bin tables, in one run
 * (docs/benchmarks.md, "Dense profile tables"): `xvfb-run -a npx tsx scripts/measureDenseProfiles.ts [repeats]`.
 */
import { profileLookupExperiment } from '../src/hosts/bench/gpuBench';

const repeats = Number(process.argv[2] ?? 7);
for (const r of profileLookupExperiment(process.cwd(), repeats)) {
  console.log(`${r.case}: measured grid ${r.measuredMs.toFixed(1)} ms, dense ${r.denseMs.toFixed(1)} ms, dense/measured ${(r.denseMs / r.measuredMs).toFixed(3)} (median of ${repeats})`);
}
