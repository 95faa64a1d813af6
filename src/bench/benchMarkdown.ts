import type { BenchResult } from './runBench';

const pct = (e: number): string => (100 * e < 0.1 ? (100 * e).toFixed(3) : (100 * e).toFixed(2));
const ms = (t: number): string => (t >= 10_000 ? `${(t / 1000).toFixed(1)} s` : `${Math.round(t)} ms`);

/** The results as markdown tables (the part of docs/benchmarks.md that the bench writes). */
export function benchTables(r: BenchResult, svgName: string | null): string {
  const lines: string[] = [];
  const m = r.machine;
  lines.push(`Run: ${m.date}${r.quick ? ' (`--quick` smoke run)' : ''}, total ${ms(r.totalMs)}.`);
  lines.push('');
  lines.push(`Machine: ${m.cpuModel}, ${m.cores} logical cores, ${m.memoryGiB} GiB; ${m.os}; Node ${m.node}.`);
  lines.push(`GL: ${m.glVersion}; renderer ${m.glRenderer}.`);
  lines.push('');
  lines.push('#### Scenes and references');
  lines.push('');
  lines.push('| scene | luminaires | comparison points | reference patches | Gauss–Seidel sweeps | reference time |');
  lines.push('|---|---|---|---|---|---|');
  for (const s of r.scenes) {
    lines.push(`| ${s.scene.name}: ${s.scene.description} | ${s.luminaires} | ${s.points} (every ${s.scene.sampleSpacing} m) | ${s.referencePatches} (${s.scene.referencePatch} m) | ${s.referenceSweeps} | ${ms(s.referenceMs)} |`);
  }
  lines.push('');
  lines.push('#### Error against run time');
  lines.push('');
  lines.push('Relative error of the baked maps (bilinear lookup, as `luxbox probe`) against the reference at the comparison points. Bake time is wall clock for `baker.bake` (all passes and the read-back; each timed bake follows an untimed warm-up bake with the same texel size and luminaires, so program compilation is excluded; the compile column shows what was left).');
  lines.push('');
  lines.push('| scene | rung | texel | samples | bounces | texels | bake time | of which compile | total RMS | total max | direct RMS | indirect RMS | mean total bake / ref (lx) |');
  lines.push('|---|---|---|---|---|---|---|---|---|---|---|---|---|');
  for (const row of r.rows) {
    const q = row.quality;
    const rung = r.rows.filter((x) => x.scene === row.scene).indexOf(row) + 1;
    lines.push(
      `| ${row.scene} | ${rung} | ${q.texelSize} m | ${q.samples} | ${q.bounces} | ${row.texels} | ${ms(row.bakeMs)} | ${ms(row.compileMs)} | ${pct(row.total.rms)} % | ${pct(row.total.max)} % | ${pct(row.direct.rms)} % | ${pct(row.indirect.rms)} % | ${row.meanBake.toFixed(1)} / ${row.meanReference.toFixed(1)} |`,
    );
  }
  lines.push('');
  if (svgName) {
    lines.push(`![error versus bake time](${svgName})`);
    lines.push('');
  }
  lines.push(`#### Bake time against luminaires and texels (${r.scalingScene}, ${r.scalingQuality.samples} samples, ${r.scalingQuality.bounces} bounces)`);
  lines.push('');
  lines.push('| study | luminaires | point sources | texel | texels | bake time | of which compile | µs per texel |');
  lines.push('|---|---|---|---|---|---|---|---|');
  for (const s of r.scaling) {
    lines.push(`| ${s.study} | ${s.luminaires} | ${s.pointSources} | ${s.texelSize} m | ${s.texels} | ${ms(s.bakeMs)} | ${ms(s.compileMs)} | ${((1000 * (s.bakeMs - s.compileMs)) / s.texels).toFixed(1)} |`);
  }
  lines.push('');
  return lines.join('\n');
}

/**
 * `doc` with the bench's section replaced by `section` (between the markers),
 * or with it appended when the markers are absent; the rest is kept as is.
 */
export function spliceSection(doc: string, section: string, markers: readonly [string, string]): string {
  const block = `${markers[0]}\n${section.trim()}\n${markers[1]}\n`;
  const start = doc.indexOf(markers[0]);
  const end = doc.indexOf(markers[1]);
  if (start >= 0 && end > start) return doc.slice(0, start) + block + doc.slice(end + markers[1].length).replace(/^\n/, '');
  return (doc.trim() ? doc.replace(/\s*$/, '\n\n') : '# Benchmarks\n\n') + block;
}
