/**
 * `npm run fuzz -- [--count N] [--target name] [--seed S] [--no-save] [--replay] [--path app|cli]`:
 * N mutants per target (default 10 000) from the real fixtures, a table per
 * target, every failing input kept under tests/fixtures/fuzz-regressions/<target>/
 * (replayed by tests/fuzz/fuzz.test.ts and meshFuzz.test.ts). Exit status 1 when anything failed.
 * The `mesh` target (asynchronous: meshTarget.ts) runs N mutants through each import path and
 * also prints its refusals by kind; `--path` picks one (two campaigns can then run side by side). docs/scene-format.md, "Hostile input and fuzzing".
 */
import { allTargets, formatTable, fuzz, isFailure, replay, saveRegression, type Tally } from './fuzzEngine';
import { formatRefusals, fuzzMesh, replayMesh } from './meshTarget';

function option(args: string[], name: string): string | undefined {
  const i = args.indexOf(name);
  return i >= 0 ? args[i + 1] : undefined;
}

async function main(args: string[]): Promise<number> {
  const count = Number(option(args, '--count') ?? 10_000);
  const seed = Number(option(args, '--seed') ?? 18);
  const only = option(args, '--target');
  const save = !args.includes('--no-save');
  if (!Number.isInteger(count) || count < 0 || !Number.isInteger(seed)) {
    process.stderr.write('usage: npm run fuzz -- [--count N] [--target name] [--seed S] [--no-save] [--replay]\n');
    return 2;
  }
  const targets = (await allTargets()).filter((t) => !only || t.name === only);
  if (targets.length === 0 && only !== 'mesh') {
    process.stderr.write(`fuzz: no target named "${only}" (have: ${(await allTargets()).map((t) => t.name).join(', ')}, mesh)\n`);
    return 2;
  }
  const tallies: Tally[] = [];
  const refusals: string[] = [];
  if (!only || only === 'mesh') {
    const paths = (['app', 'cli'] as const).filter((p) => !option(args, '--path') || option(args, '--path') === p);
    for (const path of paths) {
      const started = performance.now();
      process.stderr.write(`mesh (${path}): `);
      const tally = args.includes('--replay')
        ? await replayMesh(path)
        : await fuzzMesh(path, count, seed, {
            keepFailures: 200,
            // A long campaign reports as it goes: inputs, failures, inputs over 1 s, slowest ms.
            onProgress: (n, t) => process.stderr.write(`${n} (${t.failures.length} failing, ${t.slow} over 1 s, max ${Math.round(t.maxMs)} ms, CPU max ${Math.round(t.maxCpuMs)} ms) `),
          });
      process.stderr.write(`done in ${((performance.now() - started) / 1000).toFixed(1)} s\n`);
      tallies.push(tally);
      refusals.push(`${tally.target} refusals: ${formatRefusals(tally)}`);
      for (const f of tally.failures) {
        const why = `${f.result.verdict}${f.result.slow ? ` (slow: ${Math.round(f.result.ms)} ms)` : ''}: ${f.result.detail} [seed ${f.seed}; ${f.applied.join(', ')}]`;
        const kept = save ? saveRegression('mesh', f.bytes, why) : null;
        process.stdout.write(`FAIL mesh (${path}): ${why.slice(0, 400)}${kept ? ` → ${kept}` : ''}\n`);
      }
    }
  }
  for (const target of targets) {
    const started = performance.now();
    process.stderr.write(`${target.name}: `);
    const tally = args.includes('--replay') ? replay(target) : fuzz(target, count, seed, { keepFailures: 200, onProgress: (n) => process.stderr.write(`${n} `) });
    process.stderr.write(`done in ${((performance.now() - started) / 1000).toFixed(1)} s\n`);
    tallies.push(tally);
    for (const f of tally.failures) {
      const why = `${f.result.verdict}${f.result.slow ? ` (slow: ${Math.round(f.result.ms)} ms)` : ''}: ${f.result.detail} [seed ${f.seed}; ${f.applied.join(', ')}]`;
      const kept = save ? saveRegression(target.name, f.bytes, why) : null;
      process.stdout.write(`FAIL ${target.name}: ${why.slice(0, 400)}${kept ? ` → ${kept}` : ''}\n`);
    }
  }
  process.stdout.write(`${formatTable(tallies)}\n${refusals.map((r) => `${r}\n`).join('')}`);
  return tallies.some((t) => t.failures.some((f) => isFailure(f.result))) ? 1 : 0;
}

process.exitCode = await main(process.argv.slice(2));
